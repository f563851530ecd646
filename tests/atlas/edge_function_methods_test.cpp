// The atlas's edge-function methods against the library's coverage: the fixed-point loop equals
// rasterize() pixel for pixel wherever the library draws (every magnitude up to the guard band,
// sub-pixel triangles, both windings, edges through pixel centres); so does float64, exact in
// that range (the float32 departures the atlas charts are its findings, not tested here).
#include <gtest/gtest.h>

#include <algorithm>
#include <bit>
#include <cstdint>
#include <vector>

#include "atlas/edge_function_methods.hpp"
#include "edgewise/edgewise.hpp"
#include "random.hpp"

namespace edgewise::atlas {
namespace {

// (y, x) of the covered pixels, sorted.
using Pixels = std::vector<std::pair<std::int32_t, std::int32_t>>;

class PixelSink final : public CoverageSink {
 public:
  Pixels pixels;
  void consume(std::span<const TileCoverage> tiles) override {
    for (const TileCoverage& tile : tiles) {
      for (std::uint64_t mask = tile.mask; mask != 0; mask &= mask - 1) {
        const int bit = std::countr_zero(mask);
        pixels.emplace_back(tile.tile_y * 8 + bit / 8, tile.tile_x * 8 + bit % 8);
      }
    }
  }
};

Pixels library_pixels(const Vec2 (&triangle)[3], const PixelRect& window) {
  PixelSink sink;
  rasterize(std::span<const Vec2>(triangle, 3), {}, RasterTarget{window.x1, window.y1, window},
            RasterOptions{}, sink);
  std::sort(sink.pixels.begin(), sink.pixels.end());
  return sink.pixels;
}

Pixels method_pixels(EdgeArithmetic arithmetic, const Vec2 (&triangle)[3],
                     const PixelRect& window) {
  Pixels pixels;
  cover_triangle(arithmetic, triangle, window,
                 [&](std::int32_t x, std::int32_t y) { pixels.emplace_back(y, x); });
  return pixels;
}

// A random triangle near (cx, cy): vertices on the 1/256 grid, or on a coarse grid (1/2 px)
// where edges pass exactly through pixel centres and the fill rule decides.
void random_triangle(test::Random& random, double cx, double cy, double size, bool coarse,
                     Vec2 (&triangle)[3]) {
  const double step = coarse ? 0.5 : 1.0 / 256.0;
  for (Vec2& v : triangle) {
    v.x = static_cast<float>(std::round((cx + random.uniform(-size, size)) / step) * step);
    v.y = static_cast<float>(std::round((cy + random.uniform(-size, size)) / step) * step);
  }
}

// Float64 is exact inside the guard band: in units of 1/256 px the snapped coordinates are
// integers below 2^23 and their differences below 2^24, so each product of A x + B y + C lies
// below 2^47 and each sum below 2^49 (coverage.hpp's bound), within double's 53 bits; scaling
// to pixels by 2^-8 rounds nothing.
TEST(AtlasEdgeFunctions, FixedPointAndFloat64DecideAsTheLibraryAtEveryMagnitude) {
  test::Random random(0xa71a5);
  int compared = 0, nonempty = 0;
  for (int magnitude = 0; magnitude <= 15; ++magnitude) {
    const double centre = std::min(double(1 << magnitude), kGuardBand - 80.0);
    for (int t = 0; t < 300; ++t) {
      Vec2 triangle[3];
      const double size = random.log_uniform(1.0 / 64.0, 60.0);
      random_triangle(random, centre + 8.0, centre + 8.0, size, random.chance(0.3), triangle);
      const auto lo = static_cast<std::int32_t>(std::max(0.0, centre - 64.0));
      const PixelRect window{lo, lo, static_cast<std::int32_t>(centre) + 72,
                             static_cast<std::int32_t>(centre) + 72};
      const Pixels expected = library_pixels(triangle, window);
      for (EdgeArithmetic arithmetic : {EdgeArithmetic::fixed_point, EdgeArithmetic::float64}) {
        ASSERT_EQ(method_pixels(arithmetic, triangle, window), expected)
            << name_of(arithmetic) << ", magnitude 2^" << magnitude << ", triangle ("
            << triangle[0].x << ", " << triangle[0].y << ") (" << triangle[1].x << ", "
            << triangle[1].y << ") (" << triangle[2].x << ", " << triangle[2].y << ")";
      }
      ++compared;
      nonempty += !expected.empty();
    }
  }
  // Many triangles are below a pixel and cover no centre; most of the rest do.
  EXPECT_GT(nonempty, compared / 3);
}

TEST(AtlasEdgeFunctions, ZeroAreaCoversNothing) {
  const Vec2 line[3] = {{1.0f, 1.0f}, {5.0f, 5.0f}, {9.0f, 9.0f}};
  for (EdgeArithmetic arithmetic : kEdgeArithmetics)
    EXPECT_TRUE(method_pixels(arithmetic, line, PixelRect{0, 0, 16, 16}).empty());
}

}  // namespace
}  // namespace edgewise::atlas
