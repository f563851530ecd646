// The vertex pipeline's math: 4x4 transforms, cameras, and the viewport mapping to screen space.
//
// Conventions:
// - Mat4 is stored row-major (m[row][column]) and acts on column vectors: p' = M p. A product
//   A * B applies B first.
// - View space is right-handed: the camera sits at the origin looking down -z, y up, x right.
// - Clip space follows D3D: a point is visible when -w <= x <= w, -w <= y <= w and 0 <= z <= w.
//   perspective() and orthographic() map the near plane to z = 0 and the far plane to z = w.
// - Screen space follows docs/design/rasterization.md, "Coordinates and snapping": origin at the
//   top-left corner, y down, pixel (i, j) sampled at (i + 0.5, j + 0.5). NDC (x/w, y/w) =
//   (-1, 1) lands on the top-left corner (0, 0) and (1, -1) on the bottom-right corner (width,
//   height).
//
// Thread safety: plain functions of their arguments; call them from any thread.
#pragma once

#include <cstdint>

#include "edgewise/vector.hpp"

namespace edgewise {

struct Mat4 {
  float m[4][4];  // m[row][column]
};

Mat4 identity();
Mat4 operator*(const Mat4& a, const Mat4& b);
Mat4 translate(const Vec3& offset);
Mat4 scale(const Vec3& factors);
// Rotation by `radians` about `axis` (need not be normalized; a zero axis gives the identity),
// counter-clockwise when the axis points at the viewer.
Mat4 rotate(const Vec3& axis, float radians);

// M (x, y, z, 1) and M p.
Vec4 transform(const Mat4& m, const Vec3& p);
Vec4 transform(const Mat4& m, const Vec4& p);

// View space to clip space. fovy_radians is the full vertical field of view, aspect is
// width / height; 0 < near < far. Clip w is the distance in front of the camera (-z_view).
Mat4 perspective(float fovy_radians, float aspect, float near, float far);
// The box [left, right] x [bottom, top] x [-near, -far] of view space to the clip-space cube;
// w stays 1.
Mat4 orthographic(float left, float right, float bottom, float top, float near, float far);
// World space to view space: the camera at `eye` looking at `target`, `up` pointing up on screen.
// `up` must not be parallel to target - eye.
Mat4 look_at(const Vec3& eye, const Vec3& target, const Vec3& up);

// The pixel rectangle [0, width) x [0, height) that NDC [-1, 1]^2 maps to;
// sizes 1 .. kMaxTargetSize (coverage.hpp).
struct Viewport {
  std::int32_t width = 0, height = 0;
};

// A vertex after the perspective divide and viewport mapping.
struct ScreenVertex {
  float x, y;   // pixels, docs/DESIGN.md's screen space
  float z;      // depth z/w, clamped to [0, 1]
  float inv_w;  // 1/w, interpolated linearly in screen space for perspective-correct attributes
};

// sx = (x/w + 1) / 2 * width, sy = (1 - y/w) / 2 * height, z = z/w, inv_w = 1/w.
// For a clip-space position with w > 0 (draw()'s clipping guarantees it).
ScreenVertex to_screen(const Vec4& clip, const Viewport& viewport);

}  // namespace edgewise
