// draw(): every ISA against the scalar reference. Depth-test outcomes and depth values must be
// identical (the shared depth formula); colours must lie within a bound derived from the
// interpolation error bounds (tests/draw/colour_bounds.hpp); report counts must match.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <string>
#include <vector>

#include "edgewise/camera.hpp"
#include "edgewise/draw.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "draw/colour_bounds.hpp"
#include "draw/draw_scenes.hpp"

namespace edgewise::test {
namespace {

using Render = IsaTest;

TEST_P(Render, SceneDepthAndCountsEqualTheReference) {
  Random random(20261121);
  const std::int32_t width = 157, height = 101;  // not whole tiles
  const Scene scene = random_scene(random, 400, static_cast<double>(width) / height);
  for (DepthTest test : {DepthTest::less, DepthTest::less_equal, DepthTest::greater,
                         DepthTest::always, DepthTest::never}) {
    for (bool write : {true, false}) {
      DrawOptions options = perspective_options(width, height);
      options.depth_test = test;
      options.depth_write = write;
      const Rendered expected = render(Isa::reference, scene, options, width, height);
      const Rendered actual = render(isa(), scene, options, width, height);
      const std::string where = std::string(name_of(test)) + (write ? "" : " no write");
      EXPECT_EQ(actual.report.fragments, expected.report.fragments) << where;
      EXPECT_EQ(actual.report.fragments_passed, expected.report.fragments_passed) << where;
      EXPECT_EQ(actual.report.rasterized, expected.report.rasterized) << where;
      EXPECT_EQ(actual.report.culled, expected.report.culled) << where;
      ASSERT_EQ(actual.depth, expected.depth) << where;  // bit for bit
      if (test == DepthTest::never) {
        EXPECT_EQ(actual.report.fragments_passed, 0u);
      }
      if (test == DepthTest::always) {
        EXPECT_EQ(actual.report.fragments_passed, actual.report.fragments);
      }
      EXPECT_GT(expected.report.fragments, 10000u);
    }
  }
}

// One triangle at a time, so that every written pixel comes from a known triangle: colours of
// every method, both perspective modes and every shading model within the derived bound.
TEST_P(Render, ColoursWithinTheDerivedBound) {
  Random random(7);
  const std::int32_t width = 128, height = 96;
  const Viewport viewport{width, height};
  const Scene scene = random_scene(random, 60, static_cast<double>(width) / height);
  std::uint64_t pixels = 0;
  int widest = 0;
  for (std::size_t t = 0; t < scene.positions.size() / 3; ++t) {
    const Scene one = triangle_of(scene, t);
    DrawOptions options = perspective_options(width, height);
    const ScreenTriangle tri = screen_triangle(one, 0, options, viewport);
    for (InterpolationMethod method : kInterpolationMethods) {
      if (method == InterpolationMethod::nearest_vertex) continue;  // discontinuous: below
      for (Perspective perspective : {Perspective::correct, Perspective::affine}) {
        for (Shading shading : {Shading::gouraud, Shading::diffuse}) {
          options.interpolation = method;
          options.perspective = perspective;
          options.shading = shading;
          const Rendered expected = render(Isa::reference, one, options, width, height);
          const Rendered actual = render(isa(), one, options, width, height);
          ASSERT_EQ(actual.depth, expected.depth);
          for (std::int32_t y = 0; y < height; ++y) {
            for (std::int32_t x = 0; x < width; ++x) {
              const std::size_t p = static_cast<std::size_t>(y) * width + x;
              if (expected.depth[p] == 1.0f && actual.depth[p] == 1.0f) continue;  // not drawn
              // The plane path: colour (and diffuse's normals) from planes.
              const bool planes = method == InterpolationMethod::plane_equations;
              const int allowed =
                  planes ? plane_shading_codes(tri, attributes_of(one, 0), perspective, shading,
                                               options.ambient, x + 0.5, y + 0.5)
                         : allowed_codes(attributes_of(one, 0),
                                         weight_errors(method, perspective, tri, x + 0.5, y + 0.5),
                                         shading, options.ambient);
              widest = std::max(widest, allowed);
              for (int k = 0; k < 4; ++k) {
                const int difference = std::abs(actual.rgba[4 * p + k] - expected.rgba[4 * p + k]);
                ASSERT_LE(difference, allowed)
                    << "triangle " << t << " pixel " << x << "," << y << " channel " << k << " "
                    << name_of(method) << " " << name_of(perspective) << " " << name_of(shading);
              }
              ++pixels;
            }
          }
        }
      }
    }
  }
  EXPECT_GT(pixels, 50000u);
  // The bound is informative: with these well-shaped triangles it allows one code almost always.
  EXPECT_LE(widest, 3);
}

TEST_P(Render, NearestVertexTakesAVertexColour) {
  Random random(11);
  const std::int32_t width = 64, height = 64;
  const Scene scene = random_scene(random, 30, 1.0);
  DrawOptions options = perspective_options(width, height);
  options.interpolation = InterpolationMethod::nearest_vertex;
  options.depth_test = DepthTest::always;
  for (std::size_t t = 0; t < scene.positions.size() / 3; ++t) {
    const Scene one = triangle_of(scene, t);
    const Rendered actual = render(isa(), one, options, width, height);
    std::uint32_t vertex_codes[3];
    for (int i = 0; i < 3; ++i)
      vertex_codes[i] = pack_rgba8(one.colors[i]);
    for (std::size_t p = 0; p < actual.depth.size(); ++p) {
      if (actual.depth[p] == 1.0f) continue;
      const std::uint32_t code = actual.rgba[4 * p] | actual.rgba[4 * p + 1] << 8 |
                                 actual.rgba[4 * p + 2] << 16 |
                                 static_cast<std::uint32_t>(actual.rgba[4 * p + 3]) << 24;
      EXPECT_TRUE(code == vertex_codes[0] || code == vertex_codes[1] || code == vertex_codes[2])
          << "triangle " << t << " pixel " << p;
    }
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(Render, every_isa());

}  // namespace
}  // namespace edgewise::test
