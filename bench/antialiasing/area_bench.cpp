// Exact-area coverage throughput (rasterize_areas()): the coverage benchmark's triangles, a batch
// per call on one thread, for every supported ISA and the reference. The rate that matters is
// partially covered pixels per second: whole pixels cost no arithmetic.
#include <benchmark/benchmark.h>

#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <vector>

#include "../benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "exact_area_workload.hpp"

namespace edgewise::bench {
namespace {

constexpr AreaCase kAreaCases[] = {{8, 16384}, {64, 8192}, {1000, 1024}, {200000, 16}};

// Counts what a call delivered: tiles, and once, the pixels by kind and the summed area.
class CountingAreaSink final : public AreaSink {
 public:
  bool inspect = false;
  std::uint64_t tiles = 0, partial = 0, whole = 0;
  double area = 0.0;
  void consume(std::span<const AreaTile> batch) override {
    tiles += batch.size();
    if (!inspect) return;
    for (const AreaTile& tile : batch) {
      for (float a : tile.area) {
        partial += a > 0.0f && a < 1.0f;
        whole += a == 1.0f;
        area += a;
      }
    }
  }
};

void areas(benchmark::State& state, Isa isa, AreaCase c) {
  const std::vector<Vec2>& vertices = exact_area_workload(c.area, c.batch);
  const RasterTarget target{kWidth, kHeight, {}};
  RasterOptions options;
  options.isa = isa;
  CountingAreaSink census;
  census.inspect = true;
  const RasterReport report = rasterize_areas(vertices, {}, target, options, census);
  if (report.drawn != c.batch) {
    state.SkipWithError("not every triangle of the batch was drawn");
    return;
  }
  // The exact_area_triangles lie inside the target: their areas add up to area * batch.
  const double expected = double(c.area) * double(c.batch);
  if (std::abs(census.area - expected) > 1e-3 * expected) {
    state.SkipWithError("the areas do not add up to the triangles' area");
    return;
  }
  for (auto _ : state) {
    CountingAreaSink sink;
    rasterize_areas(vertices, {}, target, options, sink);
    benchmark::DoNotOptimize(sink.tiles);
  }
  const double iterations = double(state.iterations());
  state.counters["triangles"] =
      benchmark::Counter(double(c.batch) * iterations, benchmark::Counter::kIsRate);
  state.counters["partial_pixels"] =
      benchmark::Counter(double(census.partial) * iterations, benchmark::Counter::kIsRate);
  state.counters["pixels"] = benchmark::Counter(double(census.partial + census.whole) * iterations,
                                                benchmark::Counter::kIsRate);
}

}  // namespace

void register_area_benchmarks() {
  for (Isa isa : supported_isas()) {
    for (const AreaCase& c : kAreaCases) {
      // The reference clips every pixel of the box in double: the largest case takes seconds.
      if (isa == Isa::reference && c.area > 1000) continue;
      const std::string name =
          "Area/" + std::string(name_of(isa)) + "/area:" + std::to_string(c.area);
      benchmark::RegisterBenchmark(name.c_str(), areas, isa, c)->Unit(benchmark::kMicrosecond);
    }
  }
}

}  // namespace edgewise::bench
