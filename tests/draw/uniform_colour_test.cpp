// Triangles whose three vertices share one colour: the plane path uses that colour as it is
// (shade_colour-inl.hpp), so Gouraud writes exactly its 8-bit code on a single-sample target (on a
// multisampled one, the reference's colour within its bound), and diffuse light stays within
// the derived bound of the reference; depth and counts equal the reference's as always.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <string>

#include "draw/colour_bounds.hpp"
#include "draw/draw_scenes.hpp"
#include "edgewise/draw.hpp"
#include "isa_params.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

// The scene with each triangle's three vertices given its first vertex's colour.
Scene with_one_colour_per_triangle(Scene scene) {
  for (std::size_t v = 0; v < scene.colors.size(); ++v)
    scene.colors[v] = scene.colors[v - v % 3];
  return scene;
}

std::uint8_t code_of(float value) {
  return static_cast<std::uint8_t>(std::lrint(255.0f * value));
}

using UniformColour = IsaTest;

TEST_P(UniformColour, GouraudWritesTheColoursCode) {
  Random random(31);
  const std::int32_t width = 128, height = 96;
  const Scene scene = with_one_colour_per_triangle(
      random_scene(random, 150, static_cast<double>(width) / height, 0.05));
  std::uint64_t pixels = 0;
  for (std::size_t t = 0; t < scene.positions.size() / 3; ++t) {
    const Scene one = triangle_of(scene, t);
    const Vec4 colour = one.colors[0];
    const std::uint8_t expected[4] = {code_of(colour.x), code_of(colour.y), code_of(colour.z),
                                      code_of(colour.w)};
    for (Perspective perspective : {Perspective::correct, Perspective::affine}) {
      for (int samples : {1, 4}) {
        DrawOptions options = perspective_options(width, height);
        options.perspective = perspective;
        options.shading = Shading::gouraud;
        const Rendered drawn = render(isa(), one, options, width, height, samples);
        // With several samples a pixel is shaded at its centre, which may lie outside the
        // triangle, where the weights, kept from falling below the smallest vertex 1 / w, scale
        // the colour down as the reference's do: there the reference's colour, within the
        // planes' bound.
        const Rendered reference =
            samples == 1 ? Rendered{}
                         : render(Isa::reference, one, options, width, height, samples);
        const ScreenTriangle tri = screen_triangle(one, 0, options, Viewport{width, height});
        const auto per_sample = static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
        for (std::size_t p = 0; p < drawn.depth.size(); ++p) {
          if (drawn.depth[p] == 1.0f) continue;  // not drawn
          const auto x =
              static_cast<std::int32_t>(p % per_sample % static_cast<std::size_t>(width));
          const auto y =
              static_cast<std::int32_t>(p % per_sample / static_cast<std::size_t>(width));
          for (int k = 0; k < 4; ++k) {
            const std::string where = "triangle " + std::to_string(t) + " sample value " +
                                      std::to_string(p) + " channel " + std::to_string(k) + " " +
                                      std::string(name_of(perspective)) + ", " +
                                      std::to_string(samples) + " samples";
            if (samples == 1) {
              ASSERT_EQ(drawn.rgba[4 * p + k], expected[k]) << where;
              continue;
            }
            const int allowed =
                plane_shading_codes(tri, attributes_of(one, 0), perspective, Shading::gouraud,
                                    options.ambient, x + 0.5, y + 0.5);
            ASSERT_LE(std::abs(drawn.rgba[4 * p + k] - reference.rgba[4 * p + k]), allowed)
                << where;
          }
          ++pixels;
        }
      }
    }
  }
  EXPECT_GT(pixels, 50000u);
}

TEST_P(UniformColour, DiffuseWithinTheDerivedBound) {
  Random random(37);
  const std::int32_t width = 128, height = 96;
  const Viewport viewport{width, height};
  const Scene scene = with_one_colour_per_triangle(
      random_scene(random, 150, static_cast<double>(width) / height, 0.05));
  std::uint64_t pixels = 0;
  for (std::size_t t = 0; t < scene.positions.size() / 3; ++t) {
    const Scene one = triangle_of(scene, t);
    DrawOptions options = perspective_options(width, height);
    const ScreenTriangle tri = screen_triangle(one, 0, options, viewport);
    for (Perspective perspective : {Perspective::correct, Perspective::affine}) {
      options.perspective = perspective;
      options.shading = Shading::diffuse;
      const Rendered expected = render(Isa::reference, one, options, width, height);
      const Rendered actual = render(isa(), one, options, width, height);
      ASSERT_EQ(actual.depth, expected.depth);
      for (std::int32_t y = 0; y < height; ++y) {
        for (std::int32_t x = 0; x < width; ++x) {
          const std::size_t p = static_cast<std::size_t>(y) * width + x;
          if (expected.depth[p] == 1.0f) continue;
          const int allowed =
              plane_shading_codes(tri, attributes_of(one, 0), perspective, Shading::diffuse,
                                  options.ambient, x + 0.5, y + 0.5);
          for (int k = 0; k < 4; ++k) {
            ASSERT_LE(std::abs(actual.rgba[4 * p + k] - expected.rgba[4 * p + k]), allowed)
                << "triangle " << t << " pixel " << x << "," << y << " channel " << k << " "
                << name_of(perspective);
          }
          ++pixels;
        }
      }
    }
  }
  EXPECT_GT(pixels, 8000u);
}

EDGEWISE_INSTANTIATE_PER_ISA(UniformColour, fast_isas());

}  // namespace
}  // namespace edgewise::test
