// Clipping throughput: clip_triangle() (float32, what draw() runs) against the scalar
// double-precision reference, on clip-space triangles that need no clipping, that cross the
// near plane, and that cross the guard band, so that the cost of each path is known apart.
#include <benchmark/benchmark.h>

#include <cstdint>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "../../benchmarks.hpp"
#include "edgewise/camera.hpp"
#include "draw/vertex_stage/clip_reference.hpp"
#include "draw/vertex_stage/clip.hpp"

namespace edgewise::bench {
namespace {

constexpr std::uint64_t kClipSeed = 0x5eed'ed6e'0000'0004;
constexpr std::size_t kTriangles = 4096;

enum class Crossing { none, near, guard_band };
struct ClipCase {
  const char* name;
  Crossing crossing;
  ClipStatus expected;  // what every triangle of the case must give
};
constexpr ClipCase kCases[] = {
    {"inside", Crossing::none, ClipStatus::inside},
    {"near", Crossing::near, ClipStatus::clipped},
    {"guard_band", Crossing::guard_band, ClipStatus::clipped},
};

// A clip-space point at depth w in the view: x and y at the given fractions of w, z in the
// middle of 0 <= z <= w.
Vec4 point(float fx, float fy, float w) {
  return {fx * w, fy * w, 0.5f * w, w};
}

// Triangles with vertices inside the view frustum; one vertex then moves behind the near plane
// (z < 0), or far outside one side (x = 40 w: beyond the guard band of a full HD target, whose
// planes are near x = +-(1 + 2 * 8192 / 1920) w).
std::vector<Vec4> workload(Crossing crossing) {
  std::mt19937_64 random(kClipSeed);
  std::uniform_real_distribution<float> fraction(-0.9f, 0.9f), depth(1.0f, 50.0f);
  std::vector<Vec4> vertices;
  vertices.reserve(kTriangles * 3);
  for (std::size_t t = 0; t < kTriangles; ++t) {
    for (int v = 0; v < 3; ++v) {
      Vec4 p = point(fraction(random), fraction(random), depth(random));
      if (v == 0 && crossing == Crossing::near) p.z = -0.5f * p.w;
      if (v == 0 && crossing == Crossing::guard_band) p.x = 40.0f * p.w;
      vertices.push_back(p);
    }
  }
  return vertices;
}

// What the benchmark keeps of a clipped polygon (the two clippers return different types).
struct ClipOutcome {
  ClipStatus status;
  int triangles;  // the polygon's fan
};

template <class Clip>
void clip_batch(benchmark::State& state, const ClipCase& c, Clip clip) {
  const std::vector<Vec4> vertices = workload(c.crossing);
  // A benchmark that clipped something else (everything outside, say) would measure nothing.
  for (std::size_t i = 0; i < vertices.size(); i += 3) {
    if (clip(vertices[i], vertices[i + 1], vertices[i + 2]).status != c.expected)
      throw std::logic_error(std::string("clip benchmark: unexpected status in case ") + c.name);
  }
  std::uint64_t output_triangles = 0;
  for (auto _ : state) {
    for (std::size_t i = 0; i < vertices.size(); i += 3) {
      const ClipOutcome outcome = clip(vertices[i], vertices[i + 1], vertices[i + 2]);
      output_triangles += static_cast<std::uint64_t>(outcome.triangles);
      benchmark::DoNotOptimize(outcome);
    }
  }
  const double iterations = static_cast<double>(state.iterations());
  state.counters["triangles"] =
      benchmark::Counter(double(kTriangles) * iterations, benchmark::Counter::kIsRate);
  state.counters["out_per_in"] = double(output_triangles) / (double(kTriangles) * iterations);
}

}  // namespace

void register_clip_benchmarks() {
  const Viewport viewport{kWidth, kHeight};
  const GuardBandPlanes planes = guard_band_planes(viewport);
  for (const ClipCase& c : kCases) {
    benchmark::RegisterBenchmark(
        (std::string("Clip/float32/") + c.name).c_str(),
        [c, planes](benchmark::State& state) {
          clip_batch(state, c, [&](const Vec4& a, const Vec4& b, const Vec4& d) {
            const ClippedPolygon polygon = clip_triangle(a, b, d, planes);
            return ClipOutcome{polygon.status, polygon.triangle_count()};
          });
        })
        ->Unit(benchmark::kMicrosecond);
    benchmark::RegisterBenchmark(
        (std::string("Clip/reference/") + c.name).c_str(),
        [c, viewport](benchmark::State& state) {
          clip_batch(state, c, [&](const Vec4& a, const Vec4& b, const Vec4& d) {
            const reference::ClippedPolygon polygon = reference::clip_triangle(a, b, d, viewport);
            const int count = static_cast<int>(polygon.vertices.size());
            return ClipOutcome{polygon.status, count >= 3 ? count - 2 : 0};
          });
        })
        ->Unit(benchmark::kMicrosecond);
  }
}

}  // namespace edgewise::bench
