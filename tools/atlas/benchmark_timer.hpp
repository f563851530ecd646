// The atlas times its methods with Google Benchmark, the harness of bench/: each piece of work
// is a benchmark of its own, repeated, and the median of the repetitions is kept.
#pragma once

#include <functional>
#include <string>

namespace edgewise::atlas {

struct TimerSettings {
  int repetitions = 5;
  double min_seconds = 0.05;  // per repetition
};

// The median over the repetitions of the wall-clock time of one call of `work`, in nanoseconds.
// Throws std::runtime_error if the benchmark reports an error.
double median_nanoseconds(const std::string& name, const std::function<void()>& work,
                          const TimerSettings& settings);

}  // namespace edgewise::atlas
