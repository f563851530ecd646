#include "atlas/benchmark_timer.hpp"

#include <benchmark/benchmark.h>

#include <cmath>
#include <stdexcept>
#include <vector>

namespace edgewise::atlas {
namespace {

// Keeps the median aggregate of the one benchmark registered; prints nothing.
class MedianReporter final : public benchmark::BenchmarkReporter {
 public:
  double nanoseconds = NAN;
  std::string error;
  bool ReportContext(const Context&) override { return true; }
  void ReportRuns(const std::vector<Run>& runs) override {
    for (const Run& run : runs) {
      if (run.error_occurred) error = run.error_message;
      if (run.run_type == Run::RT_Aggregate && run.aggregate_name == "median")
        nanoseconds = run.GetAdjustedRealTime();
    }
  }
};

}  // namespace

double median_nanoseconds(const std::string& name, const std::function<void()>& work,
                          const TimerSettings& settings) {
  benchmark::ClearRegisteredBenchmarks();
  benchmark::RegisterBenchmark(name.c_str(),
                               [&work](benchmark::State& state) {
                                 for (auto _ : state)
                                   work();
                               })
      ->Repetitions(settings.repetitions < 2 ? 2 : settings.repetitions)
      ->ReportAggregatesOnly(true)
      ->MinTime(settings.min_seconds)
      ->Unit(benchmark::kNanosecond)
      ->UseRealTime();
  MedianReporter reporter;
  benchmark::RunSpecifiedBenchmarks(&reporter, ".*");
  benchmark::ClearRegisteredBenchmarks();
  if (!reporter.error.empty()) throw std::runtime_error(name + ": " + reporter.error);
  if (!std::isfinite(reporter.nanoseconds)) throw std::runtime_error(name + ": no median timed");
  return reporter.nanoseconds;
}

}  // namespace edgewise::atlas
