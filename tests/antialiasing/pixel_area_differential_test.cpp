// rasterize_areas() on every ISA against the exact-area reference: per pixel within the stated
// tolerance, on random triangles of every generator (slivers, ties, huge ones, the guard band),
// with well-formed tiles (row order, masks equal to the nonzero areas) and the reference's
// statuses and counts.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <map>
#include <span>
#include <string>
#include <tuple>
#include <utility>
#include <vector>

#include "edgewise/pixel_area.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "antialiasing/pixel_area_reference.hpp"
#include "triangle_sources.hpp"

namespace edgewise::test {
namespace {

class CollectingAreaSink final : public AreaSink {
 public:
  void consume(std::span<const AreaTile> batch) override {
    tiles.insert(tiles.end(), batch.begin(), batch.end());
  }
  std::vector<AreaTile> tiles;
};

struct AreaRun {
  RasterReport report;
  std::vector<TriangleStatus> statuses;
  std::vector<AreaTile> tiles;
};

AreaRun run_areas(Isa isa, std::span<const Vec2> vertices, const RasterTarget& target,
                  CullMode cull) {
  AreaRun run;
  run.statuses.resize(vertices.size() / 3);
  RasterOptions options;
  options.isa = isa;
  options.cull = cull;
  options.statuses = run.statuses;
  CollectingAreaSink sink;
  run.report = rasterize_areas(vertices, {}, target, options, sink);
  run.tiles = std::move(sink.tiles);
  return run;
}

// (triangle, y, x) -> area.
using AreaMap = std::map<std::tuple<std::uint32_t, std::int32_t, std::int32_t>, float>;

::testing::AssertionResult well_formed(const AreaRun& run, AreaMap& areas) {
  const AreaTile* previous = nullptr;
  for (const AreaTile& tile : run.tiles) {
    if (tile.mask == 0) return ::testing::AssertionFailure() << "a tile with an empty mask";
    if (previous != nullptr && std::tuple(previous->triangle, previous->tile_y, previous->tile_x) >=
                                   std::tuple(tile.triangle, tile.tile_y, tile.tile_x)) {
      return ::testing::AssertionFailure() << "tiles out of order at triangle " << tile.triangle;
    }
    previous = &tile;
    for (int bit = 0; bit < 64; ++bit) {
      const bool set = (tile.mask >> bit & 1) != 0;
      const float area = tile.area[bit];
      if (set != (area > 0.0f) || !(area <= 1.0f)) {
        return ::testing::AssertionFailure()
               << "pixel " << bit << " of tile (" << tile.tile_x << ", " << tile.tile_y
               << "): mask bit " << set << ", area " << area;
      }
      if (set) {
        areas[{tile.triangle, tile.tile_y * 8 + bit / 8, tile.tile_x * 8 + bit % 8}] = area;
      }
    }
  }
  return ::testing::AssertionSuccess();
}

// Every pixel either side reports (0 where the other omits it) within the tolerance of the
// reference's area; `pixels` counts the pixels compared.
::testing::AssertionResult matches_reference(Isa isa, const std::vector<Vec2>& vertices,
                                             const RasterTarget& target, std::uint64_t& pixels) {
  const double tolerance = kPixelAreaTolerance + reference::kPixelAreaErrorBound;
  const AreaRun expected = run_areas(Isa::reference, vertices, target, CullMode::none);
  const AreaRun actual = run_areas(isa, vertices, target, CullMode::none);
  AreaMap want, got;
  if (auto formed = well_formed(expected, want); !formed) return formed << " (reference)";
  if (auto formed = well_formed(actual, got); !formed) return formed;
  for (const auto& [key, area] : want)
    got.try_emplace(key, 0.0f);
  for (const auto& [key, area] : got) {
    const auto found = want.find(key);
    const double reference_area = found == want.end() ? 0.0 : double(found->second);
    ++pixels;
    if (!(std::abs(double(area) - reference_area) <= tolerance)) {
      return ::testing::AssertionFailure()
             << "triangle " << std::get<0>(key) << " pixel (" << std::get<2>(key) << ", "
             << std::get<1>(key) << "): reference " << reference_area << ", " << name_of(isa) << " "
             << area;
    }
  }
  return ::testing::AssertionSuccess();
}

using AreaDifferential = IsaTest;

// Both sides may differ from the exact area: the ISA by the tolerance, the reference by its
// bound. A pixel one side omits has an area of 0 there.
TEST_P(AreaDifferential, EverySourceWithinTheTolerance) {
  const double tolerance = kPixelAreaTolerance + reference::kPixelAreaErrorBound;
  Random random(0xa7ea'd1ff);
  double worst = 0.0;
  std::uint64_t pixels = 0;
  for (const TriangleSource& source : triangle_sources()) {
    for (int batch = 0; batch < 6; ++batch) {
      RasterTarget target = source.target;
      PixelRect aim = clip_rect(target);
      if (source.window > 0) {
        // A window keeps the reference's work small for large triangles.
        const std::int32_t w = static_cast<std::int32_t>(random.integer(1, source.window));
        const std::int32_t h = static_cast<std::int32_t>(random.integer(1, source.window));
        const std::int32_t x = static_cast<std::int32_t>(random.integer(0, target.width - w));
        const std::int32_t y = static_cast<std::int32_t>(random.integer(0, target.height - h));
        target.scissor = aim = PixelRect{x, y, x + w, y + h};
      }
      std::vector<Vec2> vertices;
      for (int t = 0; t < 64; ++t) {
        Vec2 tri[3];
        source.make(random, aim, tri);
        vertices.insert(vertices.end(), tri, tri + 3);
      }
      const CullMode cull = batch % 3 == 2 ? CullMode::clockwise : CullMode::none;
      const AreaRun expected = run_areas(Isa::reference, vertices, target, cull);
      const AreaRun actual = run_areas(isa(), vertices, target, cull);
      const std::string where = std::string(source.name) + " batch " + std::to_string(batch);
      ASSERT_TRUE(expected.statuses == actual.statuses) << where;
      ASSERT_EQ(expected.report.drawn, actual.report.drawn) << where;
      ASSERT_EQ(expected.report.culled, actual.report.culled) << where;
      ASSERT_EQ(expected.report.errors, actual.report.errors) << where;
      AreaMap want, got;
      ASSERT_TRUE(well_formed(expected, want)) << where << " (reference)";
      ASSERT_TRUE(well_formed(actual, got)) << where;
      std::map<std::tuple<std::uint32_t, std::int32_t, std::int32_t>, std::pair<float, float>> both;
      for (const auto& [key, area] : want)
        both[key].first = area;
      for (const auto& [key, area] : got)
        both[key].second = area;
      for (const auto& [key, pair] : both) {
        const double difference = std::abs(double(pair.first) - double(pair.second));
        worst = std::max(worst, difference);
        ++pixels;
        ASSERT_LE(difference, tolerance)
            << where << ": triangle " << std::get<0>(key) << " pixel (" << std::get<2>(key) << ", "
            << std::get<1>(key) << "): reference " << pair.first << ", " << name_of(isa()) << " "
            << pair.second;
      }
    }
  }
  EXPECT_GT(pixels, 10000u);
  std::printf("[ %-8s ] %llu pixels, largest difference from the reference %.3g px^2\n",
              std::string(name_of(isa())).c_str(), static_cast<unsigned long long>(pixels), worst);
}

// `batches` batches of `count` triangles, each made by make(random, tri), against the reference
// pixel by pixel; returns the number of pixels compared.
template <class Make>
std::uint64_t compare_batches(Isa isa, const RasterTarget& target, int batches, int count,
                              Random& random, Make make) {
  std::uint64_t pixels = 0;
  for (int batch = 0; batch < batches; ++batch) {
    std::vector<Vec2> vertices;
    for (int t = 0; t < count; ++t) {
      Vec2 tri[3];
      make(random, t, tri);
      vertices.insert(vertices.end(), tri, tri + 3);
    }
    EXPECT_TRUE(matches_reference(isa, vertices, target, pixels)) << "batch " << batch;
  }
  return pixels;
}

// Boxes from one pixel to several times kBoxWalkMaxGroups groups of lanes wide (narrow ones are
// computed whole, wide ones by candidates per row), with horizontal and vertical edges among
// them, against the reference pixel by pixel.
TEST_P(AreaDifferential, NarrowAndWideBoxesWithinTheTolerance) {
  Random random(0xa7ea'b0c5);
  const RasterTarget target{256, 256, std::nullopt};
  const auto make = [](Random& draw, int t, Vec2 tri[3]) {
    const double width = draw.log_uniform(0.5, 160.0), height = draw.log_uniform(0.5, 160.0);
    const double x = draw.uniform(-8.0, 256.0 - width + 8.0);
    const double y = draw.uniform(-8.0, 256.0 - height + 8.0);
    for (int i = 0; i < 3; ++i) {
      tri[i] = {static_cast<float>(x + draw.uniform(0.0, width)),
                static_cast<float>(y + draw.uniform(0.0, height))};
    }
    if (t % 4 == 1) tri[1].y = tri[0].y;  // a horizontal edge
    if (t % 4 == 2) tri[2].x = tri[1].x;  // a vertical edge
  };
  EXPECT_GT(compare_batches(isa(), target, 16, 48, random, make), 50000u);
}

// Rows of more tiles than rasterize_areas() buffers for its sink (32): long slivers across a
// wide target, against the reference pixel by pixel.
TEST_P(AreaDifferential, RowsWiderThanTheOutputBuffer) {
  Random random(0xa7ea'3ede);
  const RasterTarget target{1024, 48, std::nullopt};
  const auto make = [](Random& draw, int, Vec2 tri[3]) {
    const double width = draw.uniform(260.0, 1000.0), height = draw.uniform(0.5, 40.0);
    const double x = draw.uniform(-8.0, 1024.0 - width + 8.0);
    const double y = draw.uniform(-4.0, 48.0 - height + 4.0);
    tri[0] = {static_cast<float>(x), static_cast<float>(y + draw.uniform(0.0, height))};
    tri[1] = {static_cast<float>(x + width), static_cast<float>(y)};
    tri[2] = {static_cast<float>(x + draw.uniform(0.0, width)), static_cast<float>(y + height)};
  };
  EXPECT_GT(compare_batches(isa(), target, 4, 6, random, make), 20000u);
}

// Summed over a triangle's pixels, the areas give the triangle's area (one triangle inside the
// target, so that nothing is clipped): n pixels within the tolerance each.
TEST_P(AreaDifferential, PixelsAddUpToTheTriangle) {
  Random random(0xa7ea'5013);
  const RasterTarget target{512, 512, std::nullopt};
  for (int trial = 0; trial < 300; ++trial) {
    const double size = random.log_uniform(0.01, 200.0);
    const double cx = random.uniform(210.0, 300.0), cy = random.uniform(210.0, 300.0);
    std::vector<Vec2> tri;
    for (int i = 0; i < 3; ++i) {
      tri.push_back({static_cast<float>(cx + random.uniform(-size, size)),
                     static_cast<float>(cy + random.uniform(-size, size))});
    }
    const AreaRun run = run_areas(isa(), tri, target, CullMode::none);
    if (run.statuses[0] != TriangleStatus::drawn) continue;
    double sum = 0.0;
    std::size_t n = 0;
    for (const AreaTile& tile : run.tiles) {
      for (int bit = 0; bit < 64; ++bit) {
        sum += tile.area[bit];
        n += (tile.mask >> bit) & 1;
      }
    }
    reference::SnappedTriangle snapped;
    ASSERT_EQ(reference::snap_and_classify(tri[0], tri[1], tri[2], CullMode::none, snapped),
              TriangleStatus::drawn);
    ASSERT_NEAR(sum, reference::triangle_area(snapped),
                static_cast<double>(n) * kPixelAreaTolerance + 1e-9)
        << "trial " << trial;
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(AreaDifferential, every_isa());

}  // namespace
}  // namespace edgewise::test
