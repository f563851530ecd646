#include "scene/polygon_triangulation.hpp"

#include <cmath>
#include <numeric>

namespace edgewise::scene {
namespace {

struct Point2 {
  double u, v;
};

// Twice the signed area of (a, b, c): positive when the three turn counter-clockwise.
double turn(Point2 a, Point2 b, Point2 c) {
  return (b.u - a.u) * (c.v - a.v) - (b.v - a.v) * (c.u - a.u);
}

bool same_point(Point2 a, Point2 b) {
  return a.u == b.u && a.v == b.v;
}

// The corners projected onto the coordinate plane most facing the Newell normal, mirrored where
// needed so that the polygon turns counter-clockwise. Empty when the normal is zero or not
// finite (no plane to work in).
std::vector<Point2> project_counter_clockwise(std::span<const Vec3> corners) {
  const std::size_t n = corners.size();
  // Each Newell component is twice the polygon's signed area projected on that axis's plane.
  double nx = 0, ny = 0, nz = 0;
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 a = corners[i], b = corners[(i + 1) % n];
    nx += (double(a.y) - b.y) * (double(a.z) + b.z);
    ny += (double(a.z) - b.z) * (double(a.x) + b.x);
    nz += (double(a.x) - b.x) * (double(a.y) + b.y);
  }
  const double ax = std::fabs(nx), ay = std::fabs(ny), az = std::fabs(nz);
  const int axis = (ax >= ay && ax >= az) ? 0 : (ay >= az ? 1 : 2);
  const double area = axis == 0 ? nx : (axis == 1 ? ny : nz);
  if (!(area != 0) || !std::isfinite(area)) return {};
  const double mirror = area > 0 ? 1.0 : -1.0;

  std::vector<Point2> points(n);
  for (std::size_t i = 0; i < n; ++i) {
    const Vec3 c = corners[i];
    // (y, z), (z, x), (x, y): the orders in which the Newell components above measure area.
    switch (axis) {
      case 0:
        points[i] = {c.y, mirror * c.z};
        break;
      case 1:
        points[i] = {c.z, mirror * c.x};
        break;
      default:
        points[i] = {c.x, mirror * c.y};
        break;
    }
  }
  return points;
}

// Whether (a, b, c), a convex corner, has no other remaining corner inside or on it. Corners at
// the same place as one of a, b, c (a polygon touching itself) do not block the ear.
bool is_ear(const std::vector<Point2>& points, const std::vector<std::uint32_t>& remaining,
            std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  const Point2 pa = points[a], pb = points[b], pc = points[c];
  if (!(turn(pa, pb, pc) > 0)) return false;
  for (const std::uint32_t other : remaining) {
    if (other == a || other == b || other == c) continue;
    const Point2 p = points[other];
    if (same_point(p, pa) || same_point(p, pb) || same_point(p, pc)) continue;
    if (turn(pa, pb, p) >= 0 && turn(pb, pc, p) >= 0 && turn(pc, pa, p) >= 0) return false;
  }
  return true;
}

}  // namespace

void triangulate_polygon(std::span<const Vec3> corners, std::vector<std::uint32_t>& triangles) {
  const std::size_t n = corners.size();
  if (n < 3) return;
  std::vector<std::uint32_t> remaining(n);
  std::iota(remaining.begin(), remaining.end(), 0u);

  const std::vector<Point2> points =
      n > 3 ? project_counter_clockwise(corners) : std::vector<Point2>();
  if (!points.empty()) {
    // Walk around the polygon cutting off ears; a full lap without one means there is none.
    std::size_t position = 0;
    std::size_t laps_without_ear = 0;
    while (remaining.size() > 3 && laps_without_ear < remaining.size()) {
      const std::size_t m = remaining.size();
      position %= m;
      const std::uint32_t a = remaining[(position + m - 1) % m];
      const std::uint32_t b = remaining[position];
      const std::uint32_t c = remaining[(position + 1) % m];
      if (is_ear(points, remaining, a, b, c)) {
        triangles.insert(triangles.end(), {a, b, c});
        remaining.erase(remaining.begin() + static_cast<std::ptrdiff_t>(position));
        laps_without_ear = 0;
      } else {
        ++position;
        ++laps_without_ear;
      }
    }
  }
  // What is left: a triangle, or a polygon without ears split as a fan.
  for (std::size_t k = 1; k + 1 < remaining.size(); ++k) {
    triangles.insert(triangles.end(), {remaining[0], remaining[k], remaining[k + 1]});
  }
}

}  // namespace edgewise::scene
