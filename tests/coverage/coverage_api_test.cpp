// The raster entry points' contract: argument errors throw std::invalid_argument, bad triangles
// get error statuses, culled ones culled statuses, and the report counts them all.
#include <gtest/gtest.h>

#include <bit>
#include <limits>
#include <stdexcept>
#include <vector>

#include "coverage_result.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "triangle_sources.hpp"

namespace edgewise::test {
namespace {

using RasterApi = IsaTest;

class CountingSink final : public CoverageSink {
 public:
  void consume(std::span<const TileCoverage> tiles) override {
    for (const TileCoverage& tile : tiles)
      pixels += static_cast<std::uint64_t>(std::popcount(tile.mask));
    ++calls;
  }
  std::uint64_t pixels = 0, calls = 0;
};

RasterOptions options_for(Isa isa, CullMode cull = CullMode::none) {
  RasterOptions options;
  options.isa = isa;
  options.cull = cull;
  return options;
}

// Both entry points reject the call, and nothing reaches the sink.
void expect_rejected(std::span<const Vec2> vertices, std::span<const std::uint32_t> indices,
                     const RasterTarget& target, const RasterOptions& options,
                     std::string_view message_part) {
  CountingSink sink;
  try {
    rasterize(vertices, indices, target, options, sink);
    ADD_FAILURE() << "rasterize accepted a call that should fail with \"" << message_part << "\"";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find(message_part), std::string::npos) << e.what();
  }
  EXPECT_EQ(sink.calls, 0u);
  EXPECT_THROW(count_coverage(vertices, indices, target, options), std::invalid_argument);
}

TEST_P(RasterApi, InvalidArgumentsThrow) {
  const std::vector<Vec2> three = {{0, 0}, {8, 0}, {0, 8}};
  const std::vector<Vec2> four = {{0, 0}, {8, 0}, {0, 8}, {8, 8}};
  const RasterTarget target{16, 16, {}};
  const RasterOptions options = options_for(isa());

  expect_rejected(four, {}, target, options, "not a multiple of 3");
  const std::vector<std::uint32_t> four_indices = {0, 1, 2, 0};
  expect_rejected(three, four_indices, target, options, "not a multiple of 3");

  std::vector<TriangleStatus> two_statuses(2);
  RasterOptions with_statuses = options;
  with_statuses.statuses = two_statuses;
  expect_rejected(three, {}, target, with_statuses, "statuses");

  for (const RasterTarget bad :
       {RasterTarget{kMaxTargetSize + 1, 16, {}}, RasterTarget{16, kMaxTargetSize + 1, {}},
        RasterTarget{-1, 16, {}}, RasterTarget{16, -1, {}}}) {
    expect_rejected(three, {}, bad, options, "target");
    EXPECT_THROW(clip_rect(bad), std::invalid_argument);
  }
  for (const PixelRect inverted : {PixelRect{5, 2, 4, 8}, PixelRect{2, 5, 8, 4}}) {
    RasterTarget scissored = target;
    scissored.scissor = inverted;
    expect_rejected(three, {}, scissored, options, "inverted");
    EXPECT_THROW(clip_rect(scissored), std::invalid_argument);
  }
  RasterOptions bad_cull = options;
  bad_cull.cull = static_cast<CullMode>(7);
  expect_rejected(three, {}, target, bad_cull, "cull");
}

TEST(RasterApiIsa, UnsupportedIsaOptionThrows) {
  int unsupported = 0;
  for (Isa isa : every_isa_value()) {
    if (isa_supported(isa)) continue;
    ++unsupported;
    const std::vector<Vec2> tri = {{0, 0}, {8, 0}, {0, 8}};
    CountingSink sink;
    EXPECT_THROW(rasterize(tri, {}, RasterTarget{16, 16, {}}, options_for(isa), sink),
                 std::invalid_argument);
    EXPECT_THROW(count_coverage(tri, {}, RasterTarget{16, 16, {}}, options_for(isa)),
                 std::invalid_argument);
  }
  // No build compiles both the x86 and the AArch64 kernels.
  EXPECT_GT(unsupported, 0);
}

TEST_P(RasterApi, EmptyInput) {
  const RasterCall call{{}, {}, RasterTarget{16, 16, {}}};
  const RasterRun run = run_checked(isa(), call);
  EXPECT_TRUE(run.tiles.empty());
  EXPECT_EQ(run.report.triangles, 0u);
  EXPECT_EQ(run.report.errors, 0u);
  EXPECT_FALSE(run.report.first_error_triangle.has_value());
}

// A batch holding one triangle of every status. Triangle 0 is clockwise on screen
// ((x1-x0)(y2-y0) - (y1-y0)(x2-x0) = 64 > 0).
const std::vector<Vec2> kMixedVertices = {
    {0, 0},
    {8, 0},
    {0, 8},  // 0-2: a clockwise triangle
    {1, 1},
    {2, 2},
    {3, 3},  // 3-5: collinear
    {std::numeric_limits<float>::quiet_NaN(), 0},
    {40000, 0}  // 6: NaN, 7: out of band
};
const std::vector<std::uint32_t> kMixedIndices = {
    0, 1, 2,            // t0: clockwise
    3, 4, 5,            // t1: zero area
    0, 2, 1,            // t2: counter-clockwise
    0, 6, 1,            // t3: non-finite
    7, 1, 2,            // t4: outside the guard band
    0, 1, 99,           // t5: index past the end
    2, 1, 0,            // t6: counter-clockwise
    1, 2, 0,            // t7: clockwise (t0 rotated)
    0, 1, 0xFFFFFFFFu,  // t8: index past the end
};

TEST_P(RasterApi, StatusesAndReportCounts) {
  using S = TriangleStatus;
  struct Case {
    CullMode cull;
    std::vector<TriangleStatus> statuses;
    std::uint64_t drawn, culled;
  };
  const Case cases[] = {
      {CullMode::none,
       {S::drawn, S::culled_zero_area, S::drawn, S::error_non_finite, S::error_outside_guard_band,
        S::error_bad_index, S::drawn, S::drawn, S::error_bad_index},
       4,
       1},
      {CullMode::clockwise,
       {S::culled_winding, S::culled_zero_area, S::drawn, S::error_non_finite,
        S::error_outside_guard_band, S::error_bad_index, S::drawn, S::culled_winding,
        S::error_bad_index},
       2,
       3},
      {CullMode::counter_clockwise,
       {S::drawn, S::culled_zero_area, S::culled_winding, S::error_non_finite,
        S::error_outside_guard_band, S::error_bad_index, S::culled_winding, S::drawn,
        S::error_bad_index},
       2,
       3},
  };
  for (const Case& c : cases) {
    const RasterCall call{kMixedVertices, kMixedIndices, RasterTarget{16, 16, {}}, c.cull};
    SCOPED_TRACE(describe_call(call));
    const RasterRun run = run_checked(isa(), call);
    EXPECT_EQ(run.statuses, c.statuses);
    EXPECT_EQ(run.report.triangles, 9u);
    EXPECT_EQ(run.report.drawn, c.drawn);
    EXPECT_EQ(run.report.culled, c.culled);
    EXPECT_EQ(run.report.errors, 4u);
    EXPECT_EQ(run.report.first_error_triangle, std::optional<std::uint64_t>{3});
    EXPECT_EQ(run.report.first_error, S::error_non_finite);
    // Only drawn triangles cover, and all windings of one triangle cover the same pixels.
    const std::uint32_t first_drawn = c.cull == CullMode::clockwise ? 2 : 0;
    const std::vector<Pixel> expected = covered_pixels(run, first_drawn);
    EXPECT_FALSE(expected.empty());
    for (std::uint32_t t = 0; t < 9; ++t) {
      EXPECT_EQ(covered_pixels(run, t).empty(), c.statuses[t] != S::drawn) << "triangle " << t;
      if (c.statuses[t] == S::drawn) {
        EXPECT_EQ(covered_pixels(run, t), expected) << "triangle " << t;
      }
    }

    // The same report without asking for statuses, and from count_coverage.
    RasterOptions options = options_for(isa(), c.cull);
    CountingSink sink;
    const RasterReport without_statuses =
        rasterize(kMixedVertices, kMixedIndices, call.target, options, sink);
    const CoverageCount counted =
        count_coverage(kMixedVertices, kMixedIndices, call.target, options);
    for (const RasterReport& r : {without_statuses, counted.report}) {
      EXPECT_EQ(r.triangles, run.report.triangles);
      EXPECT_EQ(r.drawn, run.report.drawn);
      EXPECT_EQ(r.culled, run.report.culled);
      EXPECT_EQ(r.errors, run.report.errors);
      EXPECT_EQ(r.first_error_triangle, run.report.first_error_triangle);
      EXPECT_EQ(r.first_error, run.report.first_error);
      EXPECT_EQ(r.isa, isa());
    }
    EXPECT_EQ(counted.pixels, covered_pixels(run).size());
  }
}

TEST_P(RasterApi, CountCoverageEqualsTheMaskPopcount) {
  Random random(0xc0de'c0de);
  for (const TriangleSource& source : triangle_sources()) {
    std::vector<Vec2> vertices(3 * 300);
    RasterTarget target = source.target;
    if (source.window > 0)
      target.scissor = PixelRect{100, 200, 100 + source.window, 200 + source.window};
    for (std::size_t t = 0; t < vertices.size(); t += 3) {
      Vec2 tri[3];
      source.make(random, clip_rect(target), tri);
      std::copy(tri, tri + 3, vertices.begin() + static_cast<std::ptrdiff_t>(t));
    }
    for (CullMode cull : {CullMode::none, CullMode::clockwise, CullMode::counter_clockwise}) {
      SCOPED_TRACE(::testing::Message() << source.name << ", cull " << static_cast<int>(cull));
      const RasterOptions options = options_for(isa(), cull);
      CountingSink sink;
      const RasterReport report = rasterize(vertices, {}, target, options, sink);
      const CoverageCount count = count_coverage(vertices, {}, target, options);
      EXPECT_EQ(count.pixels, sink.pixels);
      EXPECT_EQ(count.report.drawn, report.drawn);
      EXPECT_EQ(count.report.culled, report.culled);
      EXPECT_EQ(count.report.errors, report.errors);
      EXPECT_EQ(count.pixels,
                count_coverage(vertices, {}, target, options_for(Isa::reference, cull)).pixels);
    }
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(RasterApi, every_isa());

}  // namespace
}  // namespace edgewise::test
