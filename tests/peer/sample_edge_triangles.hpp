// Screen triangles for comparing per-sample coverage with another rasterizer. Every vertex lies
// on the 1/256 px snapping grid, so that snapping leaves it alone in both rasterizers, and most
// on the 1/16 px grid of the sample patterns, so that many edges pass exactly through sample
// positions, where the fill rule alone decides:
//  - random triangles 1 to 60 px across, vertices anywhere on the 1/256 px grid;
//  - axis-aligned right triangles and rectangles cut into two along a diagonal (a shared edge),
//    their sides on lines through samples of the pattern;
//  - right isosceles triangles with a vertex on a sample, whose 45-degree edge runs through
//    that sample of every pixel it crosses, alone or with their mirror image along that edge;
//  - closed fans around a vertex on a sample (shared edges, a shared vertex);
//  - small jittered meshes, each quad cut along a random diagonal (shared edges).
#pragma once

#include <array>
#include <cstdint>
#include <span>
#include <vector>

#include "edgewise/multisample.hpp"
#include "random.hpp"

namespace edgewise::test {

constexpr std::int32_t kFixedOne = 256;  // one pixel in snapped units (1/256 px)

// A point in screen space (y down), in 1/256 px.
struct FixedPoint {
  std::int32_t x, y;
};
using FixedTriangle = std::array<FixedPoint, 3>;

// `shapes` shapes of the kinds above (a shape is one to about fifty triangles), in drawing
// order, every vertex inside the width x height target (borders included), on lines through the
// samples of `pattern`.
std::vector<FixedTriangle> sample_edge_triangles(Random& random, std::int32_t width,
                                                 std::int32_t height,
                                                 std::span<const SampleOffset> pattern, int shapes);

}  // namespace edgewise::test
