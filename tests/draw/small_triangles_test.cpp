// draw() of triangles within 8x8 and 16x16 pixels, the small-triangle path (block masks without
// the tile walk, the tile grid shaded a covered row at a time): on every ISA, depth and counts
// equal to the reference bit for bit, with hierarchical depth on and off and every depth test,
// for Gouraud and diffuse shading, and colours within the derived bound.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "draw/colour_bounds.hpp"
#include "draw/draw_scenes.hpp"
#include "edgewise/draw.hpp"
#include "edgewise/isa.hpp"
#include "isa_params.hpp"
#include "random.hpp"

namespace edgewise::test::small_triangles {
namespace {

using SmallTriangles = IsaTest;

constexpr std::int32_t kWidth = 192, kHeight = 144;

// Sizes from 0.005 to 0.1 of the view's height: about 0.7 to 14 pixels, many overlapping.
Scene small_scene(std::uint64_t seed, int triangles) {
  Random random(seed);
  return random_scene(random, triangles, static_cast<double>(kWidth) / kHeight, 0.005, 0.1);
}

// The small scene behind an occluder drawn first: two large triangles over the left half of the
// view at distance 4 (the small triangles lie between 0.6 and 32), whose tiles' depth bounds
// then hide many of the small triangles' tiles whole.
Scene occluded_small_scene(std::uint64_t seed, int triangles) {
  const double aspect = static_cast<double>(kWidth) / kHeight;
  const double half = std::tan(kFov / 2.0), distance = 4.0;
  const auto at = [&](double ndc_x, double ndc_y) {
    return Vec3{static_cast<float>(ndc_x * distance * half * aspect),
                static_cast<float>(ndc_y * distance * half), static_cast<float>(-distance)};
  };
  Scene scene;
  scene.positions = {at(-1, -1), at(0, -1), at(0, 1), at(-1, -1), at(0, 1), at(-1, 1)};
  scene.colors.assign(6, Vec4{0.5f, 0.5f, 0.5f, 1.0f});
  scene.normals.assign(6, Vec3{0.0f, 0.0f, 1.0f});
  const Scene small = small_scene(seed, triangles);
  scene.positions.insert(scene.positions.end(), small.positions.begin(), small.positions.end());
  scene.colors.insert(scene.colors.end(), small.colors.begin(), small.colors.end());
  scene.normals.insert(scene.normals.end(), small.normals.begin(), small.normals.end());
  return scene;
}

TEST_P(SmallTriangles, DepthAndCountsEqualTheReference) {
  const Scene scene = occluded_small_scene(21, 6000);
  for (Shading shading : {Shading::gouraud, Shading::diffuse}) {
    for (DepthTest test :
         {DepthTest::less, DepthTest::less_equal, DepthTest::greater, DepthTest::always}) {
      for (bool hierarchical : {true, false}) {
        DrawOptions options = perspective_options(kWidth, kHeight);
        options.shading = shading;
        options.depth_test = test;
        options.hierarchical_depth = hierarchical;
        const Rendered expected = render(Isa::reference, scene, options, kWidth, kHeight);
        const Rendered actual = render(isa(), scene, options, kWidth, kHeight);
        const std::string where = std::string(name_of(shading)) + " " + std::string(name_of(test)) +
                                  (hierarchical ? " hierarchical" : "");
        EXPECT_EQ(actual.report.fragments, expected.report.fragments) << where;
        EXPECT_EQ(actual.report.fragments_passed, expected.report.fragments_passed) << where;
        ASSERT_EQ(actual.depth, expected.depth) << where;  // bit for bit
        // The reference never skips tiles; the ISAs skip the occluder's hidden ones.
        EXPECT_EQ(actual.report.statistics.tiles_skipped > 0,
                  isa() != Isa::reference && hierarchical &&
                      (test == DepthTest::less || test == DepthTest::less_equal))
            << where;
        // The scene overdraws: under less, many fragments fail, so the test decides something.
        if (test == DepthTest::less) {
          EXPECT_LT(expected.report.fragments_passed, expected.report.fragments) << where;
        }
        EXPECT_GT(expected.report.fragments, 20000u) << where;
      }
    }
  }
}

TEST_P(SmallTriangles, ColoursWithinTheDerivedBound) {
  const Scene scene = small_scene(22, 300);
  const Viewport viewport{kWidth, kHeight};
  std::uint64_t pixels = 0;
  for (std::size_t t = 0; t < scene.positions.size() / 3; ++t) {
    const Scene one = triangle_of(scene, t);
    for (Perspective perspective : {Perspective::correct, Perspective::affine}) {
      for (Shading shading : {Shading::gouraud, Shading::diffuse}) {
        DrawOptions options = perspective_options(kWidth, kHeight);
        options.perspective = perspective;
        options.shading = shading;
        const ScreenTriangle tri = screen_triangle(one, 0, options, viewport);
        const Rendered expected = render(Isa::reference, one, options, kWidth, kHeight);
        const Rendered actual = render(isa(), one, options, kWidth, kHeight);
        ASSERT_EQ(actual.depth, expected.depth);
        for (std::int32_t y = 0; y < kHeight; ++y) {
          for (std::int32_t x = 0; x < kWidth; ++x) {
            const std::size_t p = static_cast<std::size_t>(y) * kWidth + x;
            if (expected.depth[p] == 1.0f) continue;  // not drawn
            const int allowed = plane_shading_codes(tri, attributes_of(one, 0), perspective,
                                                    shading, options.ambient, x + 0.5, y + 0.5);
            for (int k = 0; k < 4; ++k) {
              ASSERT_LE(std::abs(actual.rgba[4 * p + k] - expected.rgba[4 * p + k]), allowed)
                  << "triangle " << t << " pixel " << x << "," << y << " channel " << k << " "
                  << name_of(perspective) << " " << name_of(shading);
            }
            ++pixels;
          }
        }
      }
    }
  }
  EXPECT_GT(pixels, 3000u);
}

EDGEWISE_INSTANTIATE_PER_ISA(SmallTriangles, every_isa());

// AVX-512 shades colour from planes two tile rows per batch, AVX2 one row: the same float
// operations per pixel, so the two images are identical bit for bit, small triangles (the tile
// grid) and larger ones (the tile walk) alike, with colours that vary and one colour per
// triangle, under every depth test that writes through those rows.
TEST(RowPairs, Avx512DrawsTheAvx2ImageBitForBit) {
  if (!isa_supported(Isa::avx512) || !isa_supported(Isa::avx2)) {
    GTEST_SKIP() << "this CPU lacks AVX-512 or AVX2";
  }
  Random random(23);
  Scene varying = random_scene(random, 3000, static_cast<double>(kWidth) / kHeight, 0.005, 0.3);
  Scene uniform = varying;
  uniform.colors.assign(uniform.colors.size(), Vec4{0.8f, 0.6f, 0.4f, 1.0f});
  std::uint64_t passed = 0;
  for (const Scene* scene : {&varying, &uniform}) {
    for (Perspective perspective : {Perspective::correct, Perspective::affine}) {
      for (Shading shading : {Shading::gouraud, Shading::diffuse}) {
        for (DepthTest test : {DepthTest::less, DepthTest::less_equal, DepthTest::greater}) {
          DrawOptions options = perspective_options(kWidth, kHeight);
          options.perspective = perspective;
          options.shading = shading;
          options.depth_test = test;
          const Rendered avx2 = render(Isa::avx2, *scene, options, kWidth, kHeight);
          const Rendered avx512 = render(Isa::avx512, *scene, options, kWidth, kHeight);
          const std::string where = std::string(scene == &uniform ? "uniform " : "varying ") +
                                    std::string(name_of(perspective)) + " " +
                                    std::string(name_of(shading)) + " " +
                                    std::string(name_of(test));
          ASSERT_EQ(avx512.depth, avx2.depth) << where;
          ASSERT_EQ(avx512.rgba, avx2.rgba) << where;
          EXPECT_EQ(avx512.report.fragments_passed, avx2.report.fragments_passed) << where;
          passed += avx2.report.fragments_passed;
        }
      }
    }
  }
  EXPECT_GT(passed, 100000u);  // the images hold enough drawn pixels to decide something
}

}  // namespace
}  // namespace edgewise::test::small_triangles
