// OBJ files written by the tests: what a good file becomes, and that every kind of bad file is a
// clear message rather than a crash or a wrong mesh.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdio>
#include <string>

#include "mesh_checks.hpp"
#include "obj_files.hpp"
#include "scene/obj_loader.hpp"
#include "scene/procedural.hpp"
#include "temp_directory.hpp"

namespace edgewise::scene::test {
namespace {

// The mesh of a result that must be a valid one (it lives as long as `result`).
const Mesh& expect_loaded(const MeshResult& result) {
  EXPECT_TRUE(result.ok()) << result.error();
  static const Mesh empty;
  if (!result.ok()) return empty;
  const auto problem = validate(result.mesh());
  EXPECT_FALSE(problem.has_value()) << *problem;
  return result.mesh();
}

// The result is an error whose message starts with `name` and contains each of `parts`.
void expect_error(const MeshResult& result, std::string_view name,
                  std::initializer_list<std::string_view> parts) {
  ASSERT_FALSE(result.ok()) << "accepted; expected an error mentioning " << *parts.begin();
  const std::string_view message = result.error();
  EXPECT_TRUE(message.starts_with(std::string(name) + ": ")) << message;
  for (const std::string_view part : parts) {
    EXPECT_NE(message.find(part), std::string_view::npos)
        << "message: " << message << "\nexpected to contain: " << part;
  }
}

TEST(ObjLoader, CubeWithTexcoordsAndNormals) {
  const TempDirectory directory;
  const MeshResult result = load_obj(directory.write("cube.obj", kCubeObj));
  const Mesh& mesh = expect_loaded(result);
  EXPECT_EQ(result.warnings(), "");
  // Six quads of two triangles; no corner is shared between faces (each face has its normal).
  EXPECT_EQ(triangle_count(mesh), 12u);
  EXPECT_EQ(mesh.positions.size(), 24u);
  EXPECT_EQ(mesh.uvs.size(), 24u);
  EXPECT_TRUE(mesh.colors.empty());
  for (std::size_t t = 0; t < triangle_count(mesh); ++t) {
    const Vec3d geometric = triangle_normal(mesh, t);
    EXPECT_DOUBLE_EQ(length(geometric), 4.0);  // half of a 2 x 2 face, doubled
    for (int k = 0; k < 3; ++k) {
      // Counter-clockwise from outside: the triangle faces the way its corners' normals do.
      const Vec3d n = to_double(mesh.normals[mesh.indices[3 * t + k]]);
      EXPECT_DOUBLE_EQ(dot(geometric, n), 4.0) << "triangle " << t;
    }
  }
  const auto box = bounding_box(mesh);
  ASSERT_TRUE(box);
  EXPECT_EQ(box->min.x, -1.0f);
  EXPECT_EQ(box->max.z, 1.0f);
}

// OBJ's v = 0 is the image's bottom row; edgewise's t = 0 its top row.
TEST(ObjLoader, TexcoordVIsFlippedToTDown) {
  const MeshResult result =
      parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.25 0.75\nvt 1 0\nvt 0 1\nf 1/1 2/2 3/3\n");
  const Mesh& mesh = expect_loaded(result);
  ASSERT_EQ(mesh.uvs.size(), 3u);
  EXPECT_EQ(mesh.uvs[0].x, 0.25f);
  EXPECT_EQ(mesh.uvs[0].y, 0.25f);
  EXPECT_EQ(mesh.uvs[1].y, 1.0f);
  EXPECT_EQ(mesh.uvs[2].y, 0.0f);
}

TEST(ObjLoader, CornersMergeIntoVerticesOnlyWhenAllIndicesAgree) {
  const std::string square =
      "v 0 0 0\nv 1 0 0\nv 1 1 0\nv 0 1 0\n"
      "vt 0 0\nvt 1 0\nvt 1 1\nvt 0 1\nvt 0.5 0.5\n";
  // Shared corners 1/1 and 3/3: four vertices.
  EXPECT_EQ(expect_loaded(parse_obj(square + "f 1/1 2/2 3/3\nf 1/1 3/3 4/4\n")).positions.size(),
            4u);
  // Position 1 with another texcoord in the second face: a fifth vertex.
  EXPECT_EQ(expect_loaded(parse_obj(square + "f 1/1 2/2 3/3\nf 1/5 3/3 4/4\n")).positions.size(),
            5u);
  // Positions only: shared by index.
  const MeshResult plain_result = parse_obj(square + "f 1 2 3\nf 1 3 4\n");
  const Mesh& plain = expect_loaded(plain_result);
  EXPECT_EQ(plain.positions.size(), 4u);
  EXPECT_TRUE(plain.uvs.empty());
  // The same position under two indices stays two vertices (only indices are compared).
  EXPECT_EQ(expect_loaded(parse_obj(square + "v 0 0 0\nf 1 2 3\nf 5 3 4\n")).positions.size(), 5u);
}

TEST(ObjLoader, PolygonsAreTriangulatedKeepingTheirWinding) {
  // A quad, a convex pentagon and a concave hexagon (an L) in z = 0, counter-clockwise from +z,
  // and the concave pentagon tinyobjloader's own triangulation drops (it starts at the reflex
  // corner, away from the origin).
  const MeshResult result = parse_obj(
      "v 0 0 0\nv 2 0 0\nv 2 2 0\nv 0 2 0\n"
      "f 1 2 3 4\n"
      "v 10 0 0\nv 14 0 0\nv 16 3 0\nv 12 6 0\nv 8 3 0\n"
      "f 5 6 7 8 9\n"
      "v 20 0 0\nv 26 0 0\nv 26 2 0\nv 22 2 0\nv 22 6 0\nv 20 6 0\n"
      "f 10 11 12 13 14 15\n"
      "v -8 -9 0\nv -10 -6 0\nv -10 -10 0\nv -6 -10 0\nv -6 -6 0\n"
      "f 16 17 18 19 20\n");
  const Mesh& mesh = expect_loaded(result);
  ASSERT_EQ(triangle_count(mesh), 2u + 3u + 4u + 3u);
  double area = 0;
  for (std::size_t t = 0; t < triangle_count(mesh); ++t) {
    const Vec3d n = triangle_normal(mesh, t);
    EXPECT_GT(n.z, 0) << "triangle " << t;
    area += n.z / 2;
  }
  // 4 + 30 + 20 + 10: exact in double for these integer corners.
  EXPECT_EQ(area, 64.0);
}

TEST(ObjLoader, NegativeIndicesCountBackFromTheLineAbove) {
  const MeshResult result = parse_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0.5 0.5\nvn 0 0 1\n"
      "f -3/-1/-1 -2/-1/-1 -1/-1/-1\n"
      "v 5 0 0\nv 6 0 0\nv 5 1 0\nvn 0 0 2\n"
      "f -3/1/-1 -2/1/-1 -1/1/1\n");
  const Mesh& mesh = expect_loaded(result);
  ASSERT_EQ(triangle_count(mesh), 2u);
  const auto position = [&](std::size_t corner) { return mesh.positions[mesh.indices[corner]]; };
  EXPECT_EQ(position(0).x, 0.0f);
  EXPECT_EQ(position(1).x, 1.0f);
  EXPECT_EQ(position(2).y, 1.0f);
  EXPECT_EQ(position(3).x, 5.0f);
  EXPECT_EQ(position(4).x, 6.0f);
  EXPECT_EQ(position(5).y, 1.0f);
  // -1 in the second face is the second normal (0, 0, 2), normalized.
  for (std::size_t corner = 0; corner < 6; ++corner) {
    EXPECT_EQ(mesh.normals[mesh.indices[corner]].z, 1.0f);
  }
  // Positions 4 and 5 with the second normal, position 6 with the first: six vertices.
  EXPECT_EQ(mesh.positions.size(), 6u);
}

TEST(ObjLoader, MissingNormalsAreComputedPointingOutward) {
  // A tetrahedron, counter-clockwise from outside, without vn.
  const MeshResult result = parse_obj(
      "v 0 0 0\nv 1 0 0\nv 0 1 0\nv 0 0 1\n"
      "f 1 3 2\nf 1 2 4\nf 1 4 3\nf 2 3 4\n");
  const Mesh& mesh = expect_loaded(result);
  EXPECT_NE(result.warnings().find("smooth normals"), std::string::npos) << result.warnings();
  ASSERT_EQ(mesh.normals.size(), 4u);
  const Vec3d centroid{0.25, 0.25, 0.25};
  for (std::size_t i = 0; i < 4; ++i) {
    const Vec3d n = to_double(mesh.normals[i]);
    EXPECT_NEAR(length(n), 1.0, kUnitLengthTolerance);
    EXPECT_GT(dot(n, to_double(mesh.positions[i]) - centroid), 0) << "vertex " << i;
  }
  // The origin's three faces meet at right angles: its normal is -(1, 1, 1)/sqrt3.
  EXPECT_NEAR(mesh.normals[0].x, -1 / std::sqrt(3.0), 1e-7);
}

TEST(ObjLoader, ZeroLengthNormalBecomesTheFallback) {
  const MeshResult result = parse_obj("v 0 0 0\nv 1 0 0\nv 0 1 0\nvn 0 0 0\nf 1//1 2//1 3//1\n");
  const Mesh& mesh = expect_loaded(result);
  EXPECT_EQ(mesh.normals[0].z, kFallbackNormal.z);
}

TEST(ObjLoader, MaterialDiffuseColours) {
  const TempDirectory directory;
  directory.write("colours.mtl", kColoursMtl);
  const MeshResult result = load_obj(directory.write("square.obj", kTwoMaterialsObj));
  const Mesh& mesh = expect_loaded(result);
  ASSERT_EQ(triangle_count(mesh), 2u);
  // The shared edge's corners differ in material: split, so 6 vertices.
  EXPECT_EQ(mesh.positions.size(), 6u);
  ASSERT_EQ(mesh.colors.size(), 6u);
  for (int k = 0; k < 3; ++k) {
    const Vec4 red = mesh.colors[mesh.indices[k]];
    EXPECT_EQ(red.x, 1.0f);
    EXPECT_EQ(red.y, 0.0f);
    EXPECT_EQ(red.w, 1.0f);
    const Vec4 glass = mesh.colors[mesh.indices[3 + k]];
    EXPECT_EQ(glass.y, 0.5f);
    EXPECT_EQ(glass.z, 0.75f);
    EXPECT_EQ(glass.w, 0.5f);
  }
}

TEST(ObjLoader, MissingMaterialFileIsOnlyAWarning) {
  const TempDirectory directory;
  const MeshResult result = load_obj(directory.write("square.obj", kTwoMaterialsObj));
  const Mesh& mesh = expect_loaded(result);
  EXPECT_EQ(triangle_count(mesh), 2u);
  EXPECT_TRUE(mesh.colors.empty());
  EXPECT_NE(result.warnings().find("colours.mtl"), std::string::npos) << result.warnings();
}

TEST(ObjLoader, PerVertexColourExtension) {
  const MeshResult result = parse_obj("v 0 0 0 1 0 0\nv 1 0 0 0 1 0\nv 0 1 0 0 0 1\nf 1 2 3\n");
  const Mesh& mesh = expect_loaded(result);
  ASSERT_EQ(mesh.colors.size(), 3u);
  EXPECT_EQ(mesh.colors[mesh.indices[1]].y, 1.0f);
  EXPECT_EQ(mesh.colors[mesh.indices[2]].z, 1.0f);
  EXPECT_EQ(mesh.colors[mesh.indices[2]].w, 1.0f);
}

TEST(ObjLoader, FacesMayNameVerticesDefinedFurtherDown) {
  const MeshResult result = parse_obj("v 0 0 0\nf 1 2 3\nv 1 0 0\r\nv 0 1 0\rv 9 9 9");
  const Mesh& mesh = expect_loaded(result);
  EXPECT_EQ(triangle_count(mesh), 1u);
  EXPECT_EQ(mesh.positions.size(), 3u);
}

// A procedural sphere written as OBJ (one v/vt/vn triple per vertex) comes back as the same mesh.
TEST(ObjLoader, ProceduralSphereRoundTrip) {
  const Mesh sphere = make_uv_sphere({.center = {0.5f, -1, 2}, .rings = 12, .segments = 20});
  std::string text;
  char line[128];
  for (const Vec3& p : sphere.positions) {
    std::snprintf(line, sizeof line, "v %.9g %.9g %.9g\n", p.x, p.y, p.z);
    text += line;
  }
  for (const Vec2& uv : sphere.uvs) {
    std::snprintf(line, sizeof line, "vt %.9g %.9g\n", uv.x, 1.0f - uv.y);
    text += line;
  }
  for (const Vec3& n : sphere.normals) {
    std::snprintf(line, sizeof line, "vn %.9g %.9g %.9g\n", n.x, n.y, n.z);
    text += line;
  }
  for (std::size_t i = 0; i < sphere.indices.size(); i += 3) {
    std::snprintf(line, sizeof line, "f %u/%u/%u %u/%u/%u %u/%u/%u\n", sphere.indices[i] + 1,
                  sphere.indices[i] + 1, sphere.indices[i] + 1, sphere.indices[i + 1] + 1,
                  sphere.indices[i + 1] + 1, sphere.indices[i + 1] + 1, sphere.indices[i + 2] + 1,
                  sphere.indices[i + 2] + 1, sphere.indices[i + 2] + 1);
    text += line;
  }
  const MeshResult result = parse_obj(text);
  const Mesh& mesh = expect_loaded(result);
  ASSERT_EQ(mesh.positions.size(), sphere.positions.size());
  ASSERT_EQ(mesh.indices.size(), sphere.indices.size());
  // 9 significant digits name each float exactly; tinyobjloader's own decimal conversion (double
  // arithmetic, then one rounding to float) may still land one ulp away: 2^-23 relative. The
  // flipped t = 1 - v adds one float rounding of at most 2^-24 to values in [0, 1].
  for (std::size_t corner = 0; corner < sphere.indices.size(); ++corner) {
    const std::uint32_t a = sphere.indices[corner], b = mesh.indices[corner];
    const auto near = [](float x, float y, double scale) {
      return std::fabs(double(x) - y) <= 0x1.0p-23 * scale;
    };
    const Vec3 p = sphere.positions[a], q = mesh.positions[b];
    EXPECT_TRUE(near(p.x, q.x, std::fabs(p.x)) && near(p.y, q.y, std::fabs(p.y)) &&
                near(p.z, q.z, std::fabs(p.z)))
        << "corner " << corner;
    EXPECT_TRUE(near(sphere.uvs[a].x, mesh.uvs[b].x, 1) && near(sphere.uvs[a].y, mesh.uvs[b].y, 1))
        << "corner " << corner;
    EXPECT_NEAR(dot(to_double(sphere.normals[a]), to_double(mesh.normals[b])), 1.0, 1e-6);
  }
}

// --- Bad files ------------------------------------------------------------------------------

TEST(ObjLoaderRejects, MissingFileAndDirectory) {
  const TempDirectory directory;
  const std::string absent = (directory.path() / "absent.obj").string();
  expect_error(load_obj(absent), absent, {"No such file"});
  expect_error(load_obj(directory.path().string()), directory.path().string(),
               {"not a regular file"});
}

TEST(ObjLoaderRejects, EmptyFileAndNoFaces) {
  const TempDirectory directory;
  const std::string empty = directory.write("empty.obj", "");
  expect_error(load_obj(empty), empty, {"empty"});
  expect_error(parse_obj(" \n\r\n\t\n", "blank"), "blank", {"empty"});
  expect_error(parse_obj("# only vertices\nv 0 0 0\nv 1 0 0\nvn 0 0 1\n", "points"), "points",
               {"no faces", "2 vertices"});
}

const std::string kTriangleHeader = "v 0 0 0\nv 1 0 0\nv 0 1 0\nvt 0 0\nvn 0 0 1\n";

TEST(ObjLoaderRejects, MalformedLines) {
  const struct {
    std::string text;
    std::initializer_list<std::string_view> parts;
  } cases[] = {
      {"v 0 0 0\nv 1 abc 0\n", {"line 2", "vertex: 'abc' is not a number"}},
      {"v 0 0\n", {"line 1", "vertex: 2 numbers"}},
      {"v 1 2 3 4 5\n", {"line 1", "vertex: 5 numbers"}},
      {"v 1 2 3 4 5 6 7\n", {"vertex: 7 numbers"}},
      {"v 1 2 3x\n", {"'3x' is not a number"}},
      {"v 1 2 ++3\n", {"'++3' is not a number"}},
      {"vn 0 1\n", {"line 1", "normal: 2 numbers"}},
      {"vt\t0.5 0.5 0 0\n", {"texcoord: 4 numbers"}},
      {kTriangleHeader + "f 1 x 3\n", {"line 6", "'x' is not an index"}},
      {kTriangleHeader + "f 1.5 2 3\n", {"'1.5' is not an index"}},
      {kTriangleHeader + "f 1/ 2/ 3/\n", {"'1/' is not v, v/t, v//n or v/t/n"}},
      {kTriangleHeader + "f 1/1/1/1 2 3\n", {"'1/1/1/1' is not v, v/t"}},
      {kTriangleHeader + "f 1 2\n", {"line 6", "face with 2 corners"}},
      {kTriangleHeader + "f\t\n", {"face with 0 corners"}},
      {kTriangleHeader + "f 1 0 2\n", {"position index 0 (indices count from 1)"}},
      {kTriangleHeader + "f 1/0 2/1 3/1\n", {"texcoord index 0"}},
      // Left to tinyobjloader, whose message passes through.
      {kTriangleHeader + "f 1 2 3\nl 0 1\n", {"`l' line", "line 7"}},
  };
  for (const auto& [text, parts] : cases) {
    SCOPED_TRACE(text);
    expect_error(parse_obj(text, "bad.obj"), "bad.obj", parts);
  }
}

TEST(ObjLoaderRejects, IndicesOutOfRange) {
  const struct {
    std::string text;
    std::initializer_list<std::string_view> parts;
  } cases[] = {
      {kTriangleHeader + "f 1 2 4\n",
       {"line 6", "position index 4 is out of range", "the file defines 3"}},
      {kTriangleHeader + "f 1/2 2/1 3/1\n", {"texcoord index 2 is out of range"}},
      {kTriangleHeader + "f 1//1 2//2 3//1\n", {"normal index 2 is out of range"}},
      {kTriangleHeader + "f -4 -2 -1\n",
       {"line 6", "position index -4 reaches before the first", "3 defined above"}},
      {kTriangleHeader + "f 1/-2 2/-1 3/-1\n", {"texcoord index -2 reaches before"}},
      // Relative indices count only what is defined above the face.
      {"v 0 0 0\nv 1 0 0\nf -1 -2 -3\nv 0 1 0\n", {"line 3", "index -3 reaches before"}},
  };
  for (const auto& [text, parts] : cases) {
    SCOPED_TRACE(text);
    expect_error(parse_obj(text, "range.obj"), "range.obj", parts);
  }
}

TEST(ObjLoaderRejects, NonFiniteValues) {
  const struct {
    std::string text;
    std::initializer_list<std::string_view> parts;
  } cases[] = {
      {"v nan 0 0\n", {"line 1", "'nan' is not a finite number"}},
      {"v 0 0 0\nv 0 -inf 0\n", {"line 2", "'-inf' is not a finite number"}},
      {"v 0 0 infinity\n", {"'infinity' is not a finite number"}},
      {"vn 1e39 0 0\n", {"'1e39' is out of float32 range"}},
      {"vt 1e400 0\n", {"'1e400' is out of range"}},
      {"v 0 0 0 1 NaN 0\n", {"'NaN' is not a finite number"}},
  };
  for (const auto& [text, parts] : cases) {
    SCOPED_TRACE(text);
    expect_error(parse_obj(text + kTriangleHeader + "f 1 2 3\n", "values.obj"), "values.obj",
                 parts);
  }
}

// A value tinyobjloader reads into an infinite float in an MTL file (not checked line by line)
// is still caught by the final validation.
TEST(ObjLoaderRejects, NonFiniteMaterialColour) {
  const TempDirectory directory;
  directory.write("colours.mtl", "newmtl red\nKd 1e39 0 0\nnewmtl glass\nKd 0 0 1\n");
  const std::string path = directory.write("square.obj", kTwoMaterialsObj);
  expect_error(load_obj(path), path, {"colour of vertex", "not finite"});
}

TEST(ObjLoaderRejects, EnormousCounts) {
  const struct {
    std::string text;
    std::initializer_list<std::string_view> parts;
  } cases[] = {
      // Past INT_MAX (tinyobjloader's atoi would wrap 4294967295 to -1, the last vertex).
      {kTriangleHeader + "f 99999999999 1 2\n", {"'99999999999' is out of range"}},
      {kTriangleHeader + "f 4294967295 1 2\n", {"'4294967295' is out of range"}},
      {kTriangleHeader + "f 1 -2147483648 2\n", {"index -2147483648 reaches before"}},
      {kTriangleHeader + "f 2147483647 1 2\n", {"position index 2147483647 is out of range"}},
  };
  for (const auto& [text, parts] : cases) {
    SCOPED_TRACE(text);
    expect_error(parse_obj(text, "huge.obj"), "huge.obj", parts);
  }

  std::string polygon = kTriangleHeader + "f";
  for (int k = 0; k < 300; ++k) {
    polygon += ' ';
    polygon += std::to_string(1 + k % 3);
  }
  expect_error(parse_obj(polygon + "\n", "wide.obj"), "wide.obj", {"more than 255 corners"});
  expect_error(parse_obj(kTriangleHeader + "v 1 1 0\nv 2 2 0\nf 1 2 3 4 5\n", "five.obj",
                         {.max_face_vertices = 4}),
               "five.obj", {"line 8", "more than 4 corners"});

  const TempDirectory directory;
  const std::string cube = directory.write("cube.obj", kCubeObj);
  expect_error(load_obj(cube, {.max_file_bytes = 100}), cube, {"bytes is larger than 100 bytes"});
  expect_error(parse_obj(kCubeObj, "cube", {.max_file_bytes = 100}), "cube",
               {"larger than 100 bytes"});
}

}  // namespace
}  // namespace edgewise::scene::test
