// Coverage-only rasterization throughput: random triangles of one area per benchmark, a batch
// per count_coverage() call on one thread, for every supported ISA and the reference; and with
// 2 to 16 samples per pixel (RasterOptions::samples) for every SIMD ISA.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "../benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "../antialiasing/exact_area_workload.hpp"

namespace edgewise::bench {
namespace {

// Batches take about 1-10 ms on the SIMD paths at the target rates, so per-call costs vanish
// (the reference takes up to a few hundred ms per call).
constexpr AreaCase kCoverageCases[] = {{8, 65536}, {64, 32768}, {1000, 4096}, {200000, 128}};

// With random placement the expected number of covered samples equals the area (times the
// samples per pixel), so a batch covers about area * batch pixels; a result far from that means the
// benchmark measures something else (a culled batch, a broken kernel).
constexpr double kPixelCountTolerance = 0.05;

void coverage(benchmark::State& state, Isa isa, AreaCase c, int samples) {
  const std::vector<Vec2>& vertices = exact_area_workload(c.area, c.batch);
  const RasterTarget target{kWidth, kHeight, {}};
  RasterOptions options;
  options.isa = isa;
  options.threads = 1;  // one core, as the peer and target figures
  options.samples = samples;

  CoverageCount last;
  for (auto _ : state) {
    last = count_coverage(vertices, {}, target, options);
    benchmark::DoNotOptimize(last.pixels);
  }

  const double expected = double(c.area) * double(c.batch) * samples;
  if (last.report.isa != isa) {
    state.SkipWithError("count_coverage ran another ISA than the one asked for");
  } else if (last.report.drawn != c.batch) {
    state.SkipWithError("not every triangle of the batch was drawn");
  } else if (std::abs(double(last.pixels) - expected) > kPixelCountTolerance * expected) {
    const std::string message = "covered " + std::to_string(last.pixels) +
                                " samples per batch, expected about " +
                                std::to_string(std::uint64_t(expected));
    state.SkipWithError(message.c_str());
  }
  const double iterations = double(state.iterations());
  state.counters["triangles"] =
      benchmark::Counter(double(c.batch) * iterations, benchmark::Counter::kIsRate);
  state.counters["pixels"] =
      benchmark::Counter(double(last.pixels) / samples * iterations, benchmark::Counter::kIsRate);
  if (samples > 1) {
    state.counters["samples"] =
        benchmark::Counter(double(last.pixels) * iterations, benchmark::Counter::kIsRate);
  }
}

}  // namespace

void register_coverage_benchmarks() {
  for (Isa isa : supported_isas()) {
    for (const AreaCase& c : kCoverageCases) {
      const std::string name =
          "Coverage/" + std::string(name_of(isa)) + "/area:" + std::to_string(c.area);
      benchmark::RegisterBenchmark(name.c_str(), coverage, isa, c, 1)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  // The reference decides each sample pixel by pixel: too slow to time at these sizes.
  for (Isa isa : supported_isas()) {
    if (isa == Isa::reference) continue;
    for (int samples : {2, 4, 8, 16}) {
      for (const AreaCase& c : kCoverageCases) {
        const std::string name = "Coverage/" + std::string(name_of(isa)) +
                                 "/samples:" + std::to_string(samples) +
                                 "/area:" + std::to_string(c.area);
        benchmark::RegisterBenchmark(name.c_str(), coverage, isa, c, samples)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
}

}  // namespace edgewise::bench
