// Textured draw(): every ISA against the scalar reference, for every filter, both derivative
// methods and both perspective modes. Depth must be identical; colours must lie within the bound
// of tests/draw/textured_bounds.hpp (derived there), built from the sampler's bound
// (tests/texture/sample_bounds.hpp) and the shading colour bound (tests/draw/colour_bounds.hpp),
// with each pixel's query recomputed by the kernels' formula
// (kernels/draw/shading/texture_planes.hpp) and its untextured colour taken from the reference
// render of the same triangle without texture.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <iostream>
#include <string>
#include <vector>

#include "edgewise/draw.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "draw/colour_bounds.hpp"
#include "draw/draw_scenes.hpp"
#include "draw/textured_bounds.hpp"
#include "draw/shading/texture_planes.hpp"

namespace edgewise::test::textured_draw {
namespace {

constexpr std::int32_t kWidth = 96, kHeight = 72;

// Random texels: the worst case for a wrong query (neighbours are unrelated), and not a power of
// two on either axis.
Texture random_texture(Random& random, ColorEncoding encoding) {
  const std::int32_t width = 52, height = 36;
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(width) * height * 4);
  for (std::uint8_t& v : texels)
    v = static_cast<std::uint8_t>(random.integer(0, 255));
  return Texture::from_rgba8(width, height, texels, encoding, {PyramidFilter::box, true, true});
}

struct Case {
  TextureFilter filter;
  TextureDerivatives derivatives;
  Perspective perspective;
  Shading shading;
  InterpolationMethod method;
  FilterPrecision precision = FilterPrecision::automatic;
};

std::string describe(const Case& c) {
  return std::string(name_of(c.filter)) + " " + std::string(name_of(c.derivatives)) + " " +
         std::string(name_of(c.perspective)) + " " + std::string(name_of(c.shading)) + " " +
         std::string(name_of(c.method)) + " " + std::string(name_of(c.precision));
}

// The colour bound for a pixel of `one` (tests/draw/colour_bounds.hpp): flat shading is the
// Gouraud case of one-hot weights on vertex 0 without the perspective step.
double colour_error_at(const Case& c, const Scene& one, const ScreenTriangle& tri,
                       const DrawOptions& options, double px, double py) {
  const VertexAttributes attributes = attributes_of(one, 0);
  if (c.shading == Shading::flat) {
    return colour_error(attributes, one_hot_weight_errors(0, Perspective::affine, tri),
                        Shading::gouraud, options.ambient);
  }
  if (c.method == InterpolationMethod::plane_equations) {
    return plane_shading_error(tri, attributes, c.perspective, c.shading, options.ambient, px, py);
  }
  return colour_error(attributes, weight_errors(c.method, c.perspective, tri, px, py), c.shading,
                      options.ambient);
}

struct Totals {
  std::uint64_t pixels = 0;
  std::uint64_t differing = 0;  // pixels where fast and reference codes differ at all
};

// Each triangle of `scene` alone, so that every written pixel comes from a known triangle.
void check_case(Isa isa, const Case& c, const Scene& scene, const Texture& texture,
                Totals& totals) {
  DrawOptions options = perspective_options(kWidth, kHeight);
  options.interpolation = c.method;
  options.perspective = c.perspective;
  options.shading = c.shading;
  DrawOptions untextured = options;
  options.texture = DrawTexture{&texture, {}, c.derivatives};
  options.texture->sampler.filter = c.filter;
  options.texture->sampler.max_anisotropy = 8;
  options.texture->sampler.supersample_taps = 3;
  options.texture->sampler.precision = c.precision;
  const TexturedPixelCheck check(texture, options.texture->sampler);
  const Viewport viewport{kWidth, kHeight};
  for (std::size_t t = 0; t < scene.positions.size() / 3; ++t) {
    const Scene one = triangle_of(scene, t);
    const ScreenTriangle tri = screen_triangle(one, 0, options, viewport);
    Vec2 p[3], uv[3];
    for (int i = 0; i < 3; ++i) {
      p[i] = {static_cast<float>(tri.x[i]), static_cast<float>(tri.y[i])};
      uv[i] = one.uvs[i];
    }
    const detail::TexturePlanes planes = detail::make_texture_planes(p, uv, tri.w, c.perspective);
    const ShadedRange shaded = shaded_range(attributes_of(one, 0), c.shading, options.ambient);
    const Rendered expected = render(Isa::reference, one, options, kWidth, kHeight);
    const Rendered actual = render(isa, one, options, kWidth, kHeight);
    const Rendered plain = render(Isa::reference, one, untextured, kWidth, kHeight);
    ASSERT_EQ(actual.depth, expected.depth) << describe(c) << " triangle " << t;
    for (std::int32_t y = 0; y < kHeight; ++y) {
      for (std::int32_t x = 0; x < kWidth; ++x) {
        const std::size_t at = static_cast<std::size_t>(y) * kWidth + x;
        if (expected.depth[at] == 1.0f) continue;  // not drawn
        const TextureQuery query = detail::texture_query(planes, c.derivatives, x, y);
        const double e = colour_error_at(c, one, tri, options, x + 0.5, y + 0.5);
        const std::vector<CodeRanges> allowed =
            check.allowed(query, &plain.rgba[4 * at], shaded, e);
        // The reference itself at this query: its code is one of the accepted ones, exactly.
        const std::uint8_t* ref = &expected.rgba[4 * at];
        ASSERT_LE(TexturedPixelCheck::excess(allowed, ref), 0.0)
            << "reference, " << describe(c) << " triangle " << t << " pixel " << x << "," << y;
        const std::uint8_t* got = &actual.rgba[4 * at];
        ASSERT_LE(TexturedPixelCheck::excess(allowed, got), 0.0)
            << describe(c) << " triangle " << t << " pixel " << x << "," << y << " got "
            << int{got[0]} << "," << int{got[1]} << "," << int{got[2]} << "," << int{got[3]}
            << " reference " << int{ref[0]} << "," << int{ref[1]} << "," << int{ref[2]} << ","
            << int{ref[3]};
        ++totals.pixels;
        totals.differing += !std::equal(got, got + 4, ref);
      }
    }
  }
}

using TexturedRender = IsaTest;

// White flat shading: the colour is the texel alone, so this checks the queries and the filters.
// Triangles span up to 40 texture periods (strong minification, every wrap) or a fraction of one
// (magnification).
TEST_P(TexturedRender, EveryFilterWithinTheSamplerBound) {
  Random random(41);
  const Texture texture = random_texture(random, ColorEncoding::linear);
  Scene scene = random_scene(random, 16, static_cast<double>(kWidth) / kHeight, 0.4, 1.2);
  add_uvs(random, scene, 0.05, 40.0);
  for (Vec4& c : scene.colors)
    c = {1.0f, 1.0f, 1.0f, 1.0f};
  Totals totals;
  for (int f = 0; f <= static_cast<int>(TextureFilter::ewa); ++f) {
    for (TextureDerivatives d : {TextureDerivatives::quad, TextureDerivatives::analytic}) {
      for (Perspective perspective : {Perspective::correct, Perspective::affine}) {
        Case c{static_cast<TextureFilter>(f), d, perspective, Shading::flat,
               InterpolationMethod::plane_equations};
        ASSERT_NO_FATAL_FAILURE(check_case(isa(), c, scene, texture, totals));
        // The other precision of the linear texture's taps, on one combination.
        if (reads_bilinear_taps(c.filter) && d == TextureDerivatives::quad &&
            perspective == Perspective::correct) {
          c.precision = default_precision(c.filter) == FilterPrecision::fixed16
                            ? FilterPrecision::float32
                            : FilterPrecision::fixed16;
          ASSERT_NO_FATAL_FAILURE(check_case(isa(), c, scene, texture, totals));
        }
      }
    }
  }
  EXPECT_GT(totals.pixels, 40000u);
  std::cout << totals.pixels << " pixels, " << totals.differing << " differ\n";
}

// Shaded colours times the texture (sRGB-decoded): every shading model, the colour-plane path
// and a weights path.
TEST_P(TexturedRender, ShadedColoursTimesTheTextureWithinTheBound) {
  Random random(43);
  const Texture texture = random_texture(random, ColorEncoding::srgb);
  Scene scene = random_scene(random, 16, static_cast<double>(kWidth) / kHeight, 0.4, 1.2);
  add_uvs(random, scene, 0.1, 10.0);
  Totals totals;
  for (TextureFilter filter :
       {TextureFilter::bilinear, TextureFilter::trilinear, TextureFilter::anisotropic}) {
    for (Shading shading : {Shading::flat, Shading::gouraud, Shading::diffuse}) {
      for (InterpolationMethod method :
           {InterpolationMethod::plane_equations, InterpolationMethod::edge_functions}) {
        if (shading == Shading::flat && method != InterpolationMethod::plane_equations) continue;
        const Case c{filter, TextureDerivatives::quad, Perspective::correct, shading, method};
        ASSERT_NO_FATAL_FAILURE(check_case(isa(), c, scene, texture, totals));
      }
    }
  }
  EXPECT_GT(totals.pixels, 20000u);
  std::cout << totals.pixels << " pixels, " << totals.differing << " differ\n";
}

EDGEWISE_INSTANTIATE_PER_ISA(TexturedRender, every_isa());

// AVX-512 filters the bilinear taps 16 lanes at a time and samples tile rows in pairs, AVX2 8
// lanes a row at a time: the same float operations per query, so the images are identical bit
// for bit, one sample or four per pixel, every filter made of taps in both precisions, drawn
// over each other with depth tests.
TEST(TexturedWidth, Avx512DrawsTheAvx2ImageBitForBit) {
  if (!isa_supported(Isa::avx512) || !isa_supported(Isa::avx2)) {
    GTEST_SKIP() << "this CPU lacks AVX-512 or AVX2";
  }
  Random random(47);
  const Texture linear = random_texture(random, ColorEncoding::linear);
  const Texture srgb = random_texture(random, ColorEncoding::srgb);
  Scene scene = random_scene(random, 40, static_cast<double>(kWidth) / kHeight, 0.05, 1.2);
  add_uvs(random, scene, 0.05, 40.0);
  std::uint64_t passed = 0;
  for (const Texture* texture : {&linear, &srgb}) {
    for (int f = 0; f <= static_cast<int>(TextureFilter::ewa); ++f) {
      if (!reads_bilinear_taps(static_cast<TextureFilter>(f))) continue;
      for (FilterPrecision precision : {FilterPrecision::float32, FilterPrecision::fixed16}) {
        for (int samples : {1, 4}) {
          DrawOptions options = perspective_options(kWidth, kHeight);
          options.shading = Shading::gouraud;
          options.texture = DrawTexture{texture, {}, TextureDerivatives::quad};
          options.texture->sampler.filter = static_cast<TextureFilter>(f);
          options.texture->sampler.max_anisotropy = 8;
          options.texture->sampler.precision = precision;
          const Rendered avx2 = render(Isa::avx2, scene, options, kWidth, kHeight, samples);
          const Rendered avx512 = render(Isa::avx512, scene, options, kWidth, kHeight, samples);
          const std::string where = std::string(name_of(options.texture->sampler.filter)) + " " +
                                    std::string(name_of(precision)) + " " +
                                    std::to_string(samples) + " samples" +
                                    (texture == &srgb ? " srgb" : " linear");
          ASSERT_EQ(avx512.depth, avx2.depth) << where;
          ASSERT_EQ(avx512.rgba, avx2.rgba) << where;
          passed += avx2.report.fragments_passed;
        }
      }
    }
  }
  EXPECT_GT(passed, 100000u);  // enough drawn pixels to decide something
}

}  // namespace
}  // namespace edgewise::test::textured_draw
