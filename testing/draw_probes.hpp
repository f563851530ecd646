// Small draw() set-ups that the atlas's studies and the stability tests share: a transform that
// takes clip w from the vertex, and whether a depth encoding resolves two surfaces.
#pragma once

#include <cmath>
#include <cstdint>
#include <numbers>
#include <vector>

#include "edgewise/edgewise.hpp"

namespace edgewise::probes {

// Clip space from "object" positions (x, y, w): w' = w and z' = w / 2, so every depth is 1/2
// (draw with the depth test off) and a vertex at screen position (sx, sy) of a width x height
// target is (x_ndc w, y_ndc w, w) with x_ndc = 2 sx / width - 1, y_ndc = 1 - 2 sy / height.
inline Mat4 clip_from_xyw() {
  Mat4 m{};
  m.m[0][0] = 1.0f;
  m.m[1][1] = 1.0f;
  m.m[2][2] = 0.5f;
  m.m[3][2] = 1.0f;
  return m;
}

// The position clip_from_xyw() takes for a vertex at screen point (sx, sy) of a width x height
// target with clip w: exact when the sizes and w are powers of two and sx, sy lie on the 1/256
// grid.
inline Vec3 xyw_position(float sx, float sy, float w, std::int32_t width, std::int32_t height) {
  const float x_ndc = sx * (2.0f / static_cast<float>(width)) - 1.0f;
  const float y_ndc = 1.0f - sy * (2.0f / static_cast<float>(height));
  return {x_ndc * w, y_ndc * w, w};
}

// perspective() with z' = w - z: z'/w = 1 - z/w, 1 at the near plane and 0 at the far one.
inline Mat4 reversed_depth(Mat4 m) {
  for (int c = 0; c < 4; ++c)
    m.m[2][c] = m.m[3][c] - m.m[2][c];
  return m;
}

// Whether the nearer of two squares facing the camera (60-degree field of view, both wider than
// the view), at view distances near_plane < far_plane and drawn second, wins at every pixel of
// a size x size target: z/w with `less`, or with `reverse` reversed z/w with `greater` and the
// depth cleared to 0.
inline bool nearer_plane_wins(bool reverse, float near, float far, float near_plane,
                              float far_plane, std::int32_t size) {
  constexpr float kFovy = std::numbers::pi_v<float> / 3.0f;
  Framebuffer target(size, size);
  target.clear({0, 0, 0, 1}, reverse ? 0.0f : 1.0f);
  DrawOptions options;
  const Mat4 projection = perspective(kFovy, 1.0f, near, far);
  options.transform = reverse ? reversed_depth(projection) : projection;
  options.depth_test = reverse ? DepthTest::greater : DepthTest::less;
  options.threads = 1;
  // The farther one first in red, the nearer second in green (told apart by order, not by
  // distance: the two may round to the same float).
  for (const bool second : {false, true}) {
    const float distance = second ? near_plane : far_plane;
    const float half = 2.0f * distance * std::tan(kFovy / 2.0f);
    const std::vector<Vec3> positions = {{-half, -half, -distance}, {half, -half, -distance},
                                         {half, half, -distance},   {-half, -half, -distance},
                                         {half, half, -distance},   {-half, half, -distance}};
    const Vec4 colour = second ? Vec4{0, 1, 0, 1} : Vec4{1, 0, 0, 1};
    const std::vector<Vec4> colours(positions.size(), colour);
    DrawMesh mesh;
    mesh.positions = positions;
    mesh.colors = colours;
    draw(target, mesh, options);
  }
  for (std::int32_t y = 0; y < size; ++y) {
    for (std::int32_t x = 0; x < size; ++x) {
      if ((target.color(x, y) & 0xFFFFu) != 0xFF00u) return false;  // red 0, green 255
    }
  }
  return true;
}

}  // namespace edgewise::probes
