// Occlusion culling: occluders drawn by OcclusionBuffer::draw_occluders() with the fill-rate
// protocol of Masked Occlusion Culling (fillrate_triangles.hpp), one thread and all threads, and
// rectangle queries against a screen full of occluders; at full resolution and with a depth per
// 2x2 or 4x4 pixels (`reduction`, partial coverage ignored, or `merged`).
#include <benchmark/benchmark.h>

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <string>
#include <vector>

#include "../benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "fillrate_triangles.hpp"
#include "occlusion_workloads.hpp"
#if defined(EDGEWISE_BENCH_FLOOR)
#include "exact_depth_floor.hpp"
#endif

namespace edgewise::bench {
namespace {

// Back to front, every covered pixel is written: a run's written pixels must be about its
// triangles' area (edge pixels make up the difference at 10 px), or it measured something else.
constexpr double kOccluderWrittenTolerance = 0.05;

// A reduced buffer's blocks per pixel on each axis, and how it takes partial coverage.
struct Reduction {
  std::int32_t pixels = 1;
  PartialCoverage partial = PartialCoverage::ignored;
  std::string name() const {
    if (pixels == 1) return "";
    return "/reduction:" + std::to_string(pixels) +
           (partial == PartialCoverage::merged ? "/merged" : "");
  }
};
constexpr Reduction kReductions[] = {{1, PartialCoverage::ignored},
                                     {2, PartialCoverage::ignored},
                                     {4, PartialCoverage::ignored},
                                     {2, PartialCoverage::merged},
                                     {4, PartialCoverage::merged}};

void occluder_fill(benchmark::State& state, Isa isa, int size, std::size_t threads,
                   Reduction reduction) {
  const FillrateTriangles& triangles = fillrate_triangles(size, fillrate_count(size));
  OcclusionBuffer buffer(kWidth, kHeight, reduction.pixels, reduction.partial);
  OcclusionOptions options;
  options.isa = isa;
  options.threads = threads;
  DrawReport report;
  for (auto _ : state) {
    state.PauseTiming();
    buffer.clear();
    state.ResumeTiming();
    report = buffer.draw_occluders({triangles.ndc, {}}, options);
    benchmark::DoNotOptimize(report.fragments_passed);
  }
  // A reduced buffer writes the blocks that triangles cover whole: fewer than their area in
  // blocks, by the blocks along their edges.
  const double blocks = 0.5 * size * size * static_cast<double>(triangles.triangles()) /
                        (static_cast<double>(reduction.pixels) * reduction.pixels);
  const double written = static_cast<double>(report.fragments_passed);
  const bool as_expected = reduction.pixels == 1
                               ? std::abs(written - blocks) <= kOccluderWrittenTolerance * blocks
                               : written > 0.0 && written <= blocks;
  if (report.isa != isa) {
    state.SkipWithError("draw_occluders ran another ISA than the one asked for");
  } else if (!as_expected) {
    const std::string message = "wrote " + std::to_string(report.fragments_passed) +
                                " pixels, expected about " + std::to_string(std::uint64_t(blocks));
    state.SkipWithError(message.c_str());
  }
  const double iterations = static_cast<double>(state.iterations());
  state.counters["triangles"] = benchmark::Counter(
      static_cast<double>(triangles.triangles()) * iterations, benchmark::Counter::kIsRate);
  state.counters["pixels"] = benchmark::Counter(
      static_cast<double>(report.fragments_passed) * iterations, benchmark::Counter::kIsRate);
}

#if defined(EDGEWISE_BENCH_FLOOR)
// The fill-rate triangles drawn by the floor of exact depth's cost (exact_depth_floor.hpp). Its
// depths and written pixels must be draw_occluders()'s, bit for bit, or it measured something
// else.
void occluder_floor(benchmark::State& state, int size) {
  const FillrateTriangles& triangles = fillrate_triangles(size, fillrate_count(size));
  FloorDepth floor;
  for (auto _ : state) {
    state.PauseTiming();
    std::fill(floor.depth.begin(), floor.depth.end(), 1.0f);
    floor.passed = 0;
    state.ResumeTiming();
    draw_exact_depth_floor(triangles, floor);
    benchmark::DoNotOptimize(floor.depth.data());
  }
  OcclusionBuffer buffer(kWidth, kHeight);
  OcclusionOptions options;
  options.isa = Isa::avx2;
  options.threads = 1;
  const DrawReport report = buffer.draw_occluders({triangles.ndc, {}}, options);
  std::vector<float> want(static_cast<std::size_t>(kWidth) * kHeight);
  buffer.read_depth(want);
  std::string error;
  for (int y = 0; y < kHeight && error.empty(); ++y) {
    for (int x = 0; x < kWidth; ++x) {
      const float got = floor.at(x, y), expected = want[static_cast<std::size_t>(y) * kWidth + x];
      if (std::bit_cast<std::uint32_t>(got) != std::bit_cast<std::uint32_t>(expected)) {
        error = "depth at pixel (" + std::to_string(x) + ", " + std::to_string(y) +
                ") differs from draw_occluders()'s";
        break;
      }
    }
  }
  if (error.empty() && floor.passed != report.fragments_passed) {
    error = "wrote " + std::to_string(floor.passed) + " pixels, draw_occluders() " +
            std::to_string(report.fragments_passed);
  }
  if (!error.empty()) state.SkipWithError(error.c_str());
  const double iterations = static_cast<double>(state.iterations());
  state.counters["triangles"] = benchmark::Counter(
      static_cast<double>(triangles.triangles()) * iterations, benchmark::Counter::kIsRate);
  state.counters["pixels"] = benchmark::Counter(static_cast<double>(floor.passed) * iterations,
                                                benchmark::Counter::kIsRate);
}
#endif

void rect_query_rate(benchmark::State& state, Isa isa, Reduction reduction) {
  const OcclusionBuffer& buffer = query_scene(isa, reduction.pixels, reduction.partial);
  const std::vector<OcclusionRect>& rects = query_rects();
  std::vector<Visibility> answers(rects.size());
  for (auto _ : state) {
    buffer.test_rects(rects, answers, isa);
    benchmark::DoNotOptimize(answers.data());
  }
  std::size_t occluded = 0;
  for (const Visibility v : answers)
    occluded += v == Visibility::occluded;
  state.counters["queries"] = benchmark::Counter(
      static_cast<double>(rects.size()) * static_cast<double>(state.iterations()),
      benchmark::Counter::kIsRate);
  state.counters["occluded_share"] = static_cast<double>(occluded) / rects.size();
}

}  // namespace

void register_occlusion_benchmarks() {
  for (Isa isa : supported_isas()) {
    if (isa == Isa::reference) continue;  // the reference draws through draw()'s reference
    for (const Reduction& reduction : kReductions) {
      for (const int size : kFillrateSizes) {
        for (const std::size_t threads : {std::size_t{1}, std::size_t{0}}) {
          const std::string name = "Occluders/" + std::string(name_of(isa)) +
                                   "/size:" + std::to_string(size) +
                                   (threads == 1 ? "" : "/threads:all") + reduction.name();
          benchmark::RegisterBenchmark(name.c_str(), occluder_fill, isa, size, threads, reduction)
              ->Unit(benchmark::kMillisecond)
              ->UseRealTime();
        }
      }
    }
  }
#if defined(EDGEWISE_BENCH_FLOOR)
  const auto isas = supported_isas();
  if (std::find(isas.begin(), isas.end(), Isa::avx2) != isas.end()) {
    for (const int size : kFillrateSizes) {
      const std::string name = "OccluderFloor/avx2/size:" + std::to_string(size);
      benchmark::RegisterBenchmark(name.c_str(), occluder_floor, size)
          ->Unit(benchmark::kMillisecond)
          ->UseRealTime();
    }
  }
#endif
  for (const Reduction& reduction : kReductions) {
    for (Isa isa : supported_isas()) {
      const std::string name = "RectQueries/" + std::string(name_of(isa)) + reduction.name();
      benchmark::RegisterBenchmark(name.c_str(), rect_query_rate, isa, reduction)
          ->Unit(benchmark::kMillisecond);
    }
  }
}

}  // namespace edgewise::bench
