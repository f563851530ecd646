// Targets and scissors: coverage is clipped to the target intersected with the scissor, whatever
// their sizes and alignment to the 8x8 tiles, and nothing is delivered outside them.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "coverage_result.hpp"
#include "isa_params.hpp"
#include "pixel_art.hpp"

namespace edgewise::test {
namespace {

using Viewport = IsaTest;

// Its hypotenuse is x + y = 200: it covers every sample of the targets below.
const std::vector<Vec2> kHugeTriangle = {{-100.0f, -100.0f}, {300.0f, -100.0f}, {-100.0f, 300.0f}};

RasterTarget with_scissor(std::int32_t width, std::int32_t height, PixelRect scissor) {
  RasterTarget target{width, height, {}};
  target.scissor = scissor;
  return target;
}

TEST_P(Viewport, EmptyTargetsCoverNothing) {
  for (const RasterTarget target :
       {RasterTarget{0, 0, {}}, RasterTarget{0, 16, {}}, RasterTarget{16, 0, {}}}) {
    const RasterRun run = draw(isa(), kHugeTriangle, target);
    EXPECT_TRUE(run.tiles.empty());
    EXPECT_EQ(run.statuses[0], TriangleStatus::drawn);
    EXPECT_EQ(run.report.drawn, 1u);
  }
}

TEST_P(Viewport, OnePixelTarget) {
  const RasterTarget one{1, 1, {}};
  EXPECT_TRUE(covers_exactly(covered_pixels(draw(isa(), kHugeTriangle, one)), {{0, 0}}));
  // The only sample on a bottom edge, then on a top edge.
  const std::vector<Vec2> above = {{0.0f, 0.5f}, {2.0f, 0.5f}, {1.0f, -1.0f}};
  EXPECT_TRUE(covered_pixels(draw(isa(), above, one)).empty());
  const std::vector<Vec2> below = {{0.0f, 0.5f}, {2.0f, 0.5f}, {1.0f, 2.0f}};
  EXPECT_TRUE(covers_exactly(covered_pixels(draw(isa(), below, one)), {{0, 0}}));
  // A triangle beside the target.
  const std::vector<Vec2> beside = {{1.25f, 0.0f}, {3.0f, 0.0f}, {2.0f, 3.0f}};
  EXPECT_TRUE(covered_pixels(draw(isa(), beside, one)).empty());
}

TEST_P(Viewport, TriangleLargerThanTheTarget) {
  for (const auto& [w, h] :
       {std::pair{13, 7}, std::pair{8, 8}, std::pair{9, 17}, std::pair{1, 40}}) {
    SCOPED_TRACE(::testing::Message() << w << "x" << h);
    EXPECT_TRUE(covers_exactly(covered_pixels(draw(isa(), kHugeTriangle, RasterTarget{w, h, {}})),
                               block(0, 0, w, h)));
  }
}

TEST_P(Viewport, UnalignedScissor) {
  EXPECT_TRUE(covers_exactly(
      covered_pixels(draw(isa(), kHugeTriangle, with_scissor(32, 32, {3, 2, 11, 7}))),
      block(3, 2, 11, 7)));
  EXPECT_TRUE(covers_exactly(
      covered_pixels(draw(isa(), kHugeTriangle, with_scissor(32, 32, {9, 17, 10, 18}))),
      {{9, 17}}));
}

TEST_P(Viewport, ScissorIsIntersectedWithTheTarget) {
  EXPECT_TRUE(covers_exactly(
      covered_pixels(draw(isa(), kHugeTriangle, with_scissor(32, 32, {-5, -5, 4, 3}))),
      block(0, 0, 4, 3)));
  EXPECT_TRUE(covers_exactly(
      covered_pixels(draw(isa(), kHugeTriangle, with_scissor(30, 31, {28, 27, 40, 40}))),
      block(28, 27, 30, 31)));
}

TEST_P(Viewport, EmptyScissorCoversNothing) {
  for (const PixelRect scissor : {PixelRect{5, 5, 5, 9}, PixelRect{5, 5, 9, 5},
                                  PixelRect{40, 40, 50, 50}, PixelRect{-10, 3, 0, 9}}) {
    const RasterRun run = draw(isa(), kHugeTriangle, with_scissor(32, 32, scissor));
    EXPECT_TRUE(run.tiles.empty());
    EXPECT_EQ(run.statuses[0], TriangleStatus::drawn);
  }
}

TEST_P(Viewport, ScissorKeepsSharedEdgesExact) {
  // Two triangles sharing the diagonal y = x through samples, clipped by a scissor that cuts
  // the diagonal: the scissored block, each sample once.
  const std::vector<Vec2> pair = {{0.5f, 0.5f}, {12.5f, 12.5f}, {0.5f, 12.5f},
                                  {0.5f, 0.5f}, {12.5f, 0.5f},  {12.5f, 12.5f}};
  EXPECT_TRUE(covers_exactly(covered_pixels(draw(isa(), pair, with_scissor(16, 16, {3, 2, 9, 11}))),
                             block(3, 2, 9, 11)));
}

EDGEWISE_INSTANTIATE_PER_ISA(Viewport, every_isa());

}  // namespace
}  // namespace edgewise::test
