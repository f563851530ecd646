// The median of measured times, and the median wall-clock time of a piece of work: on a shared
// machine a single run may be slowed by other jobs, and the median ignores the outliers that a
// mean would average in.
#pragma once

#include <chrono>
#include <span>
#include <vector>

namespace edgewise::tools {

// The middle value (the mean of the two middle ones for an even count). Throws
// std::invalid_argument for no values.
double median(std::span<const double> values);

// Runs `work` `repetitions` times (at least once) and returns the median duration in seconds.
template <class Work>
double median_seconds(int repetitions, Work&& work) {
  using Clock = std::chrono::steady_clock;
  std::vector<double> seconds;
  for (int r = 0; r < (repetitions < 1 ? 1 : repetitions); ++r) {
    const auto start = Clock::now();
    work();
    seconds.push_back(std::chrono::duration<double>(Clock::now() - start).count());
  }
  return median(seconds);
}

}  // namespace edgewise::tools
