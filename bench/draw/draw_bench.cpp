// Shaded drawing throughput through draw(), for every supported ISA and the reference:
// - Shading/<isa>/area:<px>: the peer-comparable workload. One thread, a 1920x1080 Framebuffer
//   (RGBA8 + float32 depth), depth test less with writes, Gouraud colour; vertices in pixels
//   through an orthographic camera, random depth and colour per vertex; 200k triangles of 8 px,
//   100k of 64 px, 20k of 1000 px or 200 of 200000 px per draw() call.
// - ShadingMethod/<isa>/<method>/<perspective>/area:<px>: the same triangles on screen (64 and
//   1000 px) seen through a perspective camera, so that w varies across each triangle, drawn with
//   every interpolation method, perspective-correct and affine.
// - Shading/<isa>/threads:all/area:<px>: the Shading/ workload on every core (threads = 0, the
//   default: oneTBB's concurrency or EDGEWISE_THREADS), one draw() call as draw() runs it, timed
//   in wall-clock time (the one-thread benchmarks are timed in the thread's CPU time, which on
//   an idle machine is the same).
// - Multisample/<isa>/samples:<n>/area:<px>: the Shading/ workload into a target with n samples per
//   pixel (the standard patterns), 8, 64 and 1000 px; samples:1 is the Shading/ workload itself,
//   the baseline of the same run.
// One iteration is one draw() call over the whole set, from the vertex arrays to the written
// pixels; the framebuffer is cleared before each call with the timer paused.
#include <benchmark/benchmark.h>

#include <algorithm>
#include <chrono>
#include <cmath>
#include <cstdint>
#include <iterator>
#include <initializer_list>
#include <span>
#include <string>
#include <string_view>
#include <vector>

#include "../benchmarks.hpp"
#include "edgewise/edgewise.hpp"
#include "shading_scene.hpp"
#include "draw/draw_stages.hpp"

namespace edgewise::bench {
namespace {

using Clock = std::chrono::steady_clock;

// The interpolation methods differ per fragment: compared where fragments dominate (1000 px) and
// where per-triangle setup still shows (64 px).
constexpr int kMethodAreas[] = {64, 1000};
constexpr int kMultisampleAreas[] = {8, 64, 1000};
// The sweep is 24 benchmarks per ISA: a shorter time per repetition than the suite's default
// keeps a full five-repetition run within minutes. A call takes 10-200 ms, so each repetition
// still averages over one to twenty calls.
constexpr double kMethodMinTimeSeconds = 0.2;

// The reference shades every candidate pixel in double precision, about 20 M fragments/s: a whole
// 1000 or 200000 px set would take 1-2 s per call. It draws the first 1/16 of each set instead.
constexpr std::size_t kReferenceShare = 16;

// With random placement the expected number of covered samples equals the area, so a set covers
// about area * triangles samples; a result far from that means the benchmark measures something
// else (culled or clipped triangles, a broken kernel).
constexpr double kFragmentCountTolerance = 0.05;

std::size_t triangles_for(Isa isa, const ShadingCase& c) {
  return isa == Isa::reference ? (c.triangles + kReferenceShare - 1) / kReferenceShare
                               : c.triangles;
}

// Why a finished run does not measure the intended work, or empty.
std::string check(const DrawReport& report, Isa isa, std::size_t triangles, int area,
                  const Framebuffer& target) {
  const double samples = target.samples();
  if (report.isa != isa) return "draw() ran another ISA than the one asked for";
  if (report.rasterized != triangles || report.clipped != 0 || report.culled != 0 ||
      report.outside != 0 || report.errors != 0) {
    return "not every triangle was drawn unclipped (" + std::to_string(report.rasterized) + " of " +
           std::to_string(triangles) + ")";
  }
  const double expected = double(area) * double(triangles) * samples;
  if (std::abs(double(report.fragments) - expected) > kFragmentCountTolerance * expected) {
    return "covered " + std::to_string(report.fragments) + " samples per call, expected about " +
           std::to_string(std::uint64_t(expected));
  }
  std::uint64_t distinct = 0;
  for (std::int32_t y = 0; y < target.height(); ++y) {
    for (std::int32_t x = 0; x < target.width(); ++x)
      distinct += (target.color(x, y) >> 24) != 0;
  }
  // Each written pixel passed at least once; the first fragment on a cleared pixel always passes.
  if (distinct == 0 || report.fragments_passed < distinct ||
      report.fragments_passed > report.fragments) {
    return "inconsistent writes: " + std::to_string(report.fragments_passed) + " passed, " +
           std::to_string(distinct) + " pixels written, " + std::to_string(report.fragments) +
           " covered";
  }
  return {};
}

// The scene's first `triangles` triangles as a mesh.
DrawMesh first_triangles(const ShadingScene& s, std::size_t triangles) {
  DrawMesh mesh;
  mesh.positions = std::span(s.positions).first(3 * triangles);
  mesh.colors = std::span(s.colors).first(3 * triangles);
  return mesh;
}

// The run's checks and rate counters. Every call redraws the same set into a cleared target:
// the same counts each iteration.
void report_draws(benchmark::State& state, const DrawReport& last, Isa isa, std::size_t triangles,
                  int area, const Framebuffer& target) {
  const std::string problem = check(last, isa, triangles, area, target);
  if (!problem.empty()) state.SkipWithError(problem.c_str());
  const double iterations = double(state.iterations());
  const auto rate = [&](double per_call) {
    return benchmark::Counter(per_call * iterations, benchmark::Counter::kIsRate);
  };
  state.counters["triangles"] = rate(double(triangles));
  state.counters["fragments"] = rate(double(last.fragments));
  state.counters["written"] = rate(double(last.fragments_passed));
}

void draw_scene(benchmark::State& state, Isa isa, Camera camera, ShadingCase c,
                const DrawOptions& options, int samples = 1) {
  const std::size_t triangles = triangles_for(isa, c);
  const DrawMesh mesh = first_triangles(shading_scene(camera, c), triangles);
  Framebuffer target(kWidth, kHeight, samples);

  DrawReport last;
  double vertex_seconds = 0.0, raster_seconds = 0.0;
  for (auto _ : state) {
    state.PauseTiming();
    target.clear(kShadingClearColor, kShadingClearDepth);
    state.ResumeTiming();
    // draw(), stage by stage (kernels/draw/draw_stages.hpp), to time its vertex stage apart.
    detail::DrawCall call = detail::prepare_draw(target, mesh, options);
    if (!call.has_work()) {
      state.SkipWithError("the workload draws nothing");
      break;
    }
    const auto start = Clock::now();
    const detail::ScreenMesh screen = detail::map_to_screen(call, mesh, options);
    const auto mapped = Clock::now();
    detail::shade_screen_mesh(call, target, screen, options);
    benchmark::DoNotOptimize(target.color_tiles());
    benchmark::ClobberMemory();
    raster_seconds += std::chrono::duration<double>(Clock::now() - mapped).count();
    vertex_seconds += std::chrono::duration<double>(mapped - start).count();
    last = call.report;
  }

  report_draws(state, last, isa, triangles, c.area, target);
  // Share of draw()'s time spent in the vertex stage (transform, clipping, screen mapping).
  state.counters["vertex_share"] = vertex_seconds + raster_seconds > 0.0
                                       ? vertex_seconds / (vertex_seconds + raster_seconds)
                                       : 0.0;
}

void shading(benchmark::State& state, Isa isa, ShadingCase c) {
  draw_scene(state, isa, Camera::orthographic, c, shading_options(isa, Camera::orthographic));
}

void multisample(benchmark::State& state, Isa isa, ShadingCase c, int samples) {
  draw_scene(state, isa, Camera::orthographic, c, shading_options(isa, Camera::orthographic),
             samples);
}

// The same workload on every core, through draw() itself: with several threads, draw() runs
// the vertex stage of a mesh without indices on ranges of triangles at once, so it cannot be
// timed apart.
void shading_all_threads(benchmark::State& state, Isa isa, ShadingCase c) {
  DrawOptions options = shading_options(isa, Camera::orthographic);
  options.threads = 0;
  const std::size_t triangles = triangles_for(isa, c);
  const DrawMesh mesh = first_triangles(shading_scene(Camera::orthographic, c), triangles);
  Framebuffer target(kWidth, kHeight);
  DrawReport last;
  for (auto _ : state) {
    state.PauseTiming();
    target.clear(kShadingClearColor, kShadingClearDepth);
    state.ResumeTiming();
    last = draw(target, mesh, options);
    benchmark::DoNotOptimize(target.color_tiles());
    benchmark::ClobberMemory();
  }
  report_draws(state, last, isa, triangles, c.area, target);
  state.counters["threads"] = double(default_thread_count());
}

// The same workload without hierarchical depth: what skipping hidden tiles is worth.
void shading_without_tile_depth(benchmark::State& state, Isa isa, ShadingCase c) {
  DrawOptions options = shading_options(isa, Camera::orthographic);
  options.hierarchical_depth = false;
  draw_scene(state, isa, Camera::orthographic, c, options);
}

void shading_method(benchmark::State& state, Isa isa, ShadingCase c, InterpolationMethod method,
                    Perspective perspective) {
  DrawOptions options = shading_options(isa, Camera::perspective);
  options.interpolation = method;
  options.perspective = perspective;
  draw_scene(state, isa, Camera::perspective, c, options);
}

// Benchmark names: parts joined by '/'.
std::string joined(std::initializer_list<std::string_view> parts) {
  std::string name;
  for (std::string_view part : parts) {
    if (!name.empty()) name += '/';
    name += part;
  }
  return name;
}

std::string area_label(const ShadingCase& c) {
  return "area:" + std::to_string(c.area);
}

}  // namespace

void register_draw_benchmarks() {
  for (Isa isa : supported_isas()) {
    for (const ShadingCase& c : kShadingCases) {
      const std::string name = joined({"Shading", name_of(isa), area_label(c)});
      benchmark::RegisterBenchmark(name.c_str(), shading, isa, c)->Unit(benchmark::kMicrosecond);
    }
  }
  for (Isa isa : supported_isas()) {
    for (const ShadingCase& c : kShadingCases) {
      const std::string name = joined({"Shading", name_of(isa), "threads:all", area_label(c)});
      benchmark::RegisterBenchmark(name.c_str(), shading_all_threads, isa, c)
          ->Unit(benchmark::kMicrosecond)
          ->UseRealTime();
    }
  }
  for (Isa isa : supported_isas()) {
    if (isa == Isa::reference) continue;  // the multisample cost is the fast paths' question
    for (const ShadingCase& c : kShadingCases) {
      if (std::find(std::begin(kMultisampleAreas), std::end(kMultisampleAreas), c.area) ==
          std::end(kMultisampleAreas)) {
        continue;
      }
      for (int samples : {1, 2, 4, 8, 16}) {
        const std::string name = joined(
            {"Multisample", name_of(isa), "samples:" + std::to_string(samples), area_label(c)});
        benchmark::RegisterBenchmark(name.c_str(), multisample, isa, c, samples)
            ->Unit(benchmark::kMicrosecond);
      }
    }
  }
  for (Isa isa : supported_isas()) {
    if (isa == Isa::reference) continue;  // the reference never skips tiles
    for (const ShadingCase& c : kShadingCases) {
      const std::string name = joined({"ShadingWithoutTileDepth", name_of(isa), area_label(c)});
      benchmark::RegisterBenchmark(name.c_str(), shading_without_tile_depth, isa, c)
          ->Unit(benchmark::kMicrosecond);
    }
  }
  for (Isa isa : supported_isas()) {
    for (InterpolationMethod method : kInterpolationMethods) {
      for (Perspective perspective : {Perspective::correct, Perspective::affine}) {
        for (const ShadingCase& c : kShadingCases) {
          if (std::find(std::begin(kMethodAreas), std::end(kMethodAreas), c.area) ==
              std::end(kMethodAreas)) {
            continue;
          }
          const std::string name = joined({"ShadingMethod", name_of(isa), name_of(method),
                                           name_of(perspective), area_label(c)});
          benchmark::RegisterBenchmark(name.c_str(), shading_method, isa, c, method, perspective)
              ->Unit(benchmark::kMicrosecond)
              ->MinTime(kMethodMinTimeSeconds);
        }
      }
    }
  }
}

}  // namespace edgewise::bench
