// The top-left rule on samples that lie exactly on edges and vertices, worked out by hand and
// checked on every ISA (each run is also compared with the reference).
//
// A top edge is horizontal with the triangle below it; a left edge is not horizontal and has the
// interior to its right. Samples on those are covered; samples on bottom and right edges are not.
#include <gtest/gtest.h>

#include <algorithm>
#include <vector>

#include "coverage_result.hpp"
#include "isa_params.hpp"
#include "pixel_art.hpp"

namespace edgewise::test {
namespace {

using FillRule = IsaTest;

constexpr float kFixedStep = 1.0f / 256.0f;  // one snapping step
const RasterTarget kTarget{16, 16, {}};

// Draws the triangle in all six vertex orders; each must cover exactly `expected`.
void expect_every_order_covers(Isa isa, const Vec2& a, const Vec2& b, const Vec2& c,
                               const std::vector<Pixel>& expected,
                               const RasterTarget& target = kTarget) {
  for (const std::vector<Vec2>& order : vertex_orders(a, b, c)) {
    SCOPED_TRACE(describe_triangle(RasterCall{order, {}, target}, 0));
    const RasterRun run = draw(isa, order, target);
    EXPECT_EQ(run.statuses[0], TriangleStatus::drawn);
    EXPECT_TRUE(covers_exactly(covered_pixels(run), expected));
  }
}

TEST_P(FillRule, TopAndLeftEdgesIncluded) {
  // Top edge y = 0.5, left edge x = 0.5, hypotenuse x + y = 5 (a right edge) excluded.
  expect_every_order_covers(isa(), {0.5f, 0.5f}, {4.5f, 0.5f}, {0.5f, 4.5f},
                            pixels_from_art({
                                "####.",
                                "###..",
                                "##...",
                                "#....",
                                ".....",
                            }));
}

TEST_P(FillRule, BottomAndRightEdgesExcluded) {
  // Bottom edge y = 4.5 and right edge x = 4.5 excluded; hypotenuse x + y = 5 (a left edge)
  // included.
  expect_every_order_covers(isa(), {0.5f, 4.5f}, {4.5f, 4.5f}, {4.5f, 0.5f},
                            pixels_from_art({
                                ".....",
                                "...#.",
                                "..##.",
                                ".###.",
                                ".....",
                            }));
}

TEST_P(FillRule, DiagonalWithInteriorOnItsLeftIsARightEdge) {
  // The diagonal y = x has the interior below-left: samples on it are excluded.
  expect_every_order_covers(isa(), {0.5f, 0.5f}, {4.5f, 4.5f}, {0.5f, 4.5f},
                            pixels_from_art({
                                ".....",
                                "#....",
                                "##...",
                                "###..",
                                ".....",
                            }));
}

TEST_P(FillRule, DiagonalWithInteriorOnItsRightIsALeftEdge) {
  // The diagonal y = x has the interior above-right: samples on it are included.
  expect_every_order_covers(isa(), {0.5f, 0.5f}, {4.5f, 0.5f}, {4.5f, 4.5f},
                            pixels_from_art({
                                "####.",
                                ".###.",
                                "..##.",
                                "...#.",
                                ".....",
                            }));
}

TEST_P(FillRule, VertexOnASampleIsCoveredOnlyWhereBothEdgesAreTopLeft) {
  // The sample (2.5, 3.5) is a vertex of each triangle.
  const Vec2 s{2.5f, 3.5f};
  const float d = 0.125f;
  // Top edge and left edge meet at s: covered.
  expect_every_order_covers(isa(), s, {s.x + d, s.y}, {s.x, s.y + d}, {{2, 3}});
  // Top edge and a right (vertical, interior on its left) edge meet at s: not covered.
  expect_every_order_covers(isa(), s, {s.x - d, s.y}, {s.x, s.y + d}, {});
  // Bottom edge and left edge: not covered.
  expect_every_order_covers(isa(), s, {s.x + d, s.y}, {s.x, s.y - d}, {});
  // The smallest triangle there is, one snapping step per leg, at a top-left corner: covered.
  expect_every_order_covers(isa(), s, {s.x + kFixedStep, s.y}, {s.x, s.y + kFixedStep}, {{2, 3}});
}

TEST_P(FillRule, SubPixelTriangles) {
  // Around the sample (2.5, 3.5): covered.
  expect_every_order_covers(isa(), {2.375f, 3.375f}, {2.625f, 3.375f}, {2.5f, 3.625f}, {{2, 3}});
  // Between samples: nothing, though drawn.
  expect_every_order_covers(isa(), {2.125f, 3.125f}, {2.375f, 3.125f}, {2.25f, 3.375f}, {});
  // The sample on the triangle's top edge: covered.
  expect_every_order_covers(isa(), {2.375f, 3.5f}, {2.625f, 3.5f}, {2.5f, 3.625f}, {{2, 3}});
  // The sample on its bottom edge: not covered.
  expect_every_order_covers(isa(), {2.375f, 3.5f}, {2.625f, 3.5f}, {2.5f, 3.375f}, {});
  // The sample on its left (vertical) edge: covered; on its right edge: not.
  expect_every_order_covers(isa(), {2.5f, 3.375f}, {2.5f, 3.625f}, {2.625f, 3.5f}, {{2, 3}});
  expect_every_order_covers(isa(), {2.5f, 3.375f}, {2.5f, 3.625f}, {2.375f, 3.5f}, {});
}

TEST_P(FillRule, HorizontalSliverCoversSamplesOnItsTopEdge) {
  // One snapping step high, its top edge on row 0's samples. The far vertex (40.5, 0.5) is on
  // the right edge x = 40.5: excluded. The near vertex lies on the top edge and the long
  // diagonal, whose interior is to its right (a left edge): included.
  const RasterTarget target{48, 8, {}};
  std::vector<Pixel> row0;
  for (int x = 0; x < 40; ++x)
    row0.push_back({x, 0});
  expect_every_order_covers(isa(), {0.5f, 0.5f}, {40.5f, 0.5f}, {40.5f, 0.5f + kFixedStep}, row0,
                            target);
  // Mirrored: the samples are on its bottom edge.
  expect_every_order_covers(isa(), {0.5f, 0.5f}, {40.5f, 0.5f}, {40.5f, 0.5f - kFixedStep}, {},
                            target);
}

TEST_P(FillRule, VerticalSliverCoversSamplesOnItsLeftEdge) {
  // One snapping step wide, its left edge x = 0.5 through column 0's samples. The top vertex
  // also lies on the long diagonal, a right edge here: excluded; the bottom vertex lies on the
  // bottom edge: excluded.
  const RasterTarget target{8, 40, {}};
  std::vector<Pixel> column0;
  for (int y = 1; y < 30; ++y)
    column0.push_back({0, y});
  expect_every_order_covers(isa(), {0.5f, 0.5f}, {0.5f, 30.5f}, {0.5f + kFixedStep, 30.5f}, column0,
                            target);
  // Mirrored: x = 0.5 becomes a right edge.
  expect_every_order_covers(isa(), {0.5f, 0.5f}, {0.5f, 30.5f}, {0.5f - kFixedStep, 30.5f}, {},
                            target);
}

// Two triangles sharing an edge through samples, in every combination of vertex orders: the
// union is the block, each sample exactly once.
void expect_pair_tiles_block(Isa isa, const Vec2 first[3], const Vec2 second[3],
                             const std::vector<Pixel>& block_pixels) {
  for (const std::vector<Vec2>& a : vertex_orders(first[0], first[1], first[2])) {
    for (const std::vector<Vec2>& b : vertex_orders(second[0], second[1], second[2])) {
      std::vector<Vec2> both = a;
      both.insert(both.end(), b.begin(), b.end());
      SCOPED_TRACE(describe_triangle(RasterCall{both, {}, kTarget}, 0) + "\n" +
                   describe_triangle(RasterCall{both, {}, kTarget}, 1));
      EXPECT_TRUE(covers_exactly(covered_pixels(draw(isa, both, kTarget)), block_pixels));
    }
  }
}

TEST_P(FillRule, SharedEdgeCoversEachSampleOnce) {
  std::vector<Pixel> square = block(0, 0, 4, 4);
  std::sort(square.begin(), square.end());
  // Split along x + y = 5 and along y = x, both through samples.
  const Vec2 a[3] = {{0.5f, 0.5f}, {4.5f, 0.5f}, {0.5f, 4.5f}};
  const Vec2 b[3] = {{0.5f, 4.5f}, {4.5f, 4.5f}, {4.5f, 0.5f}};
  expect_pair_tiles_block(isa(), a, b, square);
  const Vec2 c[3] = {{0.5f, 0.5f}, {4.5f, 4.5f}, {0.5f, 4.5f}};
  const Vec2 d[3] = {{0.5f, 0.5f}, {4.5f, 0.5f}, {4.5f, 4.5f}};
  expect_pair_tiles_block(isa(), c, d, square);
  // A 4 x 8 block split along a slope-2 diagonal through (0.5 + k, 0.5 + 2k).
  std::vector<Pixel> tall = block(0, 0, 4, 8);
  std::sort(tall.begin(), tall.end());
  const Vec2 e[3] = {{0.5f, 0.5f}, {4.5f, 8.5f}, {0.5f, 8.5f}};
  const Vec2 f[3] = {{0.5f, 0.5f}, {4.5f, 0.5f}, {4.5f, 8.5f}};
  expect_pair_tiles_block(isa(), e, f, tall);
}

TEST_P(FillRule, FanAroundASampleCoversItOnce) {
  // Eight triangles around the sample (4.5, 4.5), with spokes along the axes and diagonals,
  // all through samples; the union is the 8 x 8 block [0.5, 8.5)^2 of samples, each once.
  const Vec2 center{4.5f, 4.5f};
  const Vec2 rim[8] = {{0.5f, 0.5f}, {4.5f, 0.5f}, {8.5f, 0.5f}, {8.5f, 4.5f},
                       {8.5f, 8.5f}, {4.5f, 8.5f}, {0.5f, 8.5f}, {0.5f, 4.5f}};
  std::vector<Vec2> fan;
  for (int i = 0; i < 8; ++i) {
    // Alternate windings: the rule does not depend on them.
    if (i % 2 == 0) {
      fan.insert(fan.end(), {center, rim[i], rim[(i + 1) % 8]});
    } else {
      fan.insert(fan.end(), {rim[(i + 1) % 8], rim[i], center});
    }
  }
  std::vector<Pixel> square = block(0, 0, 8, 8);
  std::sort(square.begin(), square.end());
  EXPECT_TRUE(covers_exactly(covered_pixels(draw(isa(), fan, kTarget)), square));
}

TEST_P(FillRule, SliversSharingADiagonalEdgeCoverItsSamplesOnce) {
  // The edge (0.5, 0.5)-(30.5, 10.5) holds the samples (0.5 + 3k, 0.5 + k); the two slivers
  // reach one snapping step to either side of its middle. Interior samples of the edge are
  // covered exactly once, the end points at most once, and nothing else.
  const Vec2 a{0.5f, 0.5f}, b{30.5f, 10.5f};
  const Vec2 below{15.5f, 5.5f + kFixedStep}, above{15.5f, 5.5f - kFixedStep};
  const RasterTarget target{40, 16, {}};
  for (const std::vector<Vec2>& first : vertex_orders(a, b, below)) {
    for (const std::vector<Vec2>& second : vertex_orders(b, a, above)) {
      std::vector<Vec2> both = first;
      both.insert(both.end(), second.begin(), second.end());
      const std::vector<Pixel> pixels = covered_pixels(draw(isa(), both, target));
      std::vector<Pixel> interior;
      for (int k = 1; k < 10; ++k)
        interior.push_back({3 * k, k});
      std::vector<Pixel> without_ends;
      for (const Pixel& p : pixels) {
        if (p != Pixel{0, 0} && p != Pixel{30, 10}) without_ends.push_back(p);
      }
      EXPECT_TRUE(covers_exactly(without_ends, interior));
      EXPECT_LE(pixels.size(), interior.size() + 2);
    }
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(FillRule, every_isa());

}  // namespace
}  // namespace edgewise::test
