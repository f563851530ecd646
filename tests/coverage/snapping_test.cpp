// Snapping to 1/256 px, round to nearest with ties to even, happens before every coverage and
// area decision. Coordinates at exact ties (k + 0.5 steps) pick the even neighbour, whichever
// direction that is.
#include <gtest/gtest.h>

#include <cmath>
#include <vector>

#include "coverage_result.hpp"
#include "isa_params.hpp"
#include "pixel_art.hpp"

namespace edgewise::test {
namespace {

using Snapping = IsaTest;

// A coordinate of `steps` snapping steps (1/256 px); exact in float for |steps| < 2^24.
float steps(double count) {
  return static_cast<float>(count / 256.0);
}

TriangleStatus status_of(Isa isa, const Vec2& a, const Vec2& b, const Vec2& c) {
  const std::vector<Vec2> tri = {a, b, c};
  return draw(isa, tri, RasterTarget{16, 16, {}}).statuses[0];
}

TEST_P(Snapping, TiesRoundToEven) {
  // The third vertex lands on the line y = x through (0, 0) and (512, 512) steps exactly when
  // its tied coordinate rounds to the even neighbour; any other rounding leaves a sliver.
  const Vec2 origin{0.0f, 0.0f}, far{steps(512), steps(512)};
  // 257.5 -> 258 (up to even).
  EXPECT_EQ(status_of(isa(), origin, far, {steps(257.5), steps(258)}),
            TriangleStatus::culled_zero_area);
  // 256.5 -> 256 (down to even).
  EXPECT_EQ(status_of(isa(), origin, far, {steps(256.5), steps(256)}),
            TriangleStatus::culled_zero_area);
  // The same in y, and for negative coordinates: -257.5 -> -258, -256.5 -> -256.
  EXPECT_EQ(status_of(isa(), origin, far, {steps(258), steps(257.5)}),
            TriangleStatus::culled_zero_area);
  const Vec2 negative_far{steps(-512), steps(-512)};
  EXPECT_EQ(status_of(isa(), origin, negative_far, {steps(-257.5), steps(-258)}),
            TriangleStatus::culled_zero_area);
  EXPECT_EQ(status_of(isa(), origin, negative_far, {steps(-256.5), steps(-256)}),
            TriangleStatus::culled_zero_area);
}

TEST_P(Snapping, JustPastATieRoundsAway) {
  // One float above 256.5 steps is nearer 257: the vertex leaves the line y = x.
  const Vec2 origin{0.0f, 0.0f}, far{steps(512), steps(512)};
  const float past_tie = std::nextafter(steps(256.5), 2.0f);
  EXPECT_EQ(status_of(isa(), origin, far, {past_tie, steps(256)}), TriangleStatus::drawn);
  const float before_tie = std::nextafter(steps(257.5), 0.0f);
  EXPECT_EQ(status_of(isa(), origin, far, {before_tie, steps(258)}), TriangleStatus::drawn);
}

TEST_P(Snapping, TieDecidesWhetherASampleIsOnALeftEdge) {
  // A vertical left edge at 640.5 steps snaps down to 640 = 2.5 px, onto column 2's samples,
  // which the left edge includes. Rounding half up would move it past them.
  const float edge_x = steps(640.5);
  const std::vector<Vec2> tri = {{edge_x, 0.25f}, {edge_x, 4.25f}, {4.25f, 2.25f}};
  const RasterRun run = draw(isa(), tri, RasterTarget{8, 8, {}});
  EXPECT_TRUE(covers_exactly(covered_pixels(run), pixels_from_art({
                                                      "..#.....",
                                                      "..##....",
                                                      "..##....",
                                                      "..#.....",
                                                      "........",
                                                  })));
}

TEST_P(Snapping, TieDecidesWhetherASampleIsOnATopEdge) {
  // A top edge at 640.5 steps snaps to y = 2.5, onto row 2's samples: included.
  const float edge_y = steps(640.5);
  const std::vector<Vec2> tri = {{0.25f, edge_y}, {6.25f, edge_y}, {3.25f, 4.75f}};
  const RasterRun run = draw(isa(), tri, RasterTarget{8, 8, {}});
  EXPECT_TRUE(covers_exactly(covered_pixels(run), pixels_from_art({
                                                      "........",
                                                      "........",
                                                      "######..",
                                                      "..###...",
                                                      "...#....",
                                                  })));
}

TEST_P(Snapping, CoverageUsesSnappedVertices) {
  // Each vertex is within half a step of (0.5, 0.5), (4.5, 0.5), (0.5, 4.5): the result is
  // that triangle's, with its samples on the top and left edges.
  const float q = steps(0.375);
  const std::vector<Vec2> tri = {{0.5f + q, 0.5f - q}, {4.5f - q, 0.5f + q}, {0.5f - q, 4.5f + q}};
  EXPECT_TRUE(
      covers_exactly(covered_pixels(draw(isa(), tri, RasterTarget{8, 8, {}})), pixels_from_art({
                                                                                   "####.",
                                                                                   "###..",
                                                                                   "##...",
                                                                                   "#....",
                                                                               })));
}

TEST_P(Snapping, ZeroAreaAfterSnappingIsCulled) {
  // Collinear once 0.001 px is rounded away.
  EXPECT_EQ(status_of(isa(), {0.0f, 0.0f}, {1.0f, 1.0f}, {2.0f, 2.001f}),
            TriangleStatus::culled_zero_area);
  // All three vertices within half a step of one point.
  EXPECT_EQ(status_of(isa(), {3.1f, 3.1f}, {3.1001f, 3.1f}, {3.1f, 3.1001f}),
            TriangleStatus::culled_zero_area);
  // Coincident vertices, and exactly collinear ones through samples.
  EXPECT_EQ(status_of(isa(), {2.5f, 2.5f}, {2.5f, 2.5f}, {7.5f, 1.5f}),
            TriangleStatus::culled_zero_area);
  EXPECT_EQ(status_of(isa(), {0.5f, 0.5f}, {2.5f, 1.5f}, {6.5f, 3.5f}),
            TriangleStatus::culled_zero_area);
  // A real, if thin, triangle one step off the line is drawn.
  EXPECT_EQ(status_of(isa(), {0.5f, 0.5f}, {2.5f, 1.5f + steps(1)}, {6.5f, 3.5f}),
            TriangleStatus::drawn);
}

EDGEWISE_INSTANTIATE_PER_ISA(Snapping, every_isa());

}  // namespace
}  // namespace edgewise::test
