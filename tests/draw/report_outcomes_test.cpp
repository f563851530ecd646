// DrawReport's accounting (draw.hpp): every triangle of the mesh lands in exactly one outcome,
//   outside + culled + errors + rasterized == triangles - clipped + clip_triangles,
// on every ISA and the reference, on one thread and binned on several, for meshes of tiny
// (1e-40, below float's normal range), huge (1e20 and 1e38, beyond the clipper's 2^64; and
// beyond the guard band after projection) and ordinary triangles, alone and mixed. Where the
// outcome of a kind of triangle is settled (draw.hpp says which), it is checked too.
#include <gtest/gtest.h>

#include <cstdint>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "edgewise/draw.hpp"
#include "isa_params.hpp"
#include "draw/vertex_stage/clip_reference.hpp"
#include "draw/vertex_stage/clip.hpp"

namespace edgewise::test {
namespace {

using ReportOutcomes = IsaTest;

constexpr std::int32_t kSize = 256;  // binned in several bins on several threads

// A mesh in its own coordinates, and the transform it is drawn with.
struct Case {
  std::string name;
  std::vector<Vec3> positions;
  std::vector<std::uint32_t> indices;  // empty: three vertices per triangle
  Mat4 transform = identity();
};

// Clip space with w = 1 from pixel coordinates of the kSize x kSize target.
Vec3 at_pixel(double x, double y) {
  return {static_cast<float>(x / (kSize / 2.0) - 1.0), static_cast<float>(1.0 - y / (kSize / 2.0)),
          0.5f};
}

void add(Case& c, const Vec3& a, const Vec3& b, const Vec3& d) {
  c.positions.insert(c.positions.end(), {a, b, d});
}

// Two triangles of half size `size` around (0, 0, z), one in each winding.
Case scaled(std::string name, float size, float z = 0.25f) {
  Case c{std::move(name), {}, {}, identity()};
  add(c, {-size, -size, z}, {size, -size, z}, {0, size, z});
  add(c, {-size, -size, z}, {0, size, z}, {size, -size, z});
  return c;
}

// Ordinary triangles: drawn ones, small and large; a zero-area one (a repeated corner) and a
// sliver of collinear corners, both small enough for one bin; a clipped one reaching beyond the
// guard band; one outside the view; a NaN corner.
Case ordinary() {
  Case c{"ordinary", {}, {}, identity()};
  add(c, at_pixel(10, 10), at_pixel(40, 12), at_pixel(20, 50));
  add(c, at_pixel(5, 250), at_pixel(250, 5), at_pixel(250, 250));
  add(c, at_pixel(100, 100), at_pixel(104, 101), at_pixel(104, 101));
  add(c, at_pixel(130, 130), at_pixel(131, 131), at_pixel(132, 132));
  add(c, at_pixel(60, 60), at_pixel(1e6, 70), at_pixel(70, 1e6));
  add(c, {3.0f, 3.0f, 0.5f}, {4.0f, 3.0f, 0.5f}, {3.0f, 4.0f, 0.5f});
  add(c, at_pixel(20, 20), {std::numeric_limits<float>::quiet_NaN(), 0, 0.5f}, at_pixel(30, 30));
  return c;
}

// Positions of 1e-40 under a transform whose clip-space w is 1e-40 too: exact arithmetic would
// draw the triangles across the view, but w is below kMinProjectedW (float32's 1/w overflows).
Case tiny_w() {
  Case c = scaled("tiny_w", 0.25e-40f);
  Mat4 m{};
  m.m[0][0] = 1.0f;
  m.m[1][1] = 1.0f;
  m.m[2][3] = 0.5e-40f;  // z = w / 2: between the near and far planes
  m.m[3][3] = 1e-40f;
  c.transform = m;
  return c;
}

// The framing an OBJ file of 1e-40 got: a perspective camera whose near and far planes are
// 1e-40 away.
Case tiny_perspective() {
  Case c = scaled("tiny_perspective", 1e-40f, 0.0f);
  c.transform =
      perspective(0.785f, 1.0f, 1.5e-40f, 6e-40f) * look_at({0, 0, 3e-40f}, {0, 0, 0}, {0, 1, 0});
  return c;
}

// Everything at once, indexed: each kind of triangle above, and an index past the end.
Case mixed() {
  Case c{"mixed", {}, {}, identity()};
  for (const Case& part : {ordinary(), scaled("", 1e-40f), scaled("", 1e20f), scaled("", 1e38f),
                           scaled("", 1000.0f), scaled("", 1e-3f)}) {
    const auto first = static_cast<std::uint32_t>(c.positions.size());
    c.positions.insert(c.positions.end(), part.positions.begin(), part.positions.end());
    for (std::uint32_t i = 0; i < part.positions.size(); ++i)
      c.indices.push_back(first + i);
  }
  c.indices.insert(c.indices.end(), {0, 1, 999999});
  return c;
}

std::vector<Case> cases() {
  return {ordinary(),
          scaled("tiny", 1e-40f),
          scaled("tiny_normal", 1e-37f),
          tiny_w(),
          tiny_perspective(),
          scaled("huge_1e20", 1e20f),
          scaled("huge_1e38", 1e38f),
          scaled("beyond_guard_band", 1000.0f),  // 128000 px: clipped by the guard band
          mixed()};
}

std::string counts(const DrawReport& r) {
  return "triangles " + std::to_string(r.triangles) + ", clipped " + std::to_string(r.clipped) +
         " into " + std::to_string(r.clip_triangles) + ", outside " + std::to_string(r.outside) +
         ", culled " + std::to_string(r.culled) + ", errors " + std::to_string(r.errors) +
         ", rasterized " + std::to_string(r.rasterized);
}

DrawReport draw_case(const Case& c, Isa isa, std::size_t threads, CullMode cull) {
  Framebuffer target(kSize, kSize);
  target.clear({0, 0, 0, 1}, 1.0f);
  DrawOptions options;
  options.transform = c.transform;
  options.isa = isa;
  options.threads = threads;
  options.cull = cull;
  return draw(target, {c.positions, {}, {}, c.indices}, options);
}

TEST_P(ReportOutcomes, EveryTriangleHasExactlyOneOutcome) {
  for (const Case& c : cases()) {
    for (CullMode cull : {CullMode::none, CullMode::clockwise}) {
      const DrawReport one = draw_case(c, isa(), 1, cull);
      for (std::size_t threads : {std::size_t{1}, std::size_t{3}}) {
        const DrawReport r = threads == 1 ? one : draw_case(c, isa(), threads, cull);
        const std::string where = c.name + ", cull " + std::string(name_of(cull)) + ", threads " +
                                  std::to_string(threads) + ": " + counts(r);
        EXPECT_EQ(r.outside + r.culled + r.errors + r.rasterized,
                  r.triangles - r.clipped + r.clip_triangles)
            << where;
        EXPECT_EQ(counts(r), counts(one)) << where;
      }
    }
  }
}

TEST_P(ReportOutcomes, TinyTrianglesAreCulledAndTinyWIsAnError) {
  // w = 1: both triangles snap to one point.
  const DrawReport tiny = draw_case(scaled("tiny", 1e-40f), isa(), 1, CullMode::none);
  EXPECT_EQ(tiny.culled, 2u) << counts(tiny);
  EXPECT_EQ(tiny.errors, 0u) << counts(tiny);
  EXPECT_EQ(tiny.rasterized, 0u) << counts(tiny);
  for (const Case& c : {tiny_w(), tiny_perspective()}) {
    const DrawReport r = draw_case(c, isa(), 1, CullMode::none);
    EXPECT_EQ(r.errors, 2u) << c.name << ": " << counts(r);
    EXPECT_EQ(r.rasterized, 0u) << c.name << ": " << counts(r);
  }
}

TEST_P(ReportOutcomes, CoordinatesBeyondTheClipRangeAreErrors) {
  for (float size : {1e20f, 1e38f}) {
    const DrawReport r = draw_case(scaled("huge", size), isa(), 1, CullMode::none);
    EXPECT_EQ(r.errors, 2u) << size << ": " << counts(r);
    EXPECT_EQ(r.rasterized, 0u) << size << ": " << counts(r);
  }
  // Beyond the guard band but within the clipper's range: clipped and drawn.
  const DrawReport r = draw_case(scaled("beyond", 1000.0f), isa(), 1, CullMode::none);
  EXPECT_EQ(r.clipped, 2u) << counts(r);
  EXPECT_EQ(r.errors, 0u) << counts(r);
  EXPECT_EQ(r.rasterized, r.clip_triangles) << counts(r);
}

// The rule behind tiny_w, in the clipper and its double-precision reference alike: a kept vertex
// at 0 < w < kMinProjectedW is an error; at w = 0, a degenerate projection; one that clipping
// removes is no error, whatever its w.
TEST(ClipTinyW, KeptVerticesBelowTheProjectedRangeAreErrors) {
  const Viewport viewport{64, 48};
  const auto status = [&](const Vec4& a, const Vec4& b, const Vec4& c) {
    const ClipStatus fast = clip_triangle(a, b, c, guard_band_planes(viewport)).status;
    EXPECT_EQ(fast, reference::clip_triangle(a, b, c, viewport).status);
    return fast;
  };
  const float tiny = 1e-40f, least = kMinProjectedW;
  EXPECT_EQ(status({0, 0, 0.5f * tiny, tiny}, {0.5f * tiny, 0, 0.5f * tiny, tiny},
                   {0, 0.5f * tiny, 0.5f * tiny, tiny}),
            ClipStatus::error_out_of_range);
  // One tiny vertex among ordinary ones; and the least w projected, which is drawn.
  EXPECT_EQ(status({0, 0, 0.5f, 1}, {0.5f, 0, 0.5f, 1}, {0, 0, 0, tiny}),
            ClipStatus::error_out_of_range);
  EXPECT_EQ(status({0, 0, 0.5f * least, least}, {0.5f * least, 0, 0.5f * least, least},
                   {0, 0.5f * least, 0.5f * least, least}),
            ClipStatus::inside);
  EXPECT_EQ(status({0, 0, 0.5f, 1}, {0.5f, 0, 0.5f, 1}, {0, 0, 0, 0}),
            ClipStatus::culled_degenerate);
  // Beyond the near plane: cut off, its crossing at w near 1.
  EXPECT_EQ(status({0, 0, 0.5f, 1}, {0.5f, 0, 0.5f, 1}, {0, 0.5f * tiny, -1, tiny}),
            ClipStatus::clipped);
  const GuardBandPlanes planes = guard_band_planes(viewport);
  EXPECT_FALSE(classify_clip_vertex({0, 0, 0.5f * tiny, tiny}, planes).inside);
  EXPECT_TRUE(classify_clip_vertex({0, 0, 0.5f * least, least}, planes).inside);
}

INSTANTIATE_TEST_SUITE_P(AllIsas, ReportOutcomes, ::testing::ValuesIn(every_isa()), isa_test_name);

}  // namespace
}  // namespace edgewise::test
