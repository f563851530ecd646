// The depth formula every path shares, so that depth-test outcomes are identical on every ISA and
// in the scalar reference: z/w is interpolated linearly in screen space from the snapped vertex
// positions, in float32, with one fixed order of operations.
//
//   depth(px, py) = clamp((z0 + dzdy * dy) + dzdx * dx, 0, 1),
//   dx = (px + 0.5) - x0,  dy = (py + 0.5) - y0   for pixel (px, py),
//
// each operation rounded to float32 (no fused multiply-add), where (x0, y0) is the triangle's
// first snapped vertex and z0 its depth. dx and dy are exact in float: snapped coordinates are
// multiples of 2^-8 below 2^15 in magnitude, so their differences with pixel centers need at
// most 24 significant bits. The plane's slopes come from the snapped positions in double
// (the cross products are exact: 25-bit differences) and are rounded to float once.
//
// A sample of a multisample pattern (edgewise/multisample.hpp), at (sx, sy) / 16 px from the
// centre, takes the same formula at its own position:
//
//   dx = ((px + 0.5) + sx / 16) - x0,  dy = ((py + 0.5) + sy / 16) - y0,
//
// again exact (multiples of 2^-8 below 2^16 in magnitude); offset (0, 0) is the centre's formula.
#pragma once

#include <cmath>
#include <cstdint>

#include "edgewise/vector.hpp"

namespace edgewise::detail {

struct DepthPlane {
  float z0, dzdx, dzdy;
  float x0, y0;  // the first vertex, snapped
};

inline DepthPlane make_depth_plane(const Vec2 p[3], const float z[3]) {
  const double x1 = static_cast<double>(p[1].x) - p[0].x, y1 = static_cast<double>(p[1].y) - p[0].y;
  const double x2 = static_cast<double>(p[2].x) - p[0].x, y2 = static_cast<double>(p[2].y) - p[0].y;
  const double z1 = static_cast<double>(z[1]) - z[0], z2 = static_cast<double>(z[2]) - z[0];
  const double area = x1 * y2 - y1 * x2;
  DepthPlane plane{z[0], 0.0f, 0.0f, p[0].x, p[0].y};
  if (area != 0.0) {  // zero-area triangles cover nothing; keep the plane finite anyway
    plane.dzdx = static_cast<float>((z1 * y2 - z2 * y1) / area);
    plane.dzdy = static_cast<float>((z2 * x1 - z1 * x2) / area);
  }
  return plane;
}

inline float clamp_depth(float z) {
  return z > 0.0f ? (z < 1.0f ? z : 1.0f) : 0.0f;
}

// A sample offset's sixteenths of a pixel as a float (exact).
inline float sixteenths(std::int32_t offset) {
  return static_cast<float>(offset) * 0.0625f;
}

// The depth at row py's start, before the dx term: z0 + dzdy * dy; for the samples offset by
// sy / 16 px when sy is given.
inline float depth_row_base(const DepthPlane& plane, std::int32_t py, std::int32_t sy = 0) {
  const float dy = ((static_cast<float>(py) + 0.5f) + sixteenths(sy)) - plane.y0;
  return plane.z0 + plane.dzdy * dy;
}

// The depth at pixel (px, py)'s centre, or at its sample offset by (sx, sy) / 16 px.
inline float depth_at(const DepthPlane& plane, std::int32_t px, std::int32_t py,
                      std::int32_t sx = 0, std::int32_t sy = 0) {
  const float dx = ((static_cast<float>(px) + 0.5f) + sixteenths(sx)) - plane.x0;
  return clamp_depth(depth_row_base(plane, py, sy) + plane.dzdx * dx);
}

// On a target reduced k times on each axis (k = 2 or 4), whose pixel (X, Y) stands for the
// view's samples (kX + i, kY + j), 0 <= i, j < k: the plane whose depth_at(X, Y) is the largest
// (`farthest`) or the least of depth_at() of `plane` over those samples. Each of the formula's
// roundings keeps the order of its operands, so the computed depth is monotone in dx and in dy
// and its extremes lie at the corner the slopes' signs choose, sample (i, j). That sample's
// depth is computed bit for bit: with x0' = (x0 - (i + 0.5) + k / 2) / k and dzdx' = k dzdx,
// dx' = (X + 0.5) - x0' is exactly the view's dx / k (x0 is a multiple of 2^-8 below 2^15, so
// x0' and dx' have at most 24 significant bits, and k is a power of two), and dzdx' dx' rounds
// the same product as the view's dzdx dx; the same for y. Slopes that k times over would not be
// finite give the far plane (depth 1 everywhere: nothing behind it is occluded).
inline DepthPlane block_depth_plane(const DepthPlane& plane, std::int32_t k, bool farthest) {
  const float kf = static_cast<float>(k);
  const float dzdx = plane.dzdx * kf, dzdy = plane.dzdy * kf;
  if (std::isfinite(plane.dzdx) && std::isfinite(plane.dzdy) &&
      !(std::isfinite(dzdx) && std::isfinite(dzdy))) {
    return {1.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  }
  const double i = (plane.dzdx > 0.0f) == farthest ? k - 1 : 0;
  const double j = (plane.dzdy > 0.0f) == farthest ? k - 1 : 0;
  const double half = 0.5 * k;
  return {plane.z0, dzdx, dzdy,
          static_cast<float>((static_cast<double>(plane.x0) - (i + 0.5) + half) / k),
          static_cast<float>((static_cast<double>(plane.y0) - (j + 0.5) + half) / k)};
}

}  // namespace edgewise::detail
