// What the 3D pipeline hands the rasterizer: clip-space triangles clipped one by one, their
// polygons fanned into triangles and mapped to the screen.
#pragma once

#include <cstdint>
#include <span>
#include <vector>

#include "edgewise/camera.hpp"
#include "draw/vertex_stage/clip.hpp"

namespace edgewise::test {

struct ClippedMesh {
  std::vector<ClippedPolygon> polygons;  // one per input triangle
  std::vector<ScreenVertex> screen;      // three per output triangle
  std::vector<Vec2> positions;           // screen x, y of `screen`, for rasterize()
  std::vector<std::uint32_t> source;     // the input triangle of each output triangle
};

// Triangle t is clip-space vertices indices[3t .. 3t+2].
ClippedMesh clip_mesh(std::span<const Vec4> vertices, std::span<const std::uint32_t> indices,
                      const Viewport& viewport);

}  // namespace edgewise::test
