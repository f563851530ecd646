// The Mesh helpers: bounding box, validation, smooth normals, appending.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "mesh_checks.hpp"
#include "scene/mesh.hpp"

namespace edgewise::scene::test {
namespace {

constexpr float kNaN = std::numeric_limits<float>::quiet_NaN();
constexpr float kInf = std::numeric_limits<float>::infinity();

// A unit cube's 8 corners, shared by its 12 triangles, wound counter-clockwise from outside.
Mesh shared_corner_cube() {
  Mesh mesh;
  for (int i = 0; i < 8; ++i) {
    mesh.positions.push_back(
        {(i & 1) ? 1.0f : -1.0f, (i & 2) ? 1.0f : -1.0f, (i & 4) ? 1.0f : -1.0f});
  }
  mesh.indices = {0, 2, 3, 0, 3, 1,   // -z
                  4, 5, 7, 4, 7, 6,   // +z
                  0, 4, 6, 0, 6, 2,   // -x
                  1, 3, 7, 1, 7, 5,   // +x
                  0, 1, 5, 0, 5, 4,   // -y
                  2, 6, 7, 2, 7, 3};  // +y
  return mesh;
}

TEST(BoundingBox, SkipsNonFinitePositionsAndIsEmptyWithoutAny) {
  Mesh mesh;
  EXPECT_FALSE(bounding_box(mesh).has_value());
  mesh.positions = {{kNaN, 0, 0}, {1, kInf, 2}};
  EXPECT_FALSE(bounding_box(mesh).has_value());
  mesh.positions.push_back({1, -2, 3});
  mesh.positions.push_back({kNaN, kNaN, kNaN});
  mesh.positions.push_back({-4, 5, 0.5f});
  const auto box = bounding_box(mesh);
  ASSERT_TRUE(box);
  EXPECT_EQ(box->min.x, -4);
  EXPECT_EQ(box->min.y, -2);
  EXPECT_EQ(box->min.z, 0.5f);
  EXPECT_EQ(box->max.x, 1);
  EXPECT_EQ(box->max.y, 5);
  EXPECT_EQ(box->max.z, 3);
}

TEST(Validate, AcceptsAConsistentMesh) {
  Mesh mesh = shared_corner_cube();
  EXPECT_FALSE(validate(mesh).has_value());
  mesh.uvs.assign(8, {0.5f, 2.0f});
  EXPECT_FALSE(validate(mesh).has_value());
}

// Each broken mesh is reported, and the message names what is wrong.
TEST(Validate, NamesEachProblem) {
  const auto problem_with = [](auto&& damage) {
    Mesh mesh = shared_corner_cube();
    compute_smooth_normals(mesh);
    mesh.uvs.assign(mesh.positions.size(), {0, 0});
    mesh.colors.assign(mesh.positions.size(), {1, 1, 1, 1});
    damage(mesh);
    return validate(mesh).value_or("(accepted)");
  };
  EXPECT_NE(problem_with([](Mesh& m) { m.indices.pop_back(); }).find("multiple of 3"),
            std::string::npos);
  EXPECT_NE(problem_with([](Mesh& m) { m.indices[4] = 8; }).find("index 4 is 8"),
            std::string::npos);
  EXPECT_NE(problem_with([](Mesh& m) { m.normals.pop_back(); }).find("normal: 7 values"),
            std::string::npos);
  EXPECT_NE(problem_with([](Mesh& m) { m.colors.push_back({}); }).find("colour: 9 values"),
            std::string::npos);
  EXPECT_NE(problem_with([](Mesh& m) { m.positions[3].y = kNaN; }).find("position of vertex 3"),
            std::string::npos);
  EXPECT_NE(problem_with([](Mesh& m) { m.normals[5].z = kInf; }).find("normal of vertex 5"),
            std::string::npos);
  EXPECT_NE(problem_with([](Mesh& m) { m.uvs[6].x = -kInf; }).find("uv of vertex 6"),
            std::string::npos);
  EXPECT_NE(problem_with([](Mesh& m) { m.colors[7].w = kNaN; }).find("colour of vertex 7"),
            std::string::npos);
}

TEST(SmoothNormals, CubeCornersGetTheirDiagonal) {
  Mesh mesh = shared_corner_cube();
  compute_smooth_normals(mesh);
  ASSERT_EQ(mesh.normals.size(), 8u);
  // Each corner has a right angle on each of its three faces (split between two triangles on
  // some): the normal is the corner's diagonal. The double-precision sums are exact to ~1e-15;
  // rounding the unit components to float32 adds at most 2^-24 (relative, on values below 1).
  const double tolerance = 0x1.0p-24 + 1e-12;
  for (std::size_t i = 0; i < 8; ++i) {
    const Vec3 p = mesh.positions[i];
    const double third = 1 / std::sqrt(3.0);
    EXPECT_NEAR(mesh.normals[i].x, p.x * third, tolerance) << "corner " << i;
    EXPECT_NEAR(mesh.normals[i].y, p.y * third, tolerance) << "corner " << i;
    EXPECT_NEAR(mesh.normals[i].z, p.z * third, tolerance) << "corner " << i;
  }
}

TEST(SmoothNormals, VerticesAtOnePositionShareANormal) {
  // Two triangles folded along x = 0, the fold's vertices repeated (as at a texture seam).
  Mesh mesh;
  mesh.positions = {{0, 0, 0}, {0, 1, 0}, {-1, 0, 1}, {0, 0, 0}, {1, 0, 1}, {0, 1, 0}};
  mesh.indices = {0, 1, 2, 3, 4, 5};
  compute_smooth_normals(mesh);
  EXPECT_EQ(mesh.normals[0].x, mesh.normals[3].x);
  EXPECT_EQ(mesh.normals[0].y, mesh.normals[3].y);
  EXPECT_EQ(mesh.normals[0].z, mesh.normals[3].z);
  // The faces' normals (1, 0, 1)/sqrt2 and (-1, 0, 1)/sqrt2 meet at equal angles (90 degrees
  // at the origin, acos(1/sqrt3) at (0, 1, 0) on both): their mean is +z.
  for (const std::size_t shared : {0u, 1u}) {
    EXPECT_NEAR(mesh.normals[shared].x, 0.0f, 1e-7);
    EXPECT_NEAR(mesh.normals[shared].z, 1.0f, 1e-7);
  }
  // The unshared corners keep their own face's normal.
  EXPECT_NEAR(mesh.normals[2].x, std::sqrt(0.5), 1e-7);
  EXPECT_NEAR(mesh.normals[4].x, -std::sqrt(0.5), 1e-7);
}

TEST(SmoothNormals, DegenerateAndBrokenTrianglesGiveTheFallback) {
  Mesh mesh;
  // A zero-area triangle, a triangle with a NaN corner, an out-of-range index, a lone vertex.
  mesh.positions = {{0, 0, 0}, {1, 1, 1}, {2, 2, 2}, {kNaN, 0, 0}, {5, 0, 0}, {0, 5, 0}, {9, 9, 9}};
  mesh.indices = {0, 1, 2, 3, 4, 5, 4, 5, 70};
  compute_smooth_normals(mesh);
  ASSERT_EQ(mesh.normals.size(), mesh.positions.size());
  for (const Vec3& n : mesh.normals) {
    EXPECT_EQ(n.x, kFallbackNormal.x);
    EXPECT_EQ(n.y, kFallbackNormal.y);
    EXPECT_EQ(n.z, kFallbackNormal.z);
  }
}

TEST(Append, OffsetsIndicesAndFillsMissingAttributes) {
  Mesh mesh = shared_corner_cube();
  mesh.colors.assign(8, {0.5f, 0.5f, 0.5f, 1.0f});
  Mesh triangle;
  triangle.positions = {{0, 0, 5}, {1, 0, 5}, {0, 1, 5}};
  triangle.uvs = {{0, 0}, {1, 0}, {0, 1}};
  triangle.normals.assign(3, {0, 0, 1});
  triangle.indices = {0, 1, 2};
  append(mesh, triangle);

  EXPECT_FALSE(validate(mesh).has_value());
  ASSERT_EQ(mesh.positions.size(), 11u);
  EXPECT_EQ(triangle_count(mesh), 13u);
  EXPECT_EQ(mesh.indices[36], 8u);
  EXPECT_EQ(mesh.indices[38], 10u);
  // The cube had no normals: computed (its corners' diagonals); no uvs: (0, 0).
  EXPECT_NEAR(mesh.normals[7].x, 1 / std::sqrt(3.0), 1e-7);
  EXPECT_EQ(mesh.uvs[0].x, 0.0f);
  EXPECT_EQ(mesh.uvs[9].x, 1.0f);
  // The triangle had no colours: opaque white.
  EXPECT_EQ(mesh.colors[0].x, 0.5f);
  EXPECT_EQ(mesh.colors[10].x, 1.0f);
  EXPECT_EQ(mesh.colors[10].w, 1.0f);
}

TEST(Append, IntoAnEmptyMeshCopies) {
  Mesh mesh;
  Mesh cube = shared_corner_cube();
  append(mesh, cube);
  EXPECT_EQ(mesh.indices, cube.indices);
  EXPECT_TRUE(mesh.normals.empty());
  EXPECT_TRUE(mesh.colors.empty());
}

}  // namespace
}  // namespace edgewise::scene::test
