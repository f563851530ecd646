// A view as geometry: two screen-filling triangles that draw() maps to exactly the view's
// projective mapping, so that rendered images can be scored against the same ground truth as
// the sampler's query streams.
//
// Perspective-correct interpolation divides screen-linear planes of s/w and t/w by the plane of
// 1/w. The view's mapping is s = (s_row . (x, y, 1)) / (w_row . (x, y, 1)), so giving each
// corner clip-space w proportional to 1 / (w_row . (x, y, 1)) and the uv the view maps that
// corner to reproduces it at every pixel, up to float32 rounding.
#pragma once

#include <vector>

#include "edgewise/camera.hpp"
#include "edgewise/draw.hpp"
#include "texture_scene/texture_view.hpp"

namespace edgewise::texture_scene {

struct ViewMesh {
  std::vector<Vec3> positions;  // (ndc_x w, ndc_y w, w) per corner
  std::vector<Vec2> uvs;
  // (x, y, z) to clip space (x, y, z / 2, z): depth 1/2 everywhere, w = z.
  Mat4 transform;

  DrawMesh mesh() const { return {positions, {}, {}, {}, uvs}; }
};

ViewMesh view_mesh(const TextureView& view);

}  // namespace edgewise::texture_scene
