// Random occluders and queries for the occlusion tests.
#pragma once

#include <cstdint>
#include <vector>

#include "edgewise/occlusion.hpp"
#include "occlusion/box_faces.hpp"
#include "random.hpp"

namespace edgewise::test {

// A tilted backdrop over the view, then triangles in clip space (w = 1), each at its own tilted
// depth within [0, 1], of sizes from a pixel to the whole view; some reach past the view's sides.
struct OccluderSoup {
  std::vector<Vec3> positions;
  OcclusionMesh mesh() const { return {positions, {}}; }
};
OccluderSoup random_occluders(Random& random, int triangles);

// Rectangles of every size from a sample to beyond the view (width x height), some with infinite
// sides, at depths in [-0.1, 1.1].
std::vector<OcclusionRect> random_rects(Random& random, int count, std::int32_t width,
                                        std::int32_t height);

// A camera looking into a scene of boxes: perspective or orthographic.
Mat4 random_camera(Random& random, float aspect);

// Boxes around the origin of the camera's scene: small and large, flat and long, some crossing
// the near plane or the view's sides.
std::vector<OcclusionBox> random_boxes(Random& random, int count);

}  // namespace edgewise::test
