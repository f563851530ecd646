// The guard band: snapped vertices in [-32768, 32768) px are rasterized exactly, anything else
// (or a NaN or infinity) is an error status, never a wrong pixel.
#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <cmath>
#include <limits>
#include <vector>

#include "coverage_result.hpp"
#include "isa_params.hpp"
#include "pixel_art.hpp"

namespace edgewise::test {
namespace {

using GuardBand = IsaTest;

constexpr float kLowest = -32768.0f;               // -2^23 steps: the band's first position
constexpr float kHighest = 32767.99609375f;        // 2^23 - 1 steps: its last
constexpr float kTieIntoBand = -32767.998046875f;  // -(2^23 - 0.5) steps: ties to -2^23
constexpr float kTieOutOfBand = 32767.998046875f;  // 2^23 - 0.5 steps: ties to 2^23

const RasterTarget kSmall{16, 16, {}};
const Vec2 kValid[3] = {{1.0f, 1.0f}, {9.0f, 2.0f}, {3.0f, 7.0f}};

// `kValid` with one coordinate (0..5: x0, y0, x1, ...) replaced.
std::vector<Vec2> with_coordinate(int slot, float value) {
  std::vector<Vec2> tri(kValid, kValid + 3);
  float& c = slot % 2 == 0 ? tri[slot / 2].x : tri[slot / 2].y;
  c = value;
  return tri;
}

std::vector<Pixel> pixels_where(const RasterTarget& target, auto predicate) {
  std::vector<Pixel> pixels;
  for (std::int32_t y = 0; y < target.height; ++y) {
    for (std::int32_t x = 0; x < target.width; ++x) {
      if (predicate(x, y)) pixels.push_back({x, y});
    }
  }
  return pixels;
}

TEST_P(GuardBand, ExtremeVerticesShareAnExactDiagonal) {
  // The diagonal from (-2^23, -2^23) to (2^23 - 1, 2^23 - 1) steps is the line y = x through
  // every (i + 0.5, i + 0.5) sample. Below it the diagonal is a right edge (excluded), above it
  // a left edge (included): each sample once.
  const RasterTarget target{24, 20, {}};
  const Vec2 low{kLowest, kLowest}, high{kHighest, kHighest};
  for (const auto& tri : vertex_orders(low, high, {kLowest, kHighest})) {
    EXPECT_TRUE(covers_exactly(covered_pixels(draw(isa(), tri, target)),
                               pixels_where(target, [](int x, int y) { return y > x; })));
  }
  for (const auto& tri : vertex_orders(low, high, {kHighest, kLowest})) {
    EXPECT_TRUE(covers_exactly(covered_pixels(draw(isa(), tri, target)),
                               pixels_where(target, [](int x, int y) { return y <= x; })));
  }
}

TEST_P(GuardBand, VerticesJustInsideAreDrawn) {
  for (int slot = 0; slot < 6; ++slot) {
    for (float value : {kLowest, kHighest, kTieIntoBand}) {
      SCOPED_TRACE(::testing::Message() << "coordinate " << slot << " = " << format_float(value));
      EXPECT_EQ(draw(isa(), with_coordinate(slot, value), kSmall).statuses[0],
                TriangleStatus::drawn);
    }
  }
}

TEST_P(GuardBand, VerticesJustOutsideAreErrors) {
  const float outside[] = {32768.0f,
                           kTieOutOfBand,
                           std::nextafter(kLowest, -1e9f),
                           65536.0f,
                           -1e30f,
                           std::numeric_limits<float>::max(),
                           std::numeric_limits<float>::lowest()};
  for (int slot = 0; slot < 6; ++slot) {
    for (float value : outside) {
      SCOPED_TRACE(::testing::Message() << "coordinate " << slot << " = " << format_float(value));
      const RasterRun run = draw(isa(), with_coordinate(slot, value), kSmall);
      EXPECT_EQ(run.statuses[0], TriangleStatus::error_outside_guard_band);
      EXPECT_TRUE(run.tiles.empty());
      EXPECT_EQ(run.report.errors, 1u);
    }
  }
}

TEST_P(GuardBand, NonFiniteVerticesAreErrors) {
  const float quiet_nan = std::numeric_limits<float>::quiet_NaN();
  const float non_finite[] = {quiet_nan,
                              -quiet_nan,
                              std::numeric_limits<float>::signaling_NaN(),
                              std::bit_cast<float>(std::uint32_t{0x7fc12345}),
                              std::numeric_limits<float>::infinity(),
                              -std::numeric_limits<float>::infinity()};
  for (int slot = 0; slot < 6; ++slot) {
    for (float value : non_finite) {
      SCOPED_TRACE(::testing::Message() << "coordinate " << slot << " = " << format_float(value));
      const RasterRun run = draw(isa(), with_coordinate(slot, value), kSmall);
      EXPECT_EQ(run.statuses[0], TriangleStatus::error_non_finite);
      EXPECT_TRUE(run.tiles.empty());
    }
  }
  // NaN beside an out-of-band coordinate: an error either way, the same on every ISA (run_checked
  // compares the status with the reference's).
  std::vector<Vec2> both = with_coordinate(0, quiet_nan);
  both[2].y = 1e20f;
  EXPECT_TRUE(is_error(draw(isa(), both, kSmall).statuses[0]));
}

// Counts pixels and checks that every delivered tile is full.
class FullTileCounter final : public CoverageSink {
 public:
  void consume(std::span<const TileCoverage> tiles) override {
    for (const TileCoverage& tile : tiles) {
      pixels += static_cast<std::uint64_t>(std::popcount(tile.mask));
      if (tile.mask != ~std::uint64_t{0}) ++partial_tiles;
    }
  }
  std::uint64_t pixels = 0, partial_tiles = 0;
};

TEST_P(GuardBand, BandFillingTriangleCoversTheLargestTarget) {
  // The hypotenuse runs from (-2^23, 2^23 - 1) to (2^23 - 1, -2^23) steps, i.e. x + y = -1 step:
  // every sample of a 32768 x 32768 target is inside.
  const std::vector<Vec2> tri = {{kHighest, kHighest}, {kLowest, kHighest}, {kHighest, kLowest}};
  RasterTarget largest{kMaxTargetSize, kMaxTargetSize, {}};
  const std::uint64_t all = std::uint64_t{kMaxTargetSize} * kMaxTargetSize;
  if (isa() == Isa::reference) {
    // Per-pixel evaluation of 2^30 samples would take minutes: check the far corner only.
    largest.scissor =
        PixelRect{kMaxTargetSize - 40, kMaxTargetSize - 24, kMaxTargetSize, kMaxTargetSize};
    EXPECT_EQ(covered_pixels(draw(isa(), tri, largest)).size(), 40u * 24u);
    return;
  }
  RasterOptions options;
  options.isa = isa();
  const CoverageCount count = count_coverage(tri, {}, largest, options);
  EXPECT_EQ(count.pixels, all);
  EXPECT_EQ(count.report.drawn, 1u);
  FullTileCounter sink;
  rasterize(tri, {}, largest, options, sink);
  EXPECT_EQ(sink.pixels, all);
  EXPECT_EQ(sink.partial_tiles, 0u);
}

TEST_P(GuardBand, CornersOfTheLargestTarget) {
  const RasterTarget largest{kMaxTargetSize, kMaxTargetSize, {}};
  const std::int32_t last = kMaxTargetSize - 1;
  for (const Pixel corner : {Pixel{0, 0}, Pixel{last, 0}, Pixel{0, last}, Pixel{last, last}}) {
    const float x = static_cast<float>(corner.x), y = static_cast<float>(corner.y);
    const std::vector<Vec2> tri = {
        {x + 0.25f, y + 0.25f}, {x + 0.75f, y + 0.5f}, {x + 0.5f, y + 0.75f}};
    const RasterRun run = draw(isa(), tri, largest);
    EXPECT_TRUE(covers_exactly(covered_pixels(run), {corner}));
    ASSERT_EQ(run.tiles.size(), 1u);
    EXPECT_EQ(run.tiles[0].tile_x, corner.x / kTileSize);
    EXPECT_EQ(run.tiles[0].tile_y, corner.y / kTileSize);
  }
  // The band's last position, one step short of 32768, as a vertex: the last pixel is covered
  // (its sample lies beyond the hypotenuse x + y = 65535 - 1 step, on the vertex's side).
  const std::vector<Vec2> tri = {{kHighest, kHighest}, {32767.0f, kHighest}, {kHighest, 32767.0f}};
  const RasterRun run = draw(isa(), tri, largest);
  EXPECT_TRUE(covers_exactly(covered_pixels(run), {{last, last}}));
  ASSERT_EQ(run.tiles.size(), 1u);
  EXPECT_EQ(run.tiles[0].mask, std::uint64_t{1} << 63);
}

TEST_P(GuardBand, NearlyHorizontalLongEdgesMatchTheReference) {
  // Edges that rise 1/256 px over thousands of pixels: rows cross them thousands of columns
  // apart, the regime where row intercepts need the most precision. run_checked compares with
  // the reference. Slopes from 2^18 to 2^22 steps per step straddle the span walk's limit.
  const RasterTarget target{4096, 64, {}};
  const float step = 1.0f / 256.0f;
  for (const float run : {1024.0f, 2048.0f, 4095.0f, 4096.0f, 8192.0f, 16384.0f}) {
    for (const float y : {3.5f, 3.5f + step, 17.25f, 40.0f - step}) {
      const Vec2 left{-3.0f, y}, right{run - 3.0f, y + step}, apex{700.0f, y + 20.0f};
      for (const auto& tri : vertex_orders(left, right, apex)) {
        const RasterRun result = draw(isa(), tri, target);
        EXPECT_GT(covered_pixels(result).size(), 0u);
      }
      for (const auto& tri : vertex_orders(left, right, {700.0f, y - 20.0f}))
        draw(isa(), tri, target);
    }
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(GuardBand, every_isa());

}  // namespace
}  // namespace edgewise::test
