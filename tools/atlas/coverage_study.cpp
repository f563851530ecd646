#include "atlas/coverage_study.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <vector>

#include "atlas/coverage_departures.hpp"
#include "atlas/edge_function_methods.hpp"
#include "edgewise/edgewise.hpp"
#include "exact_area_triangles.hpp"

namespace edgewise::atlas {
namespace {

// A square of cells x cells, each `cell` / 256 px, split into triangles along a random
// diagonal; the inner vertices moved by up to a third of a cell (multiples of 1/256 px), the
// border kept straight: a watertight mesh whose every pixel centre inside lies in one triangle,
// its corner at (x, y) (multiples of 1/256 px).
std::vector<Vec2> jittered_grid(int cells, int cell, float x, float y, std::mt19937_64& rng) {
  std::uniform_int_distribution<int> jitter(-cell / 3, cell / 3);
  std::vector<Vec2> corners((cells + 1) * (cells + 1));
  for (int j = 0; j <= cells; ++j) {
    for (int i = 0; i <= cells; ++i) {
      const bool border = i == 0 || j == 0 || i == cells || j == cells;
      const int dx = border ? 0 : jitter(rng), dy = border ? 0 : jitter(rng);
      corners[j * (cells + 1) + i] = {x + static_cast<float>(i * cell + dx) / 256.0f,
                                      y + static_cast<float>(j * cell + dy) / 256.0f};
    }
  }
  std::vector<Vec2> vertices;
  std::bernoulli_distribution flip(0.5);
  for (int j = 0; j < cells; ++j) {
    for (int i = 0; i < cells; ++i) {
      const Vec2 a = corners[j * (cells + 1) + i], b = corners[j * (cells + 1) + i + 1];
      const Vec2 c = corners[(j + 1) * (cells + 1) + i + 1], d = corners[(j + 1) * (cells + 1) + i];
      if (flip(rng)) {
        vertices.insert(vertices.end(), {a, b, c, a, c, d});
      } else {
        vertices.insert(vertices.end(), {a, b, d, b, c, d});
      }
    }
  }
  return vertices;
}

constexpr const char* kExactSeries = "fixed point (exact)";

double per_thousand(std::uint64_t count, std::uint64_t of) {
  return of == 0 ? 0.0 : 1000.0 * static_cast<double>(count) / static_cast<double>(of);
}

// The smallest x of a series where y is nonzero, or a negative number if there is none.
using Series = std::vector<std::pair<double, double>>;
double first_nonzero(const Series& series) {
  for (const auto& [x, y] : series) {
    if (y > 0.0) return x;
  }
  return -1.0;
}

std::string number(double x) {
  char text[32];
  std::snprintf(text, sizeof text, "%g", x);
  return text;
}

// Where each float arithmetic starts to fail, in words: "float32 leaks from 2048 px; float64
// never leaks, <range>".
std::string onset_reading(const Series& float32, const Series& float64, const std::string& what,
                          const std::string& unit, const std::string& range) {
  const auto one = [&](const char* name, const Series& series) {
    const double x = first_nonzero(series);
    std::string text = std::string(name) + " ";
    if (x < 0.0) return text + "never " + what;
    if (std::all_of(series.begin(), series.end(), [](const auto& p) { return p.second > 0.0; })) {
      return text + what + " at every point measured (" + number(series.front().first) + unit +
             " to " + number(series.back().first) + unit + ")";
    }
    return text + what + " from " + number(x) + unit;
  };
  return one("float32", float32) + "; " + one("float64", float64) + ", " + range +
         "; the fixed-point rasterizer is exact everywhere.";
}

constexpr const char* kMagnitudeDiffering = "coverage-magnitude-differing";
constexpr const char* kMagnitudeLeaks = "coverage-magnitude-watertight";

// Jittered meshes of 4-px cells moved away from the origin up to the guard band.
void magnitude_study(const StudySettings& settings, StudyOutput& out) {
  constexpr int kCells = 24, kCell = 4, kWindow = kCells * kCell;
  const int meshes = settings.quick ? 1 : 8;
  out.add_chart({kMagnitudeDiffering,
                 "Pixels decided unlike the exact rasterizer, as coordinates grow",
                 "distance of the mesh from the origin (px)", "differing pixels per 1000 covered",
                 true, true, ChartKind::line, ""});
  out.add_chart({kMagnitudeLeaks, "Holes and double hits in a watertight mesh, as coordinates grow",
                 "distance of the mesh from the origin (px)", "holes + double hits per 1000 pixels",
                 true, true, ChartKind::line, ""});
  Series differing[2], leaks[2];
  for (int k = 0; k <= 15; k += settings.quick ? 5 : 1) {
    // Up to the guard band: the window's far side stays inside it.
    const int origin = std::min(1 << k, kGuardBand - kWindow - 8);
    const PixelRect window{origin, origin, origin + kWindow, origin + kWindow};
    std::mt19937_64 rng(0x5eed + static_cast<std::uint64_t>(k));
    Departures total;
    for (int m = 0; m < meshes; ++m) {
      const auto corner = static_cast<float>(origin);
      total.add(
          measure_departures(jittered_grid(kCells, kCell * 256, corner, corner, rng), window));
    }
    const std::uint64_t mesh_pixels = std::uint64_t{kWindow} * kWindow * meshes;
    for (int i = 0; i < 2; ++i) {
      const Departure& d = total.method[i];
      differing[i].emplace_back(origin, per_thousand(d.differing, d.covered));
      leaks[i].emplace_back(origin, per_thousand(d.holes + d.doubles, mesh_pixels));
      out.add(kMagnitudeDiffering, std::string(name_of(kInexact[i])), origin,
              differing[i].back().second);
      out.add(kMagnitudeLeaks, std::string(name_of(kInexact[i])), origin, leaks[i].back().second);
    }
    out.add(kMagnitudeDiffering, kExactSeries, origin, 0.0);
    out.add(kMagnitudeLeaks, kExactSeries, origin, 0.0);
  }
  const std::string range = "up to the guard band (32768 px)";
  out.set_reading(
      kMagnitudeDiffering,
      onset_reading(differing[1], differing[0], "decides pixels differently", " px", range) +
          " float32's rounding of A x + B y + C near an edge changes single pixels at any "
          "distance; float64 is exact in the guard band (in 1/256 px every product stays below "
          "2^47 and every sum below 2^49, within its 53 bits).");
  out.set_reading(kMagnitudeLeaks,
                  onset_reading(leaks[1], leaks[0], "leaks", " px", range) +
                      " A shared edge gives both triangles the same E with opposite signs in any "
                      "arithmetic; the leaks come from triangles whose rounded area has the wrong "
                      "sign or is 0.");
}

constexpr const char* kSliverDiffering = "coverage-sliver-differing";
constexpr const char* kSliverLeaks = "coverage-sliver-watertight";

// Thin quads cut along their long diagonal (two slivers sharing it), 64 px long, of growing
// aspect ratio, at every angle, one per 96-px cell of a 1920x1080 target.
void sliver_study(const StudySettings& settings, StudyOutput& out) {
  constexpr int kWidth = 1920, kHeight = 1080, kCellPx = 96;
  constexpr double kLength = 64.0;
  const int batches = settings.quick ? 1 : 4;
  out.add_chart({kSliverDiffering, "Pixels decided unlike the exact rasterizer, as triangles thin",
                 "aspect ratio (long diagonal / short diagonal of the quad)",
                 "differing pixels per 1000 triangles", true, true, ChartKind::line, ""});
  out.add_chart({kSliverLeaks, "Holes and double hits along the shared long edge of two slivers",
                 "aspect ratio (long diagonal / short diagonal of the quad)",
                 "holes + double hits per 1000 quads", true, true, ChartKind::line, ""});
  Series differing[2], leaks[2];
  const PixelRect window{0, 0, kWidth, kHeight};
  for (double ratio = 1.0; ratio <= 16384.0; ratio *= settings.quick ? 64.0 : 4.0) {
    std::mt19937_64 rng(0x511 + static_cast<std::uint64_t>(ratio));
    std::uniform_real_distribution<double> unit(0.0, 1.0);
    const auto snapped = [](double v) {
      return static_cast<float>(std::nearbyint(v * 256.0) / 256.0);
    };
    Departures total;
    std::uint64_t quads = 0;
    for (int b = 0; b < batches; ++b) {
      std::vector<Vec2> vertices;
      for (int cy = 0; cy + kCellPx <= kHeight; cy += kCellPx) {
        for (int cx = 0; cx + kCellPx <= kWidth; cx += kCellPx) {
          const double angle = 2.0 * std::numbers::pi * unit(rng);
          const double dx = std::cos(angle), dy = std::sin(angle);
          const double mx = cx + kCellPx / 2.0 + 8.0 * (unit(rng) - 0.5);
          const double my = cy + kCellPx / 2.0 + 8.0 * (unit(rng) - 0.5);
          const double half = kLength / 2.0, width = kLength / ratio / 2.0;
          const double skew1 = kLength / 4.0 * (unit(rng) - 0.5),
                       skew2 = kLength / 4.0 * (unit(rng) - 0.5);
          const Vec2 p0{snapped(mx - half * dx), snapped(my - half * dy)};
          const Vec2 p2{snapped(mx + half * dx), snapped(my + half * dy)};
          const Vec2 p1{snapped(mx - width * dy + skew1 * dx),
                        snapped(my + width * dx + skew1 * dy)};
          const Vec2 p3{snapped(mx + width * dy + skew2 * dx),
                        snapped(my - width * dx + skew2 * dy)};
          vertices.insert(vertices.end(), {p0, p1, p2, p0, p2, p3});
          ++quads;
        }
      }
      total.add(measure_departures(vertices, window));
    }
    for (int i = 0; i < 2; ++i) {
      const Departure& d = total.method[i];
      differing[i].emplace_back(ratio, per_thousand(d.differing, 2 * quads));
      leaks[i].emplace_back(ratio, per_thousand(d.holes + d.doubles, quads));
      out.add(kSliverDiffering, std::string(name_of(kInexact[i])), ratio,
              differing[i].back().second);
      out.add(kSliverLeaks, std::string(name_of(kInexact[i])), ratio, leaks[i].back().second);
    }
    out.add(kSliverDiffering, kExactSeries, ratio, 0.0);
    out.add(kSliverLeaks, kExactSeries, ratio, 0.0);
  }
  out.set_reading(kSliverDiffering,
                  onset_reading(differing[1], differing[0], "decides pixels differently", ":1",
                                "on a 1920x1080 target"));
  out.set_reading(kSliverLeaks,
                  onset_reading(leaks[1], leaks[0], "leaks", ":1", "on a 1920x1080 target"));
}

constexpr const char* kSizeDiffering = "coverage-size-differing";
constexpr const char* kSizeLeaks = "coverage-size-watertight";

// Jittered meshes of 16x16 cells, the cell from 1/64 px to 4 px, at random places on a
// 1920x1080 target.
void size_study(const StudySettings& settings, StudyOutput& out) {
  constexpr int kCells = 16;
  const int meshes = settings.quick ? 4 : 256;
  out.add_chart({kSizeDiffering, "Pixels decided unlike the exact rasterizer, as triangles shrink",
                 "cell of the mesh (px; two triangles per cell)",
                 "differing pixels per 1000 triangles", true, true, ChartKind::line, ""});
  out.add_chart({kSizeLeaks, "Holes and double hits in a watertight mesh of small triangles",
                 "cell of the mesh (px; two triangles per cell)",
                 "holes + double hits per 1000 triangles", true, true, ChartKind::line, ""});
  Series differing[2], leaks[2];
  for (int cell = 4; cell <= 1024; cell *= settings.quick ? 16 : 2) {  // in 1/256 px
    const double cell_px = cell / 256.0;
    const int extent = static_cast<int>(std::ceil(kCells * cell_px)) + 2;
    std::mt19937_64 rng(0x512e + static_cast<std::uint64_t>(cell));
    std::uniform_int_distribution<int> x_units(256 * 8, 256 * (1900 - extent));
    std::uniform_int_distribution<int> y_units(256 * 8, 256 * (1060 - extent));
    Departures total;
    for (int m = 0; m < meshes; ++m) {
      const int x = x_units(rng), y = y_units(rng);
      const PixelRect window{x / 256, y / 256, x / 256 + extent + 1, y / 256 + extent + 1};
      const std::vector<Vec2> mesh = jittered_grid(kCells, cell, static_cast<float>(x) / 256.0f,
                                                   static_cast<float>(y) / 256.0f, rng);
      total.add(measure_departures(mesh, window));
    }
    const std::uint64_t triangles = std::uint64_t{2} * kCells * kCells * meshes;
    for (int i = 0; i < 2; ++i) {
      const Departure& d = total.method[i];
      differing[i].emplace_back(cell_px, per_thousand(d.differing, triangles));
      leaks[i].emplace_back(cell_px, per_thousand(d.holes + d.doubles, triangles));
      out.add(kSizeDiffering, std::string(name_of(kInexact[i])), cell_px,
              differing[i].back().second);
      out.add(kSizeLeaks, std::string(name_of(kInexact[i])), cell_px, leaks[i].back().second);
    }
    out.add(kSizeDiffering, kExactSeries, cell_px, 0.0);
    out.add(kSizeLeaks, kExactSeries, cell_px, 0.0);
  }
  out.set_reading(kSizeDiffering,
                  onset_reading(differing[1], differing[0], "decides pixels differently",
                                " px cells", "on a 1920x1080 target"));
  out.set_reading(kSizeLeaks,
                  onset_reading(leaks[1], leaks[0], "leaks", " px cells", "on a 1920x1080 target"));
}

// Adds one to a pixel's count for each covered centre: the same output work for every method.
class CountingSink final : public CoverageSink {
 public:
  CountingSink(std::vector<std::uint8_t>& counts, int width) : counts_(counts), width_(width) {}
  void consume(std::span<const TileCoverage> tiles) override {
    for (const TileCoverage& tile : tiles) {
      for (std::uint64_t mask = tile.mask; mask != 0; mask &= mask - 1) {
        const int bit = std::countr_zero(mask);
        ++counts_[static_cast<std::size_t>(tile.tile_y * 8 + bit / 8) * width_ + tile.tile_x * 8 +
                  bit % 8];
      }
    }
  }

 private:
  std::vector<std::uint8_t>& counts_;
  std::size_t width_;
};

constexpr const char* kSpeed = "coverage-speed";
constexpr const char* kPareto = "coverage-pareto";

// Random 64-px triangles on a 1920x1080 target: each method's time per triangle (the study's
// loops, the library's reference and fast paths) and, against it, its differing pixels.
void speed_study(const StudySettings& settings, StudyOutput& out) {
  constexpr int kWidth = 1920, kHeight = 1080;
  const std::size_t count = settings.quick ? 256 : 4096;
  const std::vector<Vec2> vertices =
      workload::exact_area_triangles(count, 64.0, kWidth, kHeight, 0x5eed'ed6e'0000'0001);
  const PixelRect window{0, 0, kWidth, kHeight};
  out.add_chart({kSpeed, "Time per triangle, 64-px triangles on 1920x1080", "method",
                 "ns per triangle", false, true, ChartKind::bar, ""});
  out.add_chart({kPareto, "Error against time, 64-px triangles on 1920x1080", "ns per triangle",
                 "differing pixels per 1000 covered", true, true, ChartKind::scatter, ""});
  const Departures departures = measure_departures(vertices, window);
  std::vector<std::uint8_t> counts(std::size_t{kWidth} * kHeight);
  const double per_triangle = 1.0 / static_cast<double>(count);
  std::string fastest_exact;
  double fastest_exact_ns = 0.0, float32_ns = 0.0, fixed_loop_ns = 0.0;
  for (EdgeArithmetic arithmetic : kEdgeArithmetics) {
    const std::string name = std::string(name_of(arithmetic)) + " (scalar loop)";
    const double ns =
        per_triangle *
        median_nanoseconds(
            "coverage/" + name,
            [&] {
              for (std::size_t t = 0; t < count; ++t) {
                const Vec2 triangle[3] = {vertices[3 * t], vertices[3 * t + 1],
                                          vertices[3 * t + 2]};
                cover_triangle(arithmetic, triangle, window, [&](std::int32_t x, std::int32_t y) {
                  ++counts[std::size_t(y) * kWidth + x];
                });
              }
            },
            settings.timer);
    out.add(kSpeed, "time", name, ns);
    double error = 0.0;
    if (arithmetic != EdgeArithmetic::fixed_point) {
      const Departure& d = departures.method[arithmetic == EdgeArithmetic::float64 ? 0 : 1];
      error = per_thousand(d.differing, d.covered);
    }
    out.add(kPareto, name, ns, error);
    if (arithmetic == EdgeArithmetic::float32) float32_ns = ns;
    if (arithmetic == EdgeArithmetic::fixed_point) fixed_loop_ns = ns;
  }
  for (Isa isa : supported_isas()) {
    const std::string name = "library, " + std::string(name_of(isa));
    RasterOptions options;
    options.isa = isa;
    const RasterTarget target{kWidth, kHeight, {}};
    CountingSink sink(counts, kWidth);
    const double ns =
        per_triangle * median_nanoseconds(
                           "coverage/" + name,
                           [&] { rasterize(vertices, {}, target, options, sink); }, settings.timer);
    out.add(kSpeed, "time", name, ns);
    out.add(kPareto, name, ns, 0.0);
    if (fastest_exact.empty() || ns < fastest_exact_ns) {
      fastest_exact = name;
      fastest_exact_ns = ns;
    }
  }
  char reading[256];
  std::snprintf(reading, sizeof reading,
                "The exact rasterizer's fastest path (%s) takes %.0f ns per triangle, %.1fx less "
                "than the float32 loop, which gets pixels wrong.",
                fastest_exact.c_str(), fastest_exact_ns, float32_ns / fastest_exact_ns);
  out.set_reading(kSpeed, reading);
  std::snprintf(reading, sizeof reading,
                "Lower left is better. The exact fixed point costs %.2fx the float32 loop's time "
                "in the same plain loop, and the library's fastest path %.2fx.",
                fixed_loop_ns / float32_ns, fastest_exact_ns / float32_ns);
  out.set_reading(kPareto, reading);
}

}  // namespace

StudyOutput coverage_study(const StudySettings& settings, const std::string& cpu) {
  StudyOutput out("coverage", "Coverage: exact fixed point against float edge functions", cpu);
  magnitude_study(settings, out);
  sliver_study(settings, out);
  size_study(settings, out);
  speed_study(settings, out);
  return out;
}

}  // namespace edgewise::atlas
