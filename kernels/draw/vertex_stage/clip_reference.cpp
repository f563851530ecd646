#include "clip_reference.hpp"

#include <algorithm>
#include <array>
#include <cmath>
#include <optional>

#include "edgewise/coverage.hpp"

namespace edgewise::reference {
namespace {

// A plane through the origin of clip space: the inside is a x + b y + c z + d w >= 0.
struct Plane {
  double a, b, c, d;
};

// The six clipping planes in clipping order, then the four sides of the frustum.
constexpr int kPlaneCount = 10;

std::array<Plane, kPlaneCount> planes_for(const Viewport& viewport) {
  // Screen x = (x/w + 1) width / 2 stays within [-G, G] when x/w is in
  // [-(1 + 2G/width), 2G/width - 1]; screen y = (1 - y/w) height / 2 likewise.
  const double band = kGuardBand - static_cast<double>(kGuardBandMargin);
  const double x_min = -(1.0 + 2.0 * band / viewport.width);
  const double x_max = 2.0 * band / viewport.width - 1.0;
  const double y_min = 1.0 - 2.0 * band / viewport.height;
  const double y_max = 1.0 + 2.0 * band / viewport.height;
  return {{
      {0, 0, 1, 0},       // near: z >= 0
      {0, 0, -1, 1},      // far: z <= w
      {1, 0, 0, -x_min},  // x >= x_min w
      {-1, 0, 0, x_max},  // x <= x_max w
      {0, 1, 0, -y_min},  // y >= y_min w
      {0, -1, 0, y_max},  // y <= y_max w
      {1, 0, 0, 1},       // left side: x >= -w
      {-1, 0, 0, 1},      // right side: x <= w
      {0, 1, 0, 1},       // bottom side: y >= -w
      {0, -1, 0, 1},      // top side: y <= w
  }};
}

double distance(const Plane& p, double x, double y, double z, double w) {
  return p.a * x + p.b * y + p.c * z + p.d * w;
}

double distance(const Plane& p, const ClipVertex& v) {
  return distance(p, v.x, v.y, v.z, v.w);
}

double scale(const Plane& p, const std::array<ClipVertex, 3>& triangle) {
  double largest = 0.0;
  for (const ClipVertex& v : triangle) {
    largest = std::max(largest, std::fabs(p.a * v.x) + std::fabs(p.b * v.y) + std::fabs(p.c * v.z) +
                                    std::fabs(p.d * v.w));
  }
  return largest;
}

ClipVertex widen(const Vec4& p, double b0, double b1, double b2) {
  return {p.x, p.y, p.z, p.w, b0, b1, b2};
}

// The point of segment a-b where the plane's distance is zero (da and db have opposite signs).
ClipVertex intersection(const ClipVertex& a, double da, const ClipVertex& b, double db) {
  const double t = da / (da - db);
  const auto mix = [t](double u, double v) { return u + t * (v - u); };
  return {mix(a.x, b.x),   mix(a.y, b.y),   mix(a.z, b.z),  mix(a.w, b.w),
          mix(a.b0, b.b0), mix(a.b1, b.b1), mix(a.b2, b.b2)};
}

// An input vertex (weights exactly one and zeros), as opposed to a computed intersection.
bool is_input(const ClipVertex& v) {
  return (v.b0 == 0) + (v.b1 == 0) + (v.b2 == 0) == 2;
}

}  // namespace

double plane_scale(int plane, const Vec4& p0, const Vec4& p1, const Vec4& p2,
                   const Viewport& viewport) {
  return scale(planes_for(viewport)[static_cast<std::size_t>(plane)],
               {widen(p0, 1, 0, 0), widen(p1, 0, 1, 0), widen(p2, 0, 0, 1)});
}

double plane_distance(int plane, double x, double y, double z, double w, const Viewport& viewport) {
  return distance(planes_for(viewport)[static_cast<std::size_t>(plane)], x, y, z, w);
}

namespace {

// Non-finite coordinates, or any beyond kMaxClipCoordinate, are errors.
std::optional<ClipStatus> bad_input(const Vec4& p0, const Vec4& p1, const Vec4& p2) {
  for (const Vec4& p : {p0, p1, p2}) {
    for (float c : {p.x, p.y, p.z, p.w}) {
      if (!std::isfinite(c)) return ClipStatus::error_non_finite;
    }
  }
  for (const Vec4& p : {p0, p1, p2}) {
    for (float c : {p.x, p.y, p.z, p.w}) {
      if (std::fabs(static_cast<double>(c)) > static_cast<double>(kMaxClipCoordinate)) {
        return ClipStatus::error_out_of_range;
      }
    }
  }
  return std::nullopt;
}

// The closest call a clipping decision made: a vertex's distance to a plane, scaled by the plane's
// scale for the triangle.
struct DecisionRecord {
  std::array<double, kPlaneCount> scales{};
  double* closest;

  void note(int p, double d) const {
    if (scales[p] > 0.0) *closest = std::min(*closest, std::fabs(d) / scales[p]);
  }
};

// Whether a vertex is outside one of the six clipping planes; nullopt when the triangle is
// rejected, all three vertices outside one plane of the frustum (near, far, a side).
std::optional<bool> needs_clipping(const std::array<ClipVertex, 3>& triangle,
                                   const std::array<Plane, kPlaneCount>& planes,
                                   const DecisionRecord& record) {
  bool clipping = false;
  for (int p = 0; p < kPlaneCount; ++p) {
    int outside = 0;
    for (const ClipVertex& v : triangle) {
      const double d = distance(planes[p], v);
      // Near, far and the sides compare input floats exactly, in float32 too: no tie there.
      if (p >= 2 && p < kClipPlaneCount) record.note(p, d);
      outside += d < 0.0;
    }
    const bool frustum_plane = p < 2 || p >= 6;
    if (frustum_plane && outside == 3) return std::nullopt;
    if (p < kClipPlaneCount && outside > 0) clipping = true;
  }
  return clipping;
}

// Sutherland-Hodgman: walk the polygon's edges; keep inside vertices, and add the intersection
// wherever an edge crosses the plane. Fewer than three vertices left: the triangle is outside.
bool clip_polygon(std::vector<ClipVertex>& polygon, const std::array<Plane, kPlaneCount>& planes,
                  const DecisionRecord& record) {
  for (int p = 0; p < kClipPlaneCount; ++p) {
    std::vector<ClipVertex> clipped;
    const std::size_t n = polygon.size();
    for (std::size_t i = 0; i < n; ++i) {
      const ClipVertex& current = polygon[i];
      const ClipVertex& next = polygon[(i + 1) % n];
      const double d_current = distance(planes[p], current);
      const double d_next = distance(planes[p], next);
      if (!is_input(current)) record.note(p, d_current);
      if (d_current >= 0.0) clipped.push_back(current);
      if ((d_current >= 0.0) != (d_next >= 0.0)) {
        clipped.push_back(intersection(current, d_current, next, d_next));
      }
    }
    polygon = std::move(clipped);
    if (polygon.size() < 3) return false;
  }
  return true;
}

// Inside the near and far planes w >= z >= 0; w = 0 only where the near plane meets the eye.
// A smaller positive w than float32 projects is out of range (clip.hpp, "Tiny w").
std::optional<ClipStatus> unprojectable(const std::vector<ClipVertex>& polygon) {
  for (const ClipVertex& v : polygon) {
    if (!(v.w > 0.0)) return ClipStatus::culled_degenerate;
    if (v.w < static_cast<double>(kMinProjectedW)) return ClipStatus::error_out_of_range;
  }
  return std::nullopt;
}

}  // namespace

ClippedPolygon clip_triangle(const Vec4& p0, const Vec4& p1, const Vec4& p2,
                             const Viewport& viewport) {
  ClippedPolygon result;
  if (const std::optional<ClipStatus> error = bad_input(p0, p1, p2)) {
    result.status = *error;
    return result;
  }
  const std::array<ClipVertex, 3> triangle = {widen(p0, 1, 0, 0), widen(p1, 0, 1, 0),
                                              widen(p2, 0, 0, 1)};
  const std::array<Plane, kPlaneCount> planes = planes_for(viewport);
  DecisionRecord record{{}, &result.closest_decision};
  for (int p = 0; p < kPlaneCount; ++p)
    record.scales[p] = scale(planes[p], triangle);
  const std::optional<bool> clipping = needs_clipping(triangle, planes, record);
  std::vector<ClipVertex> polygon(triangle.begin(), triangle.end());
  if (!clipping || (*clipping && !clip_polygon(polygon, planes, record))) {
    result.status = ClipStatus::outside;
    return result;
  }
  if (const std::optional<ClipStatus> status = unprojectable(polygon)) {
    result.status = *status;
    return result;
  }
  result.vertices = std::move(polygon);
  result.status = *clipping ? ClipStatus::clipped : ClipStatus::inside;
  return result;
}

}  // namespace edgewise::reference
