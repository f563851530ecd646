// The built-in shapes: closed, outward-facing, unit normals, the documented counts, and a demo
// scene that shows what it promises from its camera.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "mesh_checks.hpp"
#include "scene/procedural.hpp"

namespace edgewise::scene::test {
namespace {

void expect_finite_and_valid(const Mesh& mesh) {
  const auto problem = validate(mesh);
  EXPECT_FALSE(problem.has_value()) << *problem;
  EXPECT_EQ(mesh.normals.size(), mesh.positions.size());
  EXPECT_EQ(mesh.uvs.size(), mesh.positions.size());
  EXPECT_EQ(mesh.colors.size(), mesh.positions.size());
}

void expect_unit_normals(const Mesh& mesh) {
  double worst = 0;
  for (const Vec3& n : mesh.normals)
    worst = std::max(worst, std::fabs(length(to_double(n)) - 1));
  EXPECT_LE(worst, kUnitLengthTolerance);
}

// Closed and consistently wound: once vertices are welded by position, every directed edge is
// used by exactly one triangle and its reverse by exactly one other. The Euler characteristic
// V - E + F then tells the surface's genus (2 for a sphere, 0 for a torus).
void expect_closed(const Mesh& mesh, int euler_characteristic) {
  const std::vector<std::uint32_t> welded = weld_by_position(mesh);
  const auto edges = directed_edges(mesh, welded);
  int repeated = 0, unmatched = 0, degenerate = 0;
  for (const auto& [edge, count] : edges) {
    if (count != 1) ++repeated;
    if (edge.first == edge.second) ++degenerate;
    const auto reverse = edges.find({edge.second, edge.first});
    if (reverse == edges.end() || reverse->second != 1) ++unmatched;
  }
  EXPECT_EQ(repeated, 0) << "directed edges used by more than one triangle";
  EXPECT_EQ(unmatched, 0) << "edges without exactly one opposite neighbour";
  EXPECT_EQ(degenerate, 0) << "edges from a vertex to itself";
  const auto vertices = static_cast<long>(distinct_ids(welded));
  const auto undirected = static_cast<long>(edges.size() / 2);
  const auto faces = static_cast<long>(triangle_count(mesh));
  EXPECT_EQ(vertices - undirected + faces, euler_characteristic);
}

Vec3d normalized(Vec3d v) {
  return (1.0 / length(v)) * v;
}

TEST(Sphere, CountsMatchTheDocumentedFormula) {
  for (const auto& [rings, segments] : {std::pair{2, 3}, {3, 4}, {7, 11}, {24, 48}}) {
    const Mesh mesh = make_uv_sphere({.rings = rings, .segments = segments});
    EXPECT_EQ(mesh.positions.size(),
              static_cast<std::size_t>(2 * segments + (rings - 1) * (segments + 1)))
        << rings << "x" << segments;
    EXPECT_EQ(triangle_count(mesh), static_cast<std::size_t>(2 * segments * (rings - 1)))
        << rings << "x" << segments;
  }
}

TEST(Sphere, CountsBelowTheMinimumAreRaisedToIt) {
  const Mesh clamped = make_uv_sphere({.rings = 0, .segments = -5});
  const Mesh minimum = make_uv_sphere({.rings = kMinSphereRings, .segments = kMinSegments});
  EXPECT_EQ(clamped.positions.size(), minimum.positions.size());
  EXPECT_EQ(clamped.indices, minimum.indices);
}

TEST(Sphere, IsClosedWithConsistentWinding) {
  for (const auto& [rings, segments] : {std::pair{2, 3}, {3, 4}, {7, 11}, {32, 64}}) {
    SCOPED_TRACE(testing::Message() << rings << "x" << segments);
    expect_closed(make_uv_sphere({.rings = rings, .segments = segments}), 2);
  }
}

TEST(Sphere, NormalsAndWindingPointOutward) {
  const Vec3 center{1.5f, -2.0f, 0.25f};
  const float radius = 3.0f;
  const Mesh mesh =
      make_uv_sphere({.center = center, .radius = radius, .rings = 9, .segments = 13});
  expect_finite_and_valid(mesh);
  expect_unit_normals(mesh);
  const Vec3d c = to_double(center);
  double worst_cosine = 1;
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec3d radial = normalized(to_double(mesh.positions[i]) - c);
    worst_cosine = std::min(worst_cosine, dot(radial, to_double(mesh.normals[i])));
    EXPECT_NEAR(length(to_double(mesh.positions[i]) - c), radius, 1e-6 * radius);
  }
  // Positions rounded to float32 turn the radial direction by ~1e-7 at most.
  EXPECT_GT(worst_cosine, 1 - 1e-6);
  for (std::size_t t = 0; t < triangle_count(mesh); ++t) {
    EXPECT_GT(dot(triangle_normal(mesh, t), triangle_centroid(mesh, t) - c), 0) << "triangle " << t;
  }
}

TEST(Sphere, UvsCoverTheImageWithTTopDown) {
  const Mesh mesh = make_uv_sphere({.rings = 4, .segments = 8});
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    const Vec2 uv = mesh.uvs[i];
    EXPECT_GE(uv.x, 0.0f);
    EXPECT_LE(uv.x, 1.0f);
    // t = 0 at the +y pole, 1 at the -y pole: t follows (1 - y) / 2 through the latitude.
    const double expected_t =
        std::acos(std::clamp(double(mesh.positions[i].y), -1.0, 1.0)) / std::numbers::pi;
    EXPECT_NEAR(uv.y, expected_t, 1e-6) << "vertex " << i;
  }
}

// The nearest point of the (untilted) torus's middle circle, for a point given relative to the
// centre with the tilt undone.
Vec3d untilt(Vec3d q, double tilt) {
  const double c = std::cos(tilt), s = std::sin(tilt);
  return {q.x, q.y * c + q.z * s, -q.y * s + q.z * c};
}
Vec3d tube_center(Vec3d q, double major_radius) {
  return major_radius * normalized(Vec3d{q.x, 0, q.z});
}

TEST(Torus, CountsMatchTheDocumentedFormula) {
  for (const auto& [major, minor] : {std::pair{3, 3}, {5, 4}, {48, 24}}) {
    const Mesh mesh = make_torus({.major_segments = major, .minor_segments = minor});
    EXPECT_EQ(mesh.positions.size(), static_cast<std::size_t>((major + 1) * (minor + 1)));
    EXPECT_EQ(triangle_count(mesh), static_cast<std::size_t>(2 * major * minor));
  }
}

TEST(Torus, IsClosedWithConsistentWinding) {
  for (const auto& [major, minor] : {std::pair{3, 3}, {5, 4}, {48, 24}}) {
    SCOPED_TRACE(testing::Message() << major << "x" << minor);
    expect_closed(
        make_torus({.major_segments = major, .minor_segments = minor, .tilt_radians = 0.4f}), 0);
  }
}

TEST(Torus, NormalsAndWindingPointOutOfTheTube) {
  for (const float tilt : {0.0f, 0.7f}) {
    SCOPED_TRACE(testing::Message() << "tilt " << tilt);
    const Vec3 center{-1.0f, 2.0f, 3.0f};
    const TorusOptions options{.center = center,
                               .major_radius = 2.0f,
                               .minor_radius = 0.5f,
                               .major_segments = 17,
                               .minor_segments = 9,
                               .tilt_radians = tilt};
    const Mesh mesh = make_torus(options);
    expect_finite_and_valid(mesh);
    expect_unit_normals(mesh);
    const Vec3d c = to_double(center);
    double worst_cosine = 1;
    for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
      const Vec3d q = untilt(to_double(mesh.positions[i]) - c, tilt);
      const Vec3d out = q - tube_center(q, options.major_radius);
      EXPECT_NEAR(length(out), options.minor_radius, 1e-5);
      worst_cosine =
          std::min(worst_cosine, dot(normalized(out), untilt(to_double(mesh.normals[i]), tilt)));
    }
    EXPECT_GT(worst_cosine, 1 - 1e-5);
    for (std::size_t t = 0; t < triangle_count(mesh); ++t) {
      const Vec3d q = untilt(triangle_centroid(mesh, t) - c, tilt);
      const Vec3d out = q - tube_center(q, options.major_radius);
      EXPECT_GT(dot(untilt(triangle_normal(mesh, t), tilt), out), 0) << "triangle " << t;
    }
  }
}

TEST(GroundPlane, CountsNormalsAndWinding) {
  const GroundOptions options{.height = -1.5f, .half_extent = 10.0f, .cells_per_side = 5};
  const Mesh mesh = make_ground_plane(options);
  expect_finite_and_valid(mesh);
  ASSERT_EQ(mesh.positions.size(), 4u * 25);
  ASSERT_EQ(triangle_count(mesh), 2u * 25);
  for (const Vec3& n : mesh.normals) {
    EXPECT_EQ(n.x, 0.0f);
    EXPECT_EQ(n.y, 1.0f);
    EXPECT_EQ(n.z, 0.0f);
  }
  const double cell_area = 4.0 * 4.0;
  for (std::size_t t = 0; t < triangle_count(mesh); ++t) {
    const Vec3d n = triangle_normal(mesh, t);
    EXPECT_DOUBLE_EQ(n.y, cell_area) << "triangle " << t;  // twice half a cell, facing +y
    EXPECT_EQ(n.x, 0.0);
    EXPECT_EQ(n.z, 0.0);
  }
  const auto box = bounding_box(mesh);
  ASSERT_TRUE(box);
  EXPECT_EQ(box->min.x, -10.0f);
  EXPECT_EQ(box->max.z, 10.0f);
  EXPECT_EQ(box->min.y, -1.5f);
  EXPECT_EQ(box->max.y, -1.5f);
}

// Neighbouring cells share their corners bit for bit: inside, every edge has one triangle on
// each side; only the square's outline (4 * cells edges) has one.
TEST(GroundPlane, CellsMeetWithoutGaps) {
  const int cells = 7;
  const Mesh mesh = make_ground_plane({.half_extent = 123.4f, .cells_per_side = cells});
  const auto edges = directed_edges(mesh, weld_by_position(mesh));
  int boundary = 0;
  for (const auto& [edge, count] : edges) {
    EXPECT_EQ(count, 1);
    if (!edges.contains({edge.second, edge.first})) ++boundary;
  }
  EXPECT_EQ(boundary, 4 * cells);
}

TEST(GroundPlane, UvsRepeatEveryTextureTileAndColoursAlternate) {
  const GroundOptions options{.half_extent = 6.0f,
                              .cells_per_side = 3,
                              .texture_tile = 0.5f,
                              .color_a = {1, 0, 0, 1},
                              .color_b = {0, 0, 1, 1}};
  const Mesh mesh = make_ground_plane(options);
  for (std::size_t i = 0; i < mesh.positions.size(); ++i) {
    EXPECT_FLOAT_EQ(mesh.uvs[i].x, mesh.positions[i].x / options.texture_tile);
    EXPECT_FLOAT_EQ(mesh.uvs[i].y, mesh.positions[i].z / options.texture_tile);
  }
  // The plane is 12 units wide: 24 repeats of the texture.
  float lowest = 0, highest = 0;
  for (const Vec2& uv : mesh.uvs) {
    lowest = std::min(lowest, uv.x);
    highest = std::max(highest, uv.x);
  }
  EXPECT_FLOAT_EQ(highest - lowest, 24.0f);
  // Cells come row by row, 4 vertices each; each cell is one colour, unlike its neighbours.
  for (int row = 0; row < 3; ++row) {
    for (int column = 0; column < 3; ++column) {
      const std::size_t first = 4 * static_cast<std::size_t>(row * 3 + column);
      const float red = (row + column) % 2 == 0 ? 1.0f : 0.0f;
      for (std::size_t k = first; k < first + 4; ++k) {
        EXPECT_EQ(mesh.colors[k].x, red) << "cell " << row << "," << column;
        EXPECT_EQ(mesh.colors[k].z, 1.0f - red);
      }
    }
  }
}

// Where a ray from the eye through `point` first enters the sphere, as a distance along it
// (infinity when it misses).
double sphere_entry(Vec3d eye, Vec3d point, Vec3d center, double radius) {
  const Vec3d d = normalized(point - eye);
  const double b = dot(d, center - eye);
  const double disc = b * b - (dot(center - eye, center - eye) - radius * radius);
  return disc > 0 ? b - std::sqrt(disc) : INFINITY;
}

TEST(DefaultScene, IsValidAndEverythingLiesBetweenTheClipPlanes) {
  const Scene scene = default_scene();
  expect_finite_and_valid(scene.mesh);
  expect_unit_normals(scene.mesh);
  const Vec3d eye = to_double(scene.camera.eye);
  double nearest = INFINITY, farthest = 0;
  for (const Vec3& p : scene.mesh.positions) {
    const double distance = length(to_double(p) - eye);
    nearest = std::min(nearest, distance);
    farthest = std::max(farthest, distance);
  }
  EXPECT_GT(nearest, scene.camera.near_plane);
  EXPECT_LT(farthest, scene.camera.far_plane);
}

TEST(DefaultScene, TorusPassesBothInFrontOfAndBehindTheSphere) {
  const Scene scene = default_scene();
  const Vec3d eye = to_double(scene.camera.eye);
  const Vec3d center{0.0, 1.3, 0.0};  // the sphere's, as default_scene documents
  int in_front = 0, behind = 0, torus = 0;
  for (const Vec3& position : scene.mesh.positions) {
    const Vec3d p = to_double(position);
    const double from_center = length(p - center);
    // The torus's vertices are 1.35 to 1.85 from the centre; the sphere's exactly 1.
    if (from_center < 1.3 || from_center > 1.9 || p.y < 1e-3) continue;
    ++torus;
    const double entry = sphere_entry(eye, p, center, 1.0);
    if (entry == INFINITY) continue;
    if (length(p - eye) < entry) ++in_front;
    if (length(p - eye) > entry + 0.1) ++behind;
  }
  EXPECT_EQ(torus, 97 * 25);
  std::printf("of %d torus vertices, %d are in front of the sphere and %d behind it\n", torus,
              in_front, behind);
  EXPECT_GT(in_front, 100);
  EXPECT_GT(behind, 100);
}

TEST(DefaultScene, GroundReachesNearlyToTheHorizonInView) {
  const Scene scene = default_scene();
  const SceneCamera& camera = scene.camera;
  const Vec3d eye = to_double(camera.eye);
  const Vec3d forward = normalized(to_double(camera.target) - eye);
  const double half_fov = camera.vertical_fov_degrees / 2 * std::numbers::pi / 180;
  const double pitch_down = std::asin(-forward.y);
  // The horizon (pitch 0) is inside the field of view, above the image centre.
  EXPECT_GT(pitch_down, 0);
  EXPECT_LT(pitch_down, half_fov);

  const auto box = bounding_box(scene.mesh);
  ASSERT_TRUE(box);
  // Straight ahead (towards -z), the ground ends this far below the horizon.
  const double far_edge = -box->min.z + eye.z;
  const double below_horizon = std::atan(eye.y / far_edge) * 180 / std::numbers::pi;
  EXPECT_GT(below_horizon, 0);
  EXPECT_LT(below_horizon, 1.0);
  // The bottom of the view meets the ground inside the plane.
  const double bottom_z = eye.z - eye.y / std::tan(pitch_down + half_fov);
  EXPECT_GT(bottom_z, box->min.z);
  EXPECT_LT(bottom_z, box->max.z);
  EXPECT_EQ(box->min.y, 0.0f);
}

}  // namespace
}  // namespace edgewise::scene::test
