// draw() into multisampled targets (framebuffer.hpp, docs/design/anti-aliasing.md): every ISA
// against the scalar reference. Per-sample coverage, depth-test outcomes and depth values must be
// identical (the shared depth formula at each sample's position); each pixel is shaded once, so
// the samples a triangle writes in a pixel hold one colour, within the 1x colour bound of
// tests/draw/colour_bounds.hpp at the pixel centre.
#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <cstdlib>
#include <string>
#include <vector>

#include "edgewise/camera.hpp"
#include "edgewise/draw.hpp"
#include "edgewise/multisample.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "draw/colour_bounds.hpp"
#include "draw/draw_scenes.hpp"

namespace edgewise::test {
namespace {

using MultisampleRender = IsaTest;

constexpr int kSampleCounts[] = {2, 4, 8, 16};

std::size_t pixel_of(std::int32_t width, std::int32_t height, int sample, std::int32_t x,
                     std::int32_t y) {
  return (static_cast<std::size_t>(sample) * static_cast<std::size_t>(height) +
          static_cast<std::size_t>(y)) *
             static_cast<std::size_t>(width) +
         static_cast<std::size_t>(x);
}

TEST_P(MultisampleRender, SampleDepthAndCountsEqualTheReference) {
  Random random(20261127);
  const std::int32_t width = 93, height = 61;  // not whole tiles
  const Scene scene = random_scene(random, 150, static_cast<double>(width) / height);
  for (int samples : kSampleCounts) {
    for (DepthTest test : {DepthTest::less, DepthTest::greater, DepthTest::always}) {
      for (bool write : {true, false}) {
        DrawOptions options = perspective_options(width, height);
        options.depth_test = test;
        options.depth_write = write;
        const Rendered expected = render(Isa::reference, scene, options, width, height, samples);
        const Rendered actual = render(isa(), scene, options, width, height, samples);
        const std::string where = std::to_string(samples) + " samples, " +
                                  std::string(name_of(test)) + (write ? "" : " no write");
        EXPECT_EQ(actual.report.fragments, expected.report.fragments) << where;
        EXPECT_EQ(actual.report.fragments_passed, expected.report.fragments_passed) << where;
        EXPECT_EQ(actual.report.rasterized, expected.report.rasterized) << where;
        ASSERT_EQ(actual.depth, expected.depth) << where;  // bit for bit, every sample
        // Samples, not pixels: a multisampled target counts `samples` times the 1x fragments,
        // give or take the edges.
        EXPECT_GT(expected.report.fragments, 3000u * static_cast<unsigned>(samples)) << where;
      }
    }
  }
}

// The samples of a pixel: with one sample at the centre, drawn alone, a triangle covers the
// centre exactly when the multisampled draw's single sample does; with more, the samples
// written in one pixel by one triangle hold one colour (shaded once), within the 1x bound.
TEST_P(MultisampleRender, OneColourPerPixelWithinTheBound) {
  Random random(31);
  const std::int32_t width = 64, height = 48;
  const Viewport viewport{width, height};
  const Scene scene = random_scene(random, 30, static_cast<double>(width) / height, 0.1, 0.5);
  std::uint64_t checked = 0, edge_pixels = 0;
  for (std::size_t t = 0; t < scene.positions.size() / 3; ++t) {
    const Scene one = triangle_of(scene, t);
    for (Shading shading : {Shading::gouraud, Shading::diffuse}) {
      for (int samples : {4, 16}) {
        DrawOptions options = perspective_options(width, height);
        options.shading = shading;
        const ScreenTriangle tri = screen_triangle(one, 0, options, viewport);
        const Rendered expected = render(Isa::reference, one, options, width, height, samples);
        const Rendered actual = render(isa(), one, options, width, height, samples);
        ASSERT_EQ(actual.depth, expected.depth);
        for (std::int32_t y = 0; y < height; ++y) {
          for (std::int32_t x = 0; x < width; ++x) {
            const int allowed =
                plane_shading_codes(tri, attributes_of(one, 0), Perspective::correct, shading,
                                    options.ambient, x + 0.5, y + 0.5);
            int written = 0;
            const std::uint8_t* first = nullptr;
            for (int k = 0; k < samples; ++k) {
              const std::size_t p = pixel_of(width, height, k, x, y);
              if (expected.depth[p] == 1.0f) continue;  // this sample not drawn
              ++written;
              const std::uint8_t* got = &actual.rgba[4 * p];
              if (first == nullptr) first = got;
              for (int c = 0; c < 4; ++c) {
                ASSERT_EQ(got[c], first[c]) << "pixel " << x << "," << y << " sample " << k;
                ASSERT_LE(std::abs(got[c] - expected.rgba[4 * p + c]), allowed)
                    << "pixel " << x << "," << y << " sample " << k << " channel " << c << " got "
                    << int(got[c]) << " ref " << int(expected.rgba[4 * p + c]) << " t " << t
                    << " shading " << name_of(shading) << " samples " << samples << " written "
                    << written << " tri " << tri.x[0] << "," << tri.y[0] << " " << tri.x[1] << ","
                    << tri.y[1] << " " << tri.x[2] << "," << tri.y[2];
              }
              ++checked;
            }
            if (written != 0 && written != samples) ++edge_pixels;
          }
        }
      }
    }
  }
  EXPECT_GT(checked, 8000u);
  EXPECT_GT(edge_pixels, 500u);  // partly covered pixels, shaded at a centre maybe outside
}

// Hierarchical depth skips whole tiles of a multisampled target (bounded over every sample)
// without changing a sample: a near wall drawn first hides a scene drawn behind it.
TEST_P(MultisampleRender, HierarchicalDepthChangesNothing) {
  Random random(5);
  const std::int32_t width = 96, height = 64;
  Scene scene = random_scene(random, 80, static_cast<double>(width) / height);
  // The wall: two triangles across the view, nearer than every scene triangle, drawn first.
  // The scene lies from 0.6 (random_scene) to kFar away; the wall at 0.55 fills the view.
  const Vec3 wall[6] = {{-5, -5, -0.55f}, {5, -5, -0.55f}, {5, 5, -0.55f},
                        {-5, -5, -0.55f}, {5, 5, -0.55f},  {-5, 5, -0.55f}};
  scene.positions.insert(scene.positions.begin(), std::begin(wall), std::end(wall));
  scene.colors.insert(scene.colors.begin(), 6, Vec4{0.5f, 0.5f, 0.5f, 1.0f});
  scene.normals.insert(scene.normals.begin(), 6, Vec3{0.0f, 0.0f, 1.0f});
  for (int samples : {4, 8}) {
    DrawOptions options = perspective_options(width, height);
    options.hierarchical_depth = false;
    const Rendered plain = render(isa(), scene, options, width, height, samples);
    options.hierarchical_depth = true;
    const Rendered skipping = render(isa(), scene, options, width, height, samples);
    EXPECT_EQ(skipping.depth, plain.depth);
    EXPECT_EQ(skipping.rgba, plain.rgba);
    EXPECT_EQ(skipping.report.fragments_passed, plain.report.fragments_passed);
    if (isa() != Isa::reference) {
      EXPECT_GT(skipping.report.statistics.tiles_skipped, 0u);
    }
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(MultisampleRender, every_isa());

}  // namespace
}  // namespace edgewise::test
