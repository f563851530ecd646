// Rectangles and boxes of the occlusion queries turned into ranges of samples with a depth that
// bounds what they hold (docs/design/occlusion.md, "Queries"). Shared by every ISA and the
// reference: the kernels only compare those ranges with the stored depths.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>

#include "edgewise/camera.hpp"
#include "edgewise/occlusion.hpp"
#include "../draw/vertex_stage/clip.hpp"
#include "occlusion_call.hpp"

namespace edgewise::detail {

// The samples of a view of width x height whose centres lie in the rectangle, with its depth;
// empty (outside) for a depth beyond 1. Throws std::invalid_argument, naming rectangle `index`,
// for a NaN or an inverted rectangle.
SampleRect rect_samples(const OcclusionRect& rect, std::int32_t width, std::int32_t height,
                        std::size_t index);

// rect_samples() without the throw: false for a rectangle it rejects, `out` then unspecified.
bool rect_sample_range(const OcclusionRect& rect, std::int32_t width, std::int32_t height,
                       SampleRect& out);

// A range of the view's samples as the range of blocks of `reduction` x `reduction` samples that
// hold them (non-negative, so plain division rounds down); an empty range stays as it is.
inline SampleRect sample_blocks(SampleRect samples, std::int32_t reduction) {
  if (reduction > 1 && samples.x0 <= samples.x1 && samples.y0 <= samples.y1) {
    samples.x0 /= reduction;
    samples.y0 /= reduction;
    samples.x1 /= reduction;
    samples.y1 /= reduction;
  }
  return samples;
}

enum class BoxReach : std::uint8_t {
  bounded,    // `samples` bounds what the box's faces cover, and the depth they get
  outside,    // every corner beyond one plane of the view volume
  unbounded,  // a corner that draw() would clip: the box counts as visible
};

struct BoxSamples {
  BoxReach reach = BoxReach::unbounded;
  SampleRect samples;
};

// Every coordinate finite, and min <= max on each axis: box_samples() takes it.
bool valid_box(const OcclusionBox& box);

// Corner k of the box: bit 0 picks max.x, bit 1 max.y, bit 2 max.z.
inline Vec3 box_corner(const OcclusionBox& box, int k) {
  return {(k & 1) ? box.max.x : box.min.x, (k & 2) ? box.max.y : box.min.y,
          (k & 4) ? box.max.z : box.min.z};
}

// The 24 triangles the six faces can be cut into (each face's quad by either diagonal, in either
// orientation of the cut): corners (a, b, c) of each, a the one the slopes are taken from.
struct FaceTriangle {
  int a, b, c;
};
inline constexpr auto kFaceTriangles = [] {
  // The faces as quads of corners, in order around each.
  constexpr int faces[6][4] = {{0, 2, 6, 4}, {1, 3, 7, 5}, {0, 1, 5, 4},
                               {2, 3, 7, 6}, {0, 1, 3, 2}, {4, 5, 7, 6}};
  std::array<FaceTriangle, 24> triangles{};
  for (int f = 0; f < 6; ++f) {
    for (int skip = 0; skip < 4; ++skip) {  // the corner left out
      triangles[4 * f + skip] = {faces[f][skip == 0 ? 1 : 0], faces[f][skip <= 1 ? 2 : 1],
                                 faces[f][skip <= 2 ? 3 : 2]};
    }
  }
  return triangles;
}();

// What box_samples() finds of a box whose corners are all inside the clipping planes: the bounds
// of its snapped corners and their least depth, and the largest |dz/dx| and |dz/dy| over
// kFaceTriangles (steepest_slopes() in query_bounds.cpp).
struct BoxExtent {
  float min_x, max_x, min_y, max_y, min_z;
  double slope_x, slope_y;
};

// The samples and depth bound of such a box (box_samples()'s last step).
BoxSamples bounded_box_samples(const BoxExtent& extent, const Viewport& viewport);

// Throws std::invalid_argument, naming box `index`, for a non-finite or inverted box.
BoxSamples box_samples(const OcclusionBox& box, const Mat4& to_clip, const Viewport& viewport,
                       const GuardBandPlanes& planes, std::size_t index);

}  // namespace edgewise::detail
