// Rectangles and boxes to ranges of samples and a depth bound (docs/design/occlusion.md,
// "Queries").
#include "query_bounds.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <iterator>
#include <limits>
#include <stdexcept>
#include <string>

#include "../draw/vertex_stage/vertex_stage.hpp"

namespace edgewise::detail {
namespace {

// The sample indices whose centres i + 0.5 lie in [low, high], clamped to 0 .. size - 1 (in
// double: a float bound may be infinite or beyond the int32 range). Clamped to integers first,
// then rounded by a conversion: ceil and floor commute with clamping to integer bounds, and this
// code is built for the baseline ISA, where std::ceil is a library call.
void sample_range(double low, double high, std::int32_t size, std::int32_t& first,
                  std::int32_t& last) {
  const double from = std::clamp(low - 0.5, 0.0, static_cast<double>(size));
  const double to = std::clamp(high - 0.5, -1.0, static_cast<double>(size - 1));
  first = static_cast<std::int32_t>(from);  // toward zero: floor for from >= 0
  if (static_cast<double>(first) < from) ++first;
  last = static_cast<std::int32_t>(to);  // toward zero: ceil for to < 0
  if (static_cast<double>(last) > to) --last;
}

// The largest float not above `value` (> 0): the nearest, or, when that lies above, the float
// whose bits are one less (it is then positive), without a call to std::nextafter.
float float_below(double value) {
  const float f = static_cast<float>(value);
  return static_cast<double>(f) > value ? std::bit_cast<float>(std::bit_cast<std::uint32_t>(f) - 1u)
                                        : f;
}

// The largest |dz/dx| and |dz/dy| of every triangle a face can be cut into (kFaceTriangles), from
// the snapped corners as make_depth_plane() takes them, with one reciprocal per triangle in place
// of its two divisions: within a few 2^-53 of the set-up's values before they are rounded to
// float, well inside the margin's factor of two.
void steepest_slopes(const Vec2 (&p)[8], const float (&z)[8], double& sx, double& sy) {
  sx = 0.0;
  sy = 0.0;
  for (const FaceTriangle& t : kFaceTriangles) {
    const double x1 = static_cast<double>(p[t.b].x) - p[t.a].x,
                 y1 = static_cast<double>(p[t.b].y) - p[t.a].y;
    const double x2 = static_cast<double>(p[t.c].x) - p[t.a].x,
                 y2 = static_cast<double>(p[t.c].y) - p[t.a].y;
    const double z1 = static_cast<double>(z[t.b]) - z[t.a],
                 z2 = static_cast<double>(z[t.c]) - z[t.a];
    const double area = x1 * y2 - y1 * x2;
    if (area == 0.0) continue;  // covers nothing
    const double inverse = 1.0 / std::fabs(area);
    sx = std::max(sx, std::fabs(z1 * y2 - z2 * y1) * inverse);
    sy = std::max(sy, std::fabs(z2 * x1 - z1 * x2) * inverse);
  }
}

// Every coordinate of the box finite.
bool finite_box(const OcclusionBox& box) {
  const float coordinates[6] = {box.min.x, box.min.y, box.min.z, box.max.x, box.max.y, box.max.z};
  return std::all_of(std::begin(coordinates), std::end(coordinates),
                     [](float c) { return std::isfinite(c); });
}

}  // namespace

bool rect_sample_range(const OcclusionRect& rect, std::int32_t width, std::int32_t height,
                       SampleRect& out) {
  if (std::isnan(rect.x0) || std::isnan(rect.y0) || std::isnan(rect.x1) || std::isnan(rect.y1) ||
      std::isnan(rect.depth) || rect.x0 > rect.x1 || rect.y0 > rect.y1) {
    return false;
  }
  out = SampleRect{};
  if (rect.depth > 1.0f) return true;  // beyond the far plane: nothing drawn
  sample_range(rect.x0, rect.x1, width, out.x0, out.x1);
  sample_range(rect.y0, rect.y1, height, out.y0, out.y1);
  out.depth = rect.depth;
  return true;
}

SampleRect rect_samples(const OcclusionRect& rect, std::int32_t width, std::int32_t height,
                        std::size_t index) {
  SampleRect out;
  if (rect_sample_range(rect, width, height, out)) return out;
  const bool has_nan = std::isnan(rect.x0) || std::isnan(rect.y0) || std::isnan(rect.x1) ||
                       std::isnan(rect.y1) || std::isnan(rect.depth);
  throw std::invalid_argument(
      "test_rects: rectangle " + std::to_string(index) + " " +
      (has_nan ? "has a NaN coordinate or depth" : "is inverted (x0 > x1 or y0 > y1)"));
}

bool valid_box(const OcclusionBox& box) {
  return finite_box(box) && box.min.x <= box.max.x && box.min.y <= box.max.y &&
         box.min.z <= box.max.z;
}

// A face's sample at depth formula value v = (z0 + dzdy dy) + dzdx dx, every operation rounded
// to float (depth_plane.hpp), lies within about 4 u M of the plane through the snapped corners,
// M = |z0| + |dzdy| |dy| + |dzdx| |dx| and u = 2^-24: one rounding per operation (3 u M) and the
// slopes' own rounding to float (u each term). On a sample inside the triangle the plane is a
// mean of the corners' depths, so no less than the smallest. So every sample a face covers gets at
// least min z - 8 u M, with |z0| <= 1 (depths are clamped to [0, 1]) and |dx|, |dy| at most the
// box's screen extent (a covered sample and the first corner both lie in it); clamping only
// raises a value. The steepest slopes of all 24 triangles the faces can be cut into make the
// bound hold for every triangulation and vertex order of the faces.
BoxSamples bounded_box_samples(const BoxExtent& extent, const Viewport& viewport) {
  const double reach = 1.0 + extent.slope_x * (static_cast<double>(extent.max_x) - extent.min_x) +
                       extent.slope_y * (static_cast<double>(extent.max_y) - extent.min_y);
  const double lowest = static_cast<double>(extent.min_z) - 8.0 * 0x1p-24 * reach;
  BoxSamples out;
  out.reach = BoxReach::bounded;
  sample_range(extent.min_x, extent.max_x, viewport.width, out.samples.x0, out.samples.x1);
  sample_range(extent.min_y, extent.max_y, viewport.height, out.samples.y0, out.samples.y1);
  out.samples.depth = lowest > 0.0 ? float_below(lowest) : 0.0f;
  if (out.samples.x0 > out.samples.x1 || out.samples.y0 > out.samples.y1)
    out.reach = BoxReach::outside;
  return out;
}

BoxSamples box_samples(const OcclusionBox& box, const Mat4& to_clip, const Viewport& viewport,
                       const GuardBandPlanes& planes, std::size_t index) {
  if (!valid_box(box)) {
    throw std::invalid_argument(
        "test_boxes: box " + std::to_string(index) +
        (finite_box(box) ? " is inverted (min > max on an axis)" : " has a non-finite coordinate"));
  }
  BoxSamples out;
  Vec4 clip[8];
  std::uint16_t outside_all = 0xFFFF;
  bool all_checked = true, all_inside = true;
  for (int k = 0; k < 8; ++k) {
    clip[k] = transform(to_clip, box_corner(box, k));
    const ClipClass c = classify_clip_vertex(clip[k], planes);
    outside_all &= c.outside_frustum;
    all_checked = all_checked && c.checked;
    all_inside = all_inside && c.inside;
  }
  if (all_checked && outside_all != 0) {
    out.reach = BoxReach::outside;
    return out;
  }
  if (!all_inside) return out;  // unbounded
  Vec2 p[8];
  float z[8];
  BoxExtent extent{std::numeric_limits<float>::infinity(),
                   -std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::infinity(),
                   -std::numeric_limits<float>::infinity(),
                   std::numeric_limits<float>::infinity(),
                   0.0,
                   0.0};
  for (int k = 0; k < 8; ++k) {
    const ScreenVertex s = to_screen(clip[k], viewport);
    p[k] = {snap(s.x), snap(s.y)};
    z[k] = s.z;
    extent.min_x = std::min(extent.min_x, p[k].x);
    extent.max_x = std::max(extent.max_x, p[k].x);
    extent.min_y = std::min(extent.min_y, p[k].y);
    extent.max_y = std::max(extent.max_y, p[k].y);
    extent.min_z = std::min(extent.min_z, z[k]);
  }
  steepest_slopes(p, z, extent.slope_x, extent.slope_y);
  return bounded_box_samples(extent, viewport);
}

}  // namespace edgewise::detail
