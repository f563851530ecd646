// Ear clipping: n - 2 triangles that tile the polygon exactly and keep its winding, for convex
// and concave polygons in any plane, starting from any corner; no crash on degenerate input.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <limits>

#include "mesh_checks.hpp"
#include "scene/polygon_triangulation.hpp"

namespace edgewise::scene::test {
namespace {

using Polygon2 = std::vector<Vec2>;

double signed_area(const Polygon2& polygon) {
  double twice = 0;
  for (std::size_t i = 0; i < polygon.size(); ++i) {
    const Vec2 a = polygon[i], b = polygon[(i + 1) % polygon.size()];
    twice += double(a.x) * b.y - double(b.x) * a.y;
  }
  return twice / 2;
}

// Even-odd rule; the test points are triangle centroids, never on the outline.
bool inside(const Polygon2& polygon, double x, double y) {
  bool in = false;
  for (std::size_t i = 0, j = polygon.size() - 1; i < polygon.size(); j = i++) {
    const Vec2 a = polygon[i], b = polygon[j];
    if ((a.y > y) != (b.y > y) && x < (b.x - a.x) * (y - a.y) / (double(b.y) - a.y) + a.x) {
      in = !in;
    }
  }
  return in;
}

Polygon2 rotated_start(const Polygon2& polygon, std::size_t start) {
  Polygon2 result(polygon.begin() + static_cast<std::ptrdiff_t>(start), polygon.end());
  result.insert(result.end(), polygon.begin(),
                polygon.begin() + static_cast<std::ptrdiff_t>(start));
  return result;
}

// The polygon in the plane z = 0, triangulated: checks the count, that each triangle winds like
// the polygon, that the areas add up to the polygon's, and that each triangle lies inside it.
// Small integer coordinates: every area below is exact in double.
void expect_tiles_exactly(const Polygon2& polygon) {
  std::vector<Vec3> corners;
  for (const Vec2& p : polygon)
    corners.push_back({p.x, p.y, 0.0f});
  std::vector<std::uint32_t> triangles;
  triangulate_polygon(corners, triangles);
  ASSERT_EQ(triangles.size(), 3 * (polygon.size() - 2));
  const double area = signed_area(polygon);
  double sum = 0;
  for (std::size_t t = 0; t < triangles.size(); t += 3) {
    const Polygon2 triangle{polygon[triangles[t]], polygon[triangles[t + 1]],
                            polygon[triangles[t + 2]]};
    const double triangle_area = signed_area(triangle);
    EXPECT_GT(triangle_area * area, 0) << "triangle " << t / 3 << " winds the other way";
    sum += triangle_area;
    const double cx = (double(triangle[0].x) + triangle[1].x + triangle[2].x) / 3;
    const double cy = (double(triangle[0].y) + triangle[1].y + triangle[2].y) / 3;
    EXPECT_TRUE(inside(polygon, cx, cy)) << "triangle " << t / 3 << " leaves the polygon";
  }
  EXPECT_EQ(sum, area);
}

// Each from every starting corner and in both windings.
void expect_tiles_exactly_from_every_corner(const Polygon2& polygon) {
  for (const bool reverse : {false, true}) {
    Polygon2 ordered = polygon;
    if (reverse) std::reverse(ordered.begin(), ordered.end());
    for (std::size_t start = 0; start < polygon.size(); ++start) {
      SCOPED_TRACE(testing::Message() << "start " << start << (reverse ? " reversed" : ""));
      expect_tiles_exactly(rotated_start(ordered, start));
    }
  }
}

TEST(PolygonTriangulation, ConvexPolygons) {
  expect_tiles_exactly_from_every_corner({{0, 0}, {2, 0}, {2, 2}, {0, 2}});
  expect_tiles_exactly_from_every_corner({{0, 0}, {4, 0}, {6, 3}, {2, 6}, {-2, 3}});
}

// The pentagon tinyobjloader 2.0.0rc10 drops when it starts at the reflex corner (-8, -9).
TEST(PolygonTriangulation, ConcaveArrowAwayFromTheOrigin) {
  expect_tiles_exactly_from_every_corner({{-8, -9}, {-10, -6}, {-10, -10}, {-6, -10}, {-6, -6}});
}

TEST(PolygonTriangulation, ConcavePolygons) {
  // An L, a comb with three teeth, and a ten-pointed star.
  expect_tiles_exactly_from_every_corner({{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 6}, {0, 6}});
  expect_tiles_exactly_from_every_corner({{0, 0},
                                          {10, 0},
                                          {10, 6},
                                          {8, 6},
                                          {8, 2},
                                          {6, 2},
                                          {6, 6},
                                          {4, 6},
                                          {4, 2},
                                          {2, 2},
                                          {2, 6},
                                          {0, 6}});
  Polygon2 star;
  for (int k = 0; k < 10; ++k) {
    const double angle = 2 * 3.141592653589793 * k / 10;
    const double radius = k % 2 == 0 ? 10 : 4;
    star.push_back({static_cast<float>(std::round(radius * std::cos(angle))),
                    static_cast<float>(std::round(radius * std::sin(angle)))});
  }
  expect_tiles_exactly_from_every_corner(star);
}

// Off the coordinate planes: the L rotated into a tilted plane facing mostly -x. The triangles
// must face the polygon's own way. Areas: corners are rounded to float32 (error up to
// 6 * 2^-24 per coordinate), which moves an area of 20 by at most ~perimeter * 4e-7 < 1e-5.
TEST(PolygonTriangulation, TiltedPlaneKeepsTheWinding) {
  const Polygon2 l_shape{{0, 0}, {6, 0}, {6, 2}, {2, 2}, {2, 6}, {0, 6}};
  for (const bool reverse : {false, true}) {
    std::vector<Vec3> corners;
    for (const Vec2& p : l_shape) {
      // (x, y, 0) -> (-0.3 y - 0.2 x, 0.8 x, 0.9 y): a plane whose normal leans towards -x.
      corners.push_back({-0.3f * p.y - 0.2f * p.x, 0.8f * p.x, 0.9f * p.y});
    }
    if (reverse) std::reverse(corners.begin(), corners.end());
    Vec3d polygon_normal{0, 0, 0};
    for (std::size_t i = 1; i + 1 < corners.size(); ++i) {
      polygon_normal = polygon_normal + cross(to_double(corners[i]) - to_double(corners[0]),
                                              to_double(corners[i + 1]) - to_double(corners[0]));
    }
    std::vector<std::uint32_t> triangles;
    triangulate_polygon(corners, triangles);
    ASSERT_EQ(triangles.size(), 12u);
    double area_sum = 0;
    for (std::size_t t = 0; t < triangles.size(); t += 3) {
      const Vec3d a = to_double(corners[triangles[t]]);
      const Vec3d n =
          cross(to_double(corners[triangles[t + 1]]) - a, to_double(corners[triangles[t + 2]]) - a);
      EXPECT_GT(dot(n, polygon_normal), 0) << "triangle " << t / 3;
      area_sum += length(n) / 2;
    }
    EXPECT_NEAR(area_sum, length(polygon_normal) / 2, 1e-5);
  }
}

TEST(PolygonTriangulation, DegenerateInputStillGivesNMinus2Triangles) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const std::vector<std::vector<Vec3>> polygons{
      {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {3, 3, 3}, {4, 4, 4}},      // collinear
      {{0, 0, 0}, {0, 0, 0}, {0, 0, 0}, {0, 0, 0}},                 // one point
      {{0, 0, 0}, {nan, 0, 0}, {1, 1, 0}, {0, 1, 0}, {0, 2, nan}},  // NaN corners
      {{0, 0, 0}, {2, 0, 0}, {0, 2, 0}, {2, 2, 0}},                 // self-intersecting bow tie
  };
  for (const auto& polygon : polygons) {
    std::vector<std::uint32_t> triangles;
    triangulate_polygon(polygon, triangles);
    ASSERT_EQ(triangles.size(), 3 * (polygon.size() - 2));
    for (const std::uint32_t corner : triangles)
      EXPECT_LT(corner, polygon.size());
  }
  std::vector<std::uint32_t> none;
  triangulate_polygon(std::vector<Vec3>{{0, 0, 0}, {1, 0, 0}}, none);
  EXPECT_TRUE(none.empty());
}

}  // namespace
}  // namespace edgewise::scene::test
