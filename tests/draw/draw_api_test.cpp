// draw()'s contract: argument checks, bad geometry counted and never drawn, clipping at the near
// plane, the depth compare functions on a known scene, the framebuffer's layout.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "edgewise/draw.hpp"
#include "isa_params.hpp"
#include "core/framebuffer_access.hpp"

namespace edgewise::test {
namespace {

using RenderApi = IsaTest;

// Two screen-filling quads in an orthographic view of [0, 8] x [0, 8] pixels; the near one
// (depth 0.25) red, the far one (0.75) green, drawn far first.
struct TwoQuads {
  std::vector<Vec3> positions;
  std::vector<Vec4> colors;
  TwoQuads() {
    for (const auto& [z, color] :
         {std::pair{-0.75f, Vec4{0, 1, 0, 1}}, std::pair{-0.25f, Vec4{1, 0, 0, 1}}}) {
      const Vec3 quad[6] = {{0, 0, z}, {8, 0, z}, {0, 8, z}, {8, 0, z}, {8, 8, z}, {0, 8, z}};
      for (const Vec3& p : quad) {
        positions.push_back(p);
        colors.push_back(color);
      }
    }
  }
  DrawMesh mesh() const { return {positions, colors, {}, {}}; }
};

DrawOptions ortho_options(Isa isa) {
  DrawOptions options;
  // x right, y down: top = 0, bottom = 8.
  options.transform = orthographic(0.0f, 8.0f, 8.0f, 0.0f, 0.0f, 1.0f);
  options.isa = isa;
  return options;
}

TEST_P(RenderApi, DepthCompareFunctionsOnTwoQuads) {
  const TwoQuads quads;
  struct Case {
    DepthTest test;
    bool write;
    float clear_depth;
    std::uint32_t color;  // expected everywhere
    float depth;
  };
  const std::uint32_t red = 0xFF0000FF, green = 0xFF00FF00, clear = 0xFF000000;  // A B G R
  for (const Case& c : {Case{DepthTest::less, true, 1.0f, red, 0.25f},
                        Case{DepthTest::less_equal, true, 1.0f, red, 0.25f},
                        Case{DepthTest::greater, true, 0.0f, green, 0.75f},
                        Case{DepthTest::always, true, 1.0f, red, 0.25f},
                        Case{DepthTest::never, true, 1.0f, clear, 1.0f},
                        Case{DepthTest::less, false, 1.0f, red, 1.0f},
                        Case{DepthTest::less, true, 0.5f, red, 0.25f}}) {  // green fails
    DrawOptions options = ortho_options(isa());
    options.depth_test = c.test;
    options.depth_write = c.write;
    Framebuffer drawn(8, 8);
    drawn.clear({0, 0, 0, 1}, c.clear_depth);
    const DrawReport r = draw(drawn, quads.mesh(), options);
    EXPECT_EQ(r.fragments, 128u);
    for (int y = 0; y < 8; ++y) {
      for (int x = 0; x < 8; ++x) {
        EXPECT_EQ(drawn.color(x, y), c.color)
            << name_of(c.test) << " write " << c.write << " at " << x << "," << y;
        EXPECT_EQ(drawn.depth(x, y), c.depth) << name_of(c.test);
      }
    }
  }
}

TEST_P(RenderApi, BadGeometryIsCountedNotDrawn) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<Vec3> positions = {{1, 1, -0.5f}, {nan, 1, -0.5f}, {1, 6, -0.5f},
                                       {1, 1, -0.5f}, {inf, 1, -0.5f}, {1, 6, -0.5f},
                                       {1, 1, -0.5f}, {6, 1, -0.5f},   {1, 6, -0.5f}};
  const std::vector<std::uint32_t> indices = {0, 1, 2, 3, 4, 5, 6, 7, 8, 6, 7, 99};
  Framebuffer target(8, 8);
  target.clear({0, 0, 0, 1}, 1.0f);
  const DrawReport report = draw(target, {positions, {}, {}, indices}, ortho_options(isa()));
  EXPECT_EQ(report.triangles, 4u);
  EXPECT_EQ(report.errors, 3u);  // NaN, infinity, index 99
  EXPECT_EQ(report.rasterized, 1u);
  EXPECT_GT(report.fragments, 0u);
}

TEST_P(RenderApi, ArgumentErrorsThrow) {
  const std::vector<Vec3> positions(3, Vec3{0, 0, -0.5f});
  const std::vector<Vec4> two_colors(2, Vec4{1, 1, 1, 1});
  const std::vector<std::uint32_t> four_indices = {0, 1, 2, 0};
  Framebuffer target(8, 8);
  const DrawOptions options = ortho_options(isa());
  EXPECT_THROW(draw(target, {positions, two_colors, {}, {}}, options), std::invalid_argument);
  EXPECT_THROW(draw(target, {positions, {}, {}, four_indices}, options), std::invalid_argument);
  DrawOptions diffuse = options;
  diffuse.shading = Shading::diffuse;
  EXPECT_THROW(draw(target, {positions, {}, {}, {}}, diffuse), std::invalid_argument);
  DrawOptions inverted = options;
  inverted.scissor = PixelRect{5, 0, 2, 8};
  EXPECT_THROW(draw(target, {positions, {}, {}, {}}, inverted), std::invalid_argument);
  EXPECT_THROW(Framebuffer(-1, 8), std::invalid_argument);
  EXPECT_THROW(Framebuffer(8, kMaxTargetSize + 1), std::invalid_argument);
}

// Float options outside their domain (draw.hpp) throw, whatever the shading, rather than draw
// black or unlit; the values at the ends of each domain are accepted.
TEST_P(RenderApi, FloatOptionsOutsideTheirDomainThrow) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const std::vector<Vec3> positions = {{1, 1, -0.5f}, {6, 1, -0.5f}, {1, 6, -0.5f}};
  const std::vector<Vec3> normals(3, Vec3{0, 0, 1});
  const DrawMesh mesh{positions, {}, normals, {}};
  Framebuffer target(8, 8);
  for (Shading shading : {Shading::diffuse, Shading::gouraud}) {
    DrawOptions options = ortho_options(isa());
    options.shading = shading;
    for (float ambient : {nan, -nan, inf, -inf, -0.01f, 1.01f}) {
      options.ambient = ambient;
      EXPECT_THROW(draw(target, mesh, options), std::invalid_argument)
          << name_of(shading) << ", ambient " << ambient;
    }
    for (float ambient : {0.0f, 1.0f}) {
      options.ambient = ambient;
      EXPECT_NO_THROW(draw(target, mesh, options)) << "ambient " << ambient;
    }
    options.ambient = 0.15f;
    for (const Vec3& light : {Vec3{nan, 0, 1}, Vec3{0, inf, 1}, Vec3{0, 0, -inf}}) {
      options.light_direction = light;
      EXPECT_THROW(draw(target, mesh, options), std::invalid_argument)
          << name_of(shading) << ", light " << light.x << " " << light.y << " " << light.z;
    }
    // No direct light, ambient only; and directions of any finite length.
    for (const Vec3& light : {Vec3{0, 0, 0}, Vec3{1e-40f, 0, 0}, Vec3{3e38f, 3e38f, 3e38f}}) {
      options.light_direction = light;
      EXPECT_NO_THROW(draw(target, mesh, options)) << light.x << " " << light.y << " " << light.z;
    }
  }
  DrawOptions options = ortho_options(isa());
  options.ambient = nan;
  try {
    draw(target, mesh, options);
    ADD_FAILURE() << "a NaN ambient term was accepted";
  } catch (const std::invalid_argument& e) {
    EXPECT_EQ(std::string(e.what()).rfind("draw: the ambient term", 0), 0u) << e.what();
  }
}

TEST_P(RenderApi, EmptyTargetAndEmptyMeshDrawNothing) {
  Framebuffer empty(0, 0);
  const std::vector<Vec3> positions = {{0, 0, -0.5f}, {8, 0, -0.5f}, {0, 8, -0.5f}};
  const DrawReport report = draw(empty, {positions, {}, {}, {}}, ortho_options(isa()));
  EXPECT_EQ(report.fragments, 0u);
  Framebuffer target(8, 8);
  EXPECT_EQ(draw(target, {}, ortho_options(isa())).triangles, 0u);
}

TEST_P(RenderApi, TriangleCrossingTheEyePlaneKeepsItsVisiblePart) {
  // A floor triangle from behind the camera (w < 0) to far ahead: without near clipping its
  // projection would wrap around; clipped, it covers the bottom of the view and nothing above the
  // horizon, and every written depth is in [0, 1].
  const std::int32_t size = 64;
  const std::vector<Vec3> positions = {{-50, -1, 10}, {50, -1, 10}, {0, -1, -60}};
  DrawOptions options;
  options.transform = perspective(1.2f, 1.0f, 0.1f, 100.0f);
  options.isa = isa();
  Framebuffer target(size, size);
  target.clear({0, 0, 0, 1}, 1.0f);
  const DrawReport report = draw(target, {positions, {}, {}, {}}, options);
  EXPECT_EQ(report.clipped, 1u);
  EXPECT_GT(report.fragments, static_cast<std::uint64_t>(size * size / 4));
  for (int y = 0; y < size; ++y) {
    for (int x = 0; x < size; ++x) {
      const bool drawn = target.depth(x, y) < 1.0f;
      if (y < size / 2) {
        EXPECT_FALSE(drawn) << x << "," << y;  // above the horizon
      }
      EXPECT_GE(target.depth(x, y), 0.0f);
    }
  }
  EXPECT_TRUE(target.depth(size / 2, size - 1) < 1.0f);  // the floor right below the camera
}

TEST_P(RenderApi, FlatShadingTakesTheFirstVertexColour) {
  const std::vector<Vec3> positions = {
      {0.5f, 0.5f, -0.5f}, {7.5f, 1.0f, -0.2f}, {1.0f, 7.5f, -0.9f}};
  const std::vector<Vec4> colors = {{0.2f, 0.4f, 0.6f, 1.0f}, {1, 0, 0, 1}, {0, 1, 0, 1}};
  DrawOptions options = ortho_options(isa());
  options.shading = Shading::flat;
  Framebuffer target(8, 8);
  target.clear({0, 0, 0, 0}, 1.0f);
  const DrawReport report = draw(target, {positions, colors, {}, {}}, options);
  ASSERT_GT(report.fragments_passed, 20u);
  std::uint64_t flat = 0;
  for (int y = 0; y < 8; ++y) {
    for (int x = 0; x < 8; ++x) {
      if (target.depth(x, y) == 1.0f) continue;
      EXPECT_EQ(target.color(x, y), pack_rgba8(colors[0])) << x << "," << y;
      ++flat;
    }
  }
  EXPECT_EQ(flat, report.fragments_passed);
}

// Quads covering a 32x32 target at the given depths (view z = -depth), drawn in order.
std::vector<Vec3> stacked_quads(std::initializer_list<float> depths) {
  std::vector<Vec3> positions;
  for (float d : depths) {
    const float z = -d;
    for (const Vec3& p : {Vec3{0, 0, z}, Vec3{32, 0, z}, Vec3{0, 32, z}, Vec3{32, 0, z},
                          Vec3{32, 32, z}, Vec3{0, 32, z}}) {
      positions.push_back(p);
    }
  }
  return positions;
}

DrawOptions stack_options(Isa isa) {
  DrawOptions options;
  options.transform = orthographic(0.0f, 32.0f, 32.0f, 0.0f, 0.0f, 1.0f);
  options.isa = isa;
  return options;
}

struct Frame {
  std::vector<std::uint8_t> rgba = std::vector<std::uint8_t>(32 * 32 * 4);
  std::vector<float> depth = std::vector<float>(32 * 32);
};

Frame read(const Framebuffer& target) {
  Frame frame;
  target.read_rgba8(frame.rgba);
  target.read_depth(frame.depth);
  return frame;
}

TEST_P(RenderApi, HiddenTilesAreSkippedWithTheSameResult) {
  // Front to back: the second and third quads are hidden everywhere. Each quad's two triangles
  // reach 10 of the 16 tiles each (6 whole, 4 along the diagonal): 40 tile visits to skip.
  const std::vector<Vec3> positions = stacked_quads({0.2f, 0.5f, 0.8f});
  std::vector<Vec4> colors;
  for (int q = 0; q < 3; ++q)
    colors.insert(colors.end(), 6, Vec4{0.3f * static_cast<float>(q), 0.5f, 1.0f, 1.0f});
  for (DepthTest test : {DepthTest::less, DepthTest::less_equal}) {
    DrawOptions options = stack_options(isa());
    options.depth_test = test;
    Framebuffer with(32, 32), without(32, 32), reference(32, 32);
    for (Framebuffer* f : {&with, &without, &reference})
      f->clear({0, 0, 0, 1}, 1.0f);
    const DrawReport report = draw(with, {positions, colors, {}, {}}, options);
    options.hierarchical_depth = false;
    const DrawReport plain = draw(without, {positions, colors, {}, {}}, options);
    options.isa = Isa::reference;
    draw(reference, {positions, colors, {}, {}}, options);
    if (isa() != Isa::reference) {
      EXPECT_EQ(report.statistics.tiles_skipped, 40u);
    }
    EXPECT_EQ(plain.statistics.tiles_skipped, 0u);
    EXPECT_EQ(report.fragments, plain.fragments);
    EXPECT_EQ(report.fragments_passed, plain.fragments_passed);
    EXPECT_EQ(read(with).rgba, read(reference).rgba);
    EXPECT_EQ(read(with).depth, read(reference).depth);
    EXPECT_EQ(read(without).depth, read(reference).depth);
  }
}

TEST_P(RenderApi, DepthBoundsFollowEveryWayDepthChanges) {
  // Each step changes the stored depth another way; a stale bound would skip the last quad.
  const std::vector<Vec3> near = stacked_quads({0.2f}), far = stacked_quads({0.6f});
  for (int way = 0; way < 3; ++way) {
    Framebuffer fast(32, 32), reference(32, 32);
    for (Framebuffer* f : {&fast, &reference}) {
      f->clear({0, 0, 0, 1}, 1.0f);
      DrawOptions options = stack_options(f == &fast ? isa() : Isa::reference);
      draw(*f, {near, {}, {}, {}}, options);  // depth 0.2 everywhere
      if (way == 0) {
        for (int i = 0; i < 32 * 32; ++i)
          f->depth_tiles()[i] = 1.0f;  // written directly
      } else if (way == 1) {
        options.depth_test = DepthTest::always;  // raised by a draw
        draw(*f, {stacked_quads({0.9f}), {}, {}, {}}, options);
      } else {
        options.depth_test = DepthTest::greater;
        draw(*f, {stacked_quads({0.7f}), {}, {}, {}}, options);
      }
      options.depth_test = DepthTest::less;
      const std::vector<Vec4> red(6, Vec4{1, 0, 0, 1});
      const DrawReport report = draw(*f, {far, red, {}, {}}, options);
      EXPECT_EQ(report.fragments_passed, 32u * 32u) << "way " << way;
    }
    EXPECT_EQ(read(fast).rgba, read(reference).rgba) << "way " << way;
    EXPECT_EQ(read(fast).depth, read(reference).depth) << "way " << way;
  }
}

TEST(Framebuffer, TiledLayoutRoundTrips) {
  Framebuffer target(13, 9);
  EXPECT_EQ(target.tiles_x(), 2);
  EXPECT_EQ(target.tiles_y(), 2);
  EXPECT_EQ(detail::FramebufferAccess::index(target, 0, 0), 0u);
  EXPECT_EQ(detail::FramebufferAccess::index(target, 7, 7), 63u);
  EXPECT_EQ(detail::FramebufferAccess::index(target, 8, 0), 64u);
  EXPECT_EQ(detail::FramebufferAccess::index(target, 0, 8), 128u);
  EXPECT_EQ(detail::FramebufferAccess::index(target, 12, 8), 3u * 64 + 4);
  target.color_tiles()[detail::FramebufferAccess::index(target, 12, 8)] = 0x04030201;
  std::vector<std::uint8_t> rgba(13 * 9 * 4);
  target.read_rgba8(rgba);
  const std::size_t p = (8 * 13 + 12) * 4;
  EXPECT_EQ(rgba[p], 1);
  EXPECT_EQ(rgba[p + 3], 4);
  std::vector<std::uint8_t> wrong(5);
  EXPECT_THROW(target.read_rgba8(wrong), std::invalid_argument);
  EXPECT_EQ(pack_rgba8({1.0f, 0.0f, 0.5f, 2.0f}), 0xFF8000FFu);
  EXPECT_EQ(pack_rgba8({std::numeric_limits<float>::quiet_NaN(), -1.0f, 0.0f, 1.0f}), 0xFF000000u);
}

EDGEWISE_INSTANTIATE_PER_ISA(RenderApi, every_isa());

}  // namespace
}  // namespace edgewise::test
