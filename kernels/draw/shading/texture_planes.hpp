// The texture coordinates and derivatives every path shares, so that each ISA and the scalar
// reference hand the sampler the same queries (float32, one fixed order of operations, no fused
// multiply-add), as depth_plane.hpp does for depth.
//
// Per triangle, three planes over the snapped screen positions, set up in double from the
// vertex values and rounded to float once (value at vertex 0, x and y slopes):
//   perspective-correct (divides): s/w, t/w and q = 1/w;  otherwise s, t and q = 1.
// At pixel (px, py), with dx = (px + 0.5) - x0 and dy = (py + 0.5) - y0 exact in float:
//   plane(px, py) = (at_vertex + dy_slope * dy) + dx_slope * dx,
//   r = 1 / q(px, py),   s = (s/w)(px, py) * r,   t = (t/w)(px, py) * r
// (without division r = 1 and s, t are the planes' values). The derivatives:
//   TextureDerivatives::analytic: ds/dx = (dx_slope of s/w - s * dx_slope of q) * r, and likewise
//     for t and for y (without division, the planes' slopes);
//   TextureDerivatives::quad: differences of s and t within the pixel's 2x2 quad (draw.hpp).
// Division follows the shading kernels' rule: perspective-correct, every w within
// [kMinClipW, kMaxClipW], and not all three w equal (then the affine values are exact).
#pragma once

#include <cstdint>

#include "../../interpolation/screen_triangle.hpp"
#include "edgewise/draw.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/vector.hpp"

namespace edgewise::detail {

struct AttributePlane {
  float at_vertex = 0.0f, dx = 0.0f, dy = 0.0f;
};

struct TexturePlanes {
  AttributePlane s, t, q;
  float x0 = 0.0f, y0 = 0.0f;  // the first vertex, snapped
  bool divides = false;
};

inline bool texture_divides(Perspective perspective, const double w[3]) {
  bool usable = true;
  for (int i = 0; i < 3; ++i)
    usable = usable && w[i] >= kMinClipW && w[i] <= kMaxClipW;
  return perspective == Perspective::correct && usable && !(w[0] == w[1] && w[1] == w[2]);
}

// A plane through (p_i, f_i): slopes from the snapped positions in double, rounded once. A
// zero-area triangle covers nothing; its slopes are 0.
inline AttributePlane make_attribute_plane(const Vec2 p[3], const double f[3]) {
  const double x1 = static_cast<double>(p[1].x) - p[0].x, y1 = static_cast<double>(p[1].y) - p[0].y;
  const double x2 = static_cast<double>(p[2].x) - p[0].x, y2 = static_cast<double>(p[2].y) - p[0].y;
  const double area = x1 * y2 - y1 * x2;
  const double f1 = f[1] - f[0], f2 = f[2] - f[0];
  AttributePlane plane{static_cast<float>(f[0]), 0.0f, 0.0f};
  if (area != 0.0) {
    plane.dx = static_cast<float>((f1 * y2 - f2 * y1) / area);
    plane.dy = static_cast<float>((f2 * x1 - f1 * x2) / area);
  }
  return plane;
}

inline TexturePlanes make_texture_planes(const Vec2 p[3], const Vec2 uv[3], const double w[3],
                                         Perspective perspective) {
  TexturePlanes planes;
  planes.divides = texture_divides(perspective, w);
  double s[3], t[3], q[3];
  for (int i = 0; i < 3; ++i) {
    q[i] = planes.divides ? 1.0 / w[i] : 1.0;
    s[i] = static_cast<double>(uv[i].x) * q[i];
    t[i] = static_cast<double>(uv[i].y) * q[i];
  }
  planes.s = make_attribute_plane(p, s);
  planes.t = make_attribute_plane(p, t);
  planes.q = make_attribute_plane(p, q);
  planes.x0 = p[0].x;
  planes.y0 = p[0].y;
  return planes;
}

// The pixel center's offsets from the first vertex: exact (depth_plane.hpp).
inline float offset_x(const TexturePlanes& planes, std::int32_t px) {
  return (static_cast<float>(px) + 0.5f) - planes.x0;
}
inline float offset_y(const TexturePlanes& planes, std::int32_t py) {
  return (static_cast<float>(py) + 0.5f) - planes.y0;
}

inline float plane_value(const AttributePlane& plane, float dx, float dy) {
  return (plane.at_vertex + plane.dy * dy) + plane.dx * dx;
}

struct TexturePoint {
  float s, t, r;  // r = 1 / q, 1 without division
};

inline TexturePoint texture_point(const TexturePlanes& planes, std::int32_t px, std::int32_t py) {
  const float dx = offset_x(planes, px), dy = offset_y(planes, py);
  const float s = plane_value(planes.s, dx, dy), t = plane_value(planes.t, dx, dy);
  if (!planes.divides) return {s, t, 1.0f};
  const float r = 1.0f / plane_value(planes.q, dx, dy);
  return {s * r, t * r, r};
}

// The sampler's query at pixel (px, py).
inline TextureQuery texture_query(const TexturePlanes& planes, TextureDerivatives derivatives,
                                  std::int32_t px, std::int32_t py) {
  const TexturePoint here = texture_point(planes, px, py);
  TextureQuery query{here.s, here.t, 0, 0, 0, 0};
  if (derivatives == TextureDerivatives::quad) {
    const TexturePoint left = texture_point(planes, px & ~1, py);
    const TexturePoint right = texture_point(planes, px | 1, py);
    const TexturePoint top = texture_point(planes, px, py & ~1);
    const TexturePoint bottom = texture_point(planes, px, py | 1);
    query.dsdx = right.s - left.s;
    query.dtdx = right.t - left.t;
    query.dsdy = bottom.s - top.s;
    query.dtdy = bottom.t - top.t;
  } else if (!planes.divides) {
    query.dsdx = planes.s.dx;
    query.dtdx = planes.t.dx;
    query.dsdy = planes.s.dy;
    query.dtdy = planes.t.dy;
  } else {
    query.dsdx = (planes.s.dx - here.s * planes.q.dx) * here.r;
    query.dtdx = (planes.t.dx - here.t * planes.q.dx) * here.r;
    query.dsdy = (planes.s.dy - here.s * planes.q.dy) * here.r;
    query.dtdy = (planes.t.dy - here.t * planes.q.dy) * here.r;
  }
  return query;
}

}  // namespace edgewise::detail
