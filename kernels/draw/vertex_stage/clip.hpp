// Homogeneous clipping of one clip-space triangle (camera.hpp's conventions: visible when
// -w <= x <= w, -w <= y <= w, 0 <= z <= w) before the perspective divide.
//
// The triangle is clipped (Sutherland-Hodgman, in this order) against
//   near   z >= 0                  so that every output vertex has w > 0 (see below),
//   far    z <= w,
//   the guard band  x_min w <= x <= x_max w,  y_min w <= y <= y_max w  (GuardBandPlanes),
// and not against the sides x = +-w, y = +-w: the rasterizer's scissor trims those for free.
// A triangle entirely outside one plane of the view frustum (near, far or a side) is rejected.
//
// Behind the camera: with perspective() and near > 0, z >= 0 means w >= near > 0, so the near
// plane removes everything at or behind the eye (w <= 0) and a triangle crossing w = 0 keeps
// exactly its visible part. orthographic() keeps w = 1. A projection whose z = 0 plane passes
// through the eye can leave a vertex at w = 0: such triangles are culled_degenerate.
//
// Tiny w: a vertex kept at 0 < w < kMinProjectedW is an error (error_out_of_range), not a
// degenerate triangle: exact arithmetic projects it to a definite point, but float32 cannot
// (1/w overflows below 2^-128, and the guard band's rounding bound assumes normal floats).
// Small positions are no error in themselves: under a camera that keeps w normal (w = 1 for
// orthographic()), a triangle of 1e-40 snaps to one point and is culled for its zero area.
//
// Crack-free: two triangles sharing an edge compute bit-identical points where that edge crosses
// a plane (clip.cpp says how), so a mesh stays watertight after clipping.
//
// Thread safety: plain functions of their arguments; call them from any thread.
#pragma once

#include <cstdint>

#include "edgewise/camera.hpp"
#include "edgewise/vector.hpp"
#include "edgewise/names.hpp"

namespace edgewise {

// Clipped vertices land at least this far inside the rasterizer's guard band, in pixels: the
// float32 rounding of clipping, to_screen() and snapping stays below 0.015 px (clip.cpp derives
// it), and a margin under 0.5 px removes no pixel center of the largest target.
inline constexpr float kGuardBandMargin = 1.0f / 16.0f;

// Inputs with a coordinate beyond this magnitude are rejected, so that no intermediate of the
// clipper overflows float32.
inline constexpr float kMaxClipCoordinate = 0x1p64f;

// The smallest w a vertex is projected from: from it on, w, 1/w and the guard band's products
// (x_max w, ...; every bound is at least 1/2 in magnitude) are normal floats, whose roundings are
// relative, as the guard band's bound in clip.cpp assumes. A vertex kept by the clipper with
// 0 < w below it is an error (see "Tiny w" above).
inline constexpr float kMinProjectedW = 0x1p-125f;

// The guard band as planes through the eye: a vertex with w > 0 maps to screen coordinates in
// [-(kGuardBand - kGuardBandMargin), kGuardBand - kGuardBandMargin] on each axis when
// x_min w <= x <= x_max w and y_min w <= y <= y_max w. From sx = (x/w + 1) width / 2 and
// sy = (1 - y/w) height / 2 with G = kGuardBand - kGuardBandMargin:
//   x_min = -(1 + 2G/width),  x_max = 2G/width - 1,  y_min = 1 - 2G/height,  y_max = 1 + 2G/height
// (asymmetric: the viewport maps -1 .. 1 to 0 .. width, not around 0).
struct GuardBandPlanes {
  float x_min, x_max, y_min, y_max;
};
// Throws std::invalid_argument for a size outside 1 .. kMaxTargetSize.
GuardBandPlanes guard_band_planes(const Viewport& viewport);

enum class ClipStatus : std::uint8_t {
  inside,              // nothing to clip: the original triangle, bit for bit
  clipped,             // a new convex polygon
  outside,             // entirely outside a frustum plane, or clipped away: nothing to draw
  culled_degenerate,   // a clipped vertex at w <= 0 (see above), or a polygon that float32 sees
                       // as a line (its vertices alternate sides of a plane): nothing to draw
  error_non_finite,    // a NaN or infinite coordinate: nothing to draw
  error_out_of_range,  // a coordinate beyond kMaxClipCoordinate, or a vertex kept at
                       // 0 < w < kMinProjectedW: nothing to draw
};

// Near, far and the four guard-band planes: each adds at most one vertex to a convex polygon.
inline constexpr int kClipPlaneCount = 6;
inline constexpr int kMaxClipVertices = 3 + kClipPlaneCount;

struct ClipVertex {
  Vec4 position;  // clip space; w >= kMinProjectedW
  // Weights of the original vertices 0, 1, 2: position = b0 p0 + b1 p1 + b2 p2 (up to rounding).
  // Attributes are linear in clip space, so a vertex attribute a interpolates the same way:
  // a = b0 a0 + b1 a1 + b2 a2.
  float b0, b1, b2;
};

// The visible part of a triangle as a convex polygon, in the original winding. It is drawn as a
// fan: triangle k (0 <= k < triangle_count()) is vertices (0, k + 1, k + 2).
struct ClippedPolygon {
  ClipStatus status = ClipStatus::outside;
  std::uint8_t count = 0;  // 0, or 3 .. kMaxClipVertices
  ClipVertex vertices[kMaxClipVertices];

  int triangle_count() const { return count >= 3 ? count - 2 : 0; }
};

ClippedPolygon clip_triangle(const Vec4& p0, const Vec4& p1, const Vec4& p2,
                             const GuardBandPlanes& planes);

// What clip_triangle() concludes from one vertex alone, so that callers classify each vertex once
// instead of clipping every triangle. For a finite vertex within kMaxClipCoordinate (`checked`):
// `outside_frustum` has a bit per view-frustum plane (near, far, the four sides) the vertex is
// beyond, and `inside` says it is at w >= kMinProjectedW inside every plane. When all three
// vertices of a triangle are checked, clip_triangle() returns ClipStatus::outside if their
// outside_frustum bits share a plane, and the triangle unchanged as ClipStatus::inside if all are
// inside. A vertex at 0 < w < kMinProjectedW is not inside: clip_triangle() decides its triangle,
// an error unless clipping removes that vertex.
struct ClipClass {
  std::uint16_t outside_frustum = 0;
  bool inside = false;
  bool checked = false;
};
ClipClass classify_clip_vertex(const Vec4& p, const GuardBandPlanes& planes);

// Names of the values (names.hpp).
std::string_view name_of(ClipStatus value);
template <>
std::span<const ClipStatus> values_of<ClipStatus>();

}  // namespace edgewise
