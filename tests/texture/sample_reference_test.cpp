// The scalar reference sampler (kernels/texture/sample_reference.hpp) against hand-computed
// values and properties that follow from each filter's definition (sample.hpp):
// addressing, magnification, level of detail, every minification filter, and bad input.
//
// Rounding: u = 2^-53 is double's unit roundoff. Where a tolerance is not 0 its comment counts
// the roundings between the two sides (Higham's model: each operation adds u times the
// magnitude of its result).
#include <gtest/gtest.h>

#include <algorithm>
#include <array>
#include <cmath>
#include <cstdint>
#include <functional>
#include <limits>
#include <numbers>
#include <span>
#include <string>
#include <vector>

#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "random.hpp"
#include "texture/sample_reference.hpp"

namespace edgewise::test {
namespace {

using reference::Rgba;

constexpr double kU = 0x1p-53;
constexpr float kInfF = std::numeric_limits<float>::infinity();
constexpr float kNaNF = std::numeric_limits<float>::quiet_NaN();

constexpr WrapMode kWraps[] = {WrapMode::repeat, WrapMode::clamp_to_edge, WrapMode::mirror};

constexpr TextureFilter kAllFilters[] = {
    TextureFilter::nearest,         TextureFilter::bilinear,    TextureFilter::bicubic_catmull_rom,
    TextureFilter::bicubic_bspline, TextureFilter::mip_nearest, TextureFilter::trilinear,
    TextureFilter::supersample,     TextureFilter::ripmap,      TextureFilter::summed_area,
    TextureFilter::anisotropic,     TextureFilter::ewa};

bool reads_derivatives(TextureFilter filter) {
  return filter != TextureFilter::nearest && filter != TextureFilter::bilinear &&
         filter != TextureFilter::bicubic_catmull_rom && filter != TextureFilter::bicubic_bspline;
}

constexpr TextureBuild kFullBuild{.ripmaps = true, .summed_area_table = true};

using FloatTexel = std::array<float, 4>;
using CodeTexel = std::array<std::uint8_t, 4>;

Texture float_texture(int width, int height, const std::function<FloatTexel(int, int)>& texel,
                      const TextureBuild& build = {}) {
  std::vector<float> values;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const FloatTexel v = texel(x, y);
      values.insert(values.end(), v.begin(), v.end());
    }
  }
  return Texture::from_rgba32f(width, height, values, build);
}

Texture rgba8_texture(int width, int height, const std::function<CodeTexel(int, int)>& texel,
                      ColorEncoding encoding, const TextureBuild& build = {}) {
  std::vector<std::uint8_t> codes;
  for (int y = 0; y < height; ++y) {
    for (int x = 0; x < width; ++x) {
      const CodeTexel v = texel(x, y);
      codes.insert(codes.end(), v.begin(), v.end());
    }
  }
  return Texture::from_rgba8(width, height, codes, encoding, build);
}

// A texture of random float texels in [-1, 1].
Texture random_float_texture(int width, int height, std::uint64_t seed,
                             const TextureBuild& build = {}) {
  Random rng(seed);
  return float_texture(
      width, height,
      [&](int, int) {
        return FloatTexel{
            static_cast<float>(rng.uniform(-1, 1)), static_cast<float>(rng.uniform(-1, 1)),
            static_cast<float>(rng.uniform(-1, 1)), static_cast<float>(rng.uniform(-1, 1))};
      },
      build);
}

SamplerOptions options_for(TextureFilter filter, WrapMode wrap_s, WrapMode wrap_t) {
  SamplerOptions options;
  options.filter = filter;
  options.wrap_s = wrap_s;
  options.wrap_t = wrap_t;
  return options;
}

const TextureLevel& level0(const Texture& texture) {
  return texture.mip_levels().front();
}

Rgba level0_texel(const Texture& texture, std::int64_t x, std::int64_t y) {
  return reference::texel(texture, level0(texture), WrapMode::clamp_to_edge,
                          WrapMode::clamp_to_edge, x, y);
}

void expect_rgba_near(const Rgba& got, const Rgba& want, double tolerance,
                      const std::string& context = "") {
  for (int c = 0; c < 4; ++c) {
    EXPECT_NEAR(got[c], want[c], tolerance) << "channel " << c << " " << context;
  }
}

void expect_rgba_eq(const Rgba& got, const Rgba& want, const std::string& context = "") {
  for (int c = 0; c < 4; ++c)
    EXPECT_EQ(got[c], want[c]) << "channel " << c << " " << context;
}

// The query's six values by position (s, t, dsdx, dtdx, dsdy, dtdy), as in a query file.
float& field(TextureQuery& q, int index) {
  switch (index) {
    case 0:
      return q.s;
    case 1:
      return q.t;
    case 2:
      return q.dsdx;
    case 3:
      return q.dtdx;
    case 4:
      return q.dsdy;
    default:
      return q.dtdy;
  }
}

std::string describe(const TextureQuery& q) {
  return "query (" + std::to_string(q.s) + ", " + std::to_string(q.t) + ", " +
         std::to_string(q.dsdx) + ", " + std::to_string(q.dtdx) + ", " + std::to_string(q.dsdy) +
         ", " + std::to_string(q.dtdy) + ")";
}

std::string describe(TextureFilter filter, WrapMode wrap) {
  return std::string(name_of(filter)) + "/" + std::string(name_of(wrap));
}

// ---------------------------------------------------------------------------------------------
// Addressing

TEST(SampleReference, WrapIndexHandCases) {
  using reference::wrap_index;
  constexpr std::int64_t kMin = std::numeric_limits<std::int64_t>::min();
  constexpr std::int64_t kMax = std::numeric_limits<std::int64_t>::max();

  EXPECT_EQ(wrap_index(-1, 5, WrapMode::repeat), 4);
  EXPECT_EQ(wrap_index(-5, 5, WrapMode::repeat), 0);
  EXPECT_EQ(wrap_index(-6, 5, WrapMode::repeat), 4);
  EXPECT_EQ(wrap_index(5, 5, WrapMode::repeat), 0);
  EXPECT_EQ(wrap_index(12, 5, WrapMode::repeat), 2);
  EXPECT_EQ(wrap_index(kMin, 5, WrapMode::repeat), 2);  // -2^63 = -3 (mod 5)
  EXPECT_EQ(wrap_index(kMax, 5, WrapMode::repeat), 2);  // 2^63 - 1 = 2 (mod 5)

  EXPECT_EQ(wrap_index(-1, 5, WrapMode::clamp_to_edge), 0);
  EXPECT_EQ(wrap_index(kMin, 5, WrapMode::clamp_to_edge), 0);
  EXPECT_EQ(wrap_index(3, 5, WrapMode::clamp_to_edge), 3);
  EXPECT_EQ(wrap_index(5, 5, WrapMode::clamp_to_edge), 4);
  EXPECT_EQ(wrap_index(kMax, 5, WrapMode::clamp_to_edge), 4);

  // Mirror, n = 3: period 0 1 2 2 1 0, starting at every multiple of 6.
  const std::int64_t period[6] = {0, 1, 2, 2, 1, 0};
  for (std::int64_t i = -12; i < 12; ++i) {
    EXPECT_EQ(wrap_index(i, 3, WrapMode::mirror), period[((i % 6) + 6) % 6]) << "i = " << i;
  }
  EXPECT_EQ(wrap_index(kMax, 3, WrapMode::mirror), 1);  // 2^63 - 1 = 1 (mod 6)
  EXPECT_EQ(wrap_index(kMin, 3, WrapMode::mirror), 1);  // -2^63 = 4 (mod 6)

  for (WrapMode wrap : kWraps) {
    for (std::int64_t i : {kMin, std::int64_t{-7}, std::int64_t{0}, std::int64_t{9}, kMax}) {
      EXPECT_EQ(wrap_index(i, 1, wrap), 0) << name_of(wrap);
    }
  }
}

// The mirror rule against its geometric meaning: texel i's centre i + 1/2 folded into [0, n)
// by reflections at every multiple of n.
TEST(SampleReference, WrapIndexMatchesUnfolding) {
  for (std::int64_t n = 1; n <= 7; ++n) {
    for (std::int64_t i = -40; i <= 40; ++i) {
      double x = static_cast<double>(i) + 0.5;
      while (x < 0 || x >= static_cast<double>(n))
        x = x < 0 ? -x : 2.0 * n - x;
      EXPECT_EQ(reference::wrap_index(i, n, WrapMode::mirror), static_cast<std::int64_t>(x))
          << "n = " << n << ", i = " << i;
      const std::int64_t shifted = i + 100 * n;  // repeat: shifting by periods changes nothing
      EXPECT_EQ(reference::wrap_index(i, n, WrapMode::repeat), shifted % n);
    }
  }
}

TEST(SampleReference, TexelDecoding) {
  const Texture linear = rgba8_texture(
      2, 1,
      [](int x, int) {
        return CodeTexel{static_cast<std::uint8_t>(51 * x), 255, 0, 128};
      },
      ColorEncoding::linear);
  expect_rgba_eq(level0_texel(linear, 1, 0), {51.0 / 255.0, 1.0, 0.0, 128.0 / 255.0});

  const Texture floats = float_texture(1, 1, [](int, int) {
    return FloatTexel{0.1f, -3.0f, 1e20f, 0.5f};
  });
  expect_rgba_eq(level0_texel(floats, 0, 0), {double{0.1f}, -3.0, double{1e20f}, 0.5});

  // sRGB (IEC 61966-2-1) for R, G, B; alpha stays linear. The formula is written out again
  // here; both sides round pow once (1 ulp of a value <= 1) and a few exact-ish operations.
  std::vector<std::uint8_t> codes;
  for (int v = 0; v < 256; ++v)
    codes.insert(codes.end(), {std::uint8_t(v), std::uint8_t(v), std::uint8_t(v), std::uint8_t(v)});
  const Texture srgb = Texture::from_rgba8(256, 1, codes, ColorEncoding::srgb);
  for (int v = 0; v < 256; ++v) {
    const double c = v / 255.0;
    const double decoded = c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
    const Rgba got = level0_texel(srgb, v, 0);
    EXPECT_NEAR(got[0], decoded, 8 * kU) << "code " << v;
    EXPECT_EQ(got[1], got[0]);
    EXPECT_EQ(got[2], got[0]);
    EXPECT_EQ(got[3], c) << "code " << v;
  }
}

TEST(SampleReference, NearestPicksTheTexelAtBoundaries) {
  // R = x + 10 y on a 4 x 2 texture; t = 0.25 is row 0's centre.
  const Texture texture = float_texture(4, 2, [](int x, int y) {
    return FloatTexel{float(x + 10 * y), 0, 0, 1};
  });
  auto red = [&](WrapMode wrap, float s, float t) {
    return reference::nearest(texture, level0(texture), wrap, wrap, s, t)[0];
  };
  for (WrapMode wrap : kWraps) {
    EXPECT_EQ(red(wrap, 0.25f, 0.25f), 1) << name_of(wrap);       // s w = 1: texel 1
    EXPECT_EQ(red(wrap, std::nextafter(0.25f, 0.0f), 0.25f), 0);  // just below: texel 0
    EXPECT_EQ(red(wrap, 0.5f, 0.25f), 2);
    EXPECT_EQ(red(wrap, 0.0f, 0.25f), 0);
    EXPECT_EQ(red(wrap, 0.25f, 0.5f), 11);  // t h = 1: row 1
    EXPECT_EQ(red(wrap, 0.25f, std::nextafter(0.5f, 0.0f)), 1);
  }
  // Just left of 0: index -1; at 1: index 4; at 1.25: index 5.
  const float left = -1e-7f;
  EXPECT_EQ(red(WrapMode::repeat, left, 0.25f), 3);
  EXPECT_EQ(red(WrapMode::clamp_to_edge, left, 0.25f), 0);
  EXPECT_EQ(red(WrapMode::mirror, left, 0.25f), 0);
  EXPECT_EQ(red(WrapMode::repeat, 1.0f, 0.25f), 0);
  EXPECT_EQ(red(WrapMode::clamp_to_edge, 1.0f, 0.25f), 3);
  EXPECT_EQ(red(WrapMode::mirror, 1.0f, 0.25f), 3);
  EXPECT_EQ(red(WrapMode::repeat, 1.25f, 0.25f), 1);
  EXPECT_EQ(red(WrapMode::clamp_to_edge, 1.25f, 0.25f), 3);
  EXPECT_EQ(red(WrapMode::mirror, 1.25f, 0.25f), 2);
}

// ---------------------------------------------------------------------------------------------
// Bilinear and bicubic

TEST(SampleReference, BilinearIsExactAtTexelCentres) {
  // At a centre the weights are exactly 1 and 0, so the sum is the texel itself.
  const Texture texture = random_float_texture(4, 4, 11);
  for (WrapMode wrap : kWraps) {
    for (int b = 0; b < 4; ++b) {
      for (int a = 0; a < 4; ++a) {
        const double s = (a + 0.5) / 4, t = (b + 0.5) / 4;
        expect_rgba_eq(reference::bilinear(texture, level0(texture), wrap, wrap, s, t),
                       level0_texel(texture, a, b), std::string(name_of(wrap)));
      }
    }
  }
}

TEST(SampleReference, BilinearHandValues) {
  // Between two texels' centres the weights are 1/2: 0.5 a + 0.5 b rounds like (a + b) / 2,
  // since halving is exact. So every expectation below is exact.
  const Texture row = float_texture(4, 1, [](int x, int) {
    return FloatTexel{float(1 << x), 0, 0, 1};
  });
  auto red = [&](WrapMode wrap, double s) {
    return reference::bilinear(row, level0(row), wrap, wrap, s, 0.5)[0];
  };
  // Texels 1 2 4 8. s = 0.5: between texels 1 and 2.
  for (WrapMode wrap : kWraps)
    EXPECT_EQ(red(wrap, 0.5), 3.0) << name_of(wrap);
  // The seams. s = 0: indices -1, 0; s = 1: 3, 4; s = -0.25: -2, -1; s = 1.25: 4, 5.
  EXPECT_EQ(red(WrapMode::repeat, 0.0), 4.5);  // texels 3 and 0
  EXPECT_EQ(red(WrapMode::clamp_to_edge, 0.0), 1.0);
  EXPECT_EQ(red(WrapMode::mirror, 0.0), 1.0);
  EXPECT_EQ(red(WrapMode::repeat, 1.0), 4.5);
  EXPECT_EQ(red(WrapMode::clamp_to_edge, 1.0), 8.0);
  EXPECT_EQ(red(WrapMode::mirror, 1.0), 8.0);
  EXPECT_EQ(red(WrapMode::repeat, -0.25), 6.0);         // texels 2 and 3
  EXPECT_EQ(red(WrapMode::clamp_to_edge, -0.25), 1.0);  // texel 0 twice
  EXPECT_EQ(red(WrapMode::mirror, -0.25), 1.5);         // texels 1 and 0
  EXPECT_EQ(red(WrapMode::repeat, 1.25), 1.5);          // texels 0 and 1
  EXPECT_EQ(red(WrapMode::clamp_to_edge, 1.25), 8.0);
  EXPECT_EQ(red(WrapMode::mirror, 1.25), 6.0);  // texels 3 and 2

  // Two dimensions, 2 x 2 texels 0 1 / 2 4, at u = 0.25, v = 0.75: weights 3/16, 1/16, 9/16,
  // 3/16, all exact, as are the products and sums (multiples of 1/16 below 2).
  const Texture square = float_texture(2, 2, [](int x, int y) {
    const float values[2][2] = {{0, 1}, {2, 4}};
    return FloatTexel{values[y][x], 0, 0, 1};
  });
  EXPECT_EQ(reference::bilinear(square, level0(square), WrapMode::clamp_to_edge,
                                WrapMode::clamp_to_edge, 0.375, 0.625)[0],
            1.9375);
}

TEST(SampleReference, HugeCoordinatesAreExact) {
  // R = x on 4 x 4; t = 0.125 is row 0's centre. s = 2^30 and 1e30 (a float, a multiple of
  // 2^76) put s w at a multiple of 8, both wrap periods; s = 2^24 - 1 (odd) at 4 mod 8, the
  // start of the mirrored copy. Bilinear then sits exactly half way between indices x - 1 and
  // x, so every expectation is exact.
  struct Case {
    float s;
    double repeat_nearest, repeat_bilinear, mirror_nearest, mirror_bilinear, clamp_nearest,
        clamp_bilinear;
  };
  const Case cases[] = {
      {0x1p30f, 0, 1.5, 0, 0, 3, 3},       // texels 3, 0 | 0, 0
      {1e30f, 0, 1.5, 0, 0, 3, 3},         //
      {-0x1p30f, 0, 1.5, 0, 0, 0, 0},      //
      {16777215.0f, 0, 1.5, 3, 3, 3, 3},   // mirror: texels 3, 3
      {-16777215.0f, 0, 1.5, 3, 3, 0, 0},  //
  };
  const Texture texture = float_texture(4, 4, [](int x, int) {
    return FloatTexel{float(x), 0, 0, 1};
  });
  for (const Case& c : cases) {
    auto red = [&](TextureFilter filter, WrapMode wrap) {
      return reference::sample(texture, options_for(filter, wrap, wrap),
                               {c.s, 0.125f, 0, 0, 0, 0})[0];
    };
    EXPECT_EQ(red(TextureFilter::nearest, WrapMode::repeat), c.repeat_nearest) << c.s;
    EXPECT_EQ(red(TextureFilter::bilinear, WrapMode::repeat), c.repeat_bilinear) << c.s;
    EXPECT_EQ(red(TextureFilter::nearest, WrapMode::mirror), c.mirror_nearest) << c.s;
    EXPECT_EQ(red(TextureFilter::bilinear, WrapMode::mirror), c.mirror_bilinear) << c.s;
    EXPECT_EQ(red(TextureFilter::nearest, WrapMode::clamp_to_edge), c.clamp_nearest) << c.s;
    EXPECT_EQ(red(TextureFilter::bilinear, WrapMode::clamp_to_edge), c.clamp_bilinear) << c.s;
  }
}

TEST(SampleReference, CubicWeightsSumToOne) {
  // Each weight is a cubic in f in [0, 1) with coefficients of at most 6, in at most 8
  // operations on terms of at most 6: its error is below 8 * 6 u. Four weights: 200 u.
  Random rng(3);
  std::vector<double> fractions = {0.0, 0.5, std::nextafter(1.0, 0.0)};
  for (int i = 0; i < 1000; ++i)
    fractions.push_back(rng.uniform());
  for (reference::CubicKernel kernel :
       {reference::CubicKernel::catmull_rom, reference::CubicKernel::bspline}) {
    for (double f : fractions) {
      const std::array<double, 4> w = reference::cubic_weights(kernel, f);
      EXPECT_NEAR(w[0] + w[1] + w[2] + w[3], 1.0, 200 * kU) << "f = " << f;
      if (kernel == reference::CubicKernel::bspline) {
        for (double weight : w)
          EXPECT_GE(weight, 0.0);
      }
    }
  }
  // At f = 0 Catmull-Rom is (0, 1, 0, 0) (interpolating), the B-spline (1/6, 2/3, 1/6, 0).
  EXPECT_EQ(reference::cubic_weights(reference::CubicKernel::catmull_rom, 0.0),
            (std::array<double, 4>{0, 1, 0, 0}));
  const std::array<double, 4> b = reference::cubic_weights(reference::CubicKernel::bspline, 0.0);
  EXPECT_NEAR(b[0], 1.0 / 6, kU);
  EXPECT_NEAR(b[1], 2.0 / 3, kU);
  EXPECT_NEAR(b[2], 1.0 / 6, kU);
  EXPECT_EQ(b[3], 0.0);
}

TEST(SampleReference, CatmullRomInterpolatesTexels) {
  // Weights (0, 1, 0, 0) exactly at centres: the texel itself, whatever its neighbours.
  const Texture texture = random_float_texture(5, 3, 12);
  for (WrapMode wrap : kWraps) {
    for (int b = 0; b < 3; ++b) {
      for (int a = 0; a < 5; ++a) {
        const double s = (a + 0.5) / 5, t = (b + 0.5) / 3;
        // s w = (a + 0.5) / 5 * 5 may miss a + 0.5 by two roundings of values < 8, d <= 16 u.
        // The weights' slopes are at most 1.5 and each axis' |weights| sum to at most 1.25, so
        // the 16 products move by at most 2 * 4 * 1.5 d * 1.25 = 15 d = 240 u; each product is
        // computed within 2 * 1.25 * 48 u = 120 u (CubicWeightsSumToOne), 16 of them on texels
        // <= 1: 1920 u; 16 additions: 32 u. Below 2200 u.
        expect_rgba_near(reference::bicubic(texture, level0(texture), wrap, wrap, s, t,
                                            reference::CubicKernel::catmull_rom),
                         level0_texel(texture, a, b), 2200 * kU);
      }
    }
  }
  const Texture exact = random_float_texture(4, 4, 13);
  for (int b = 0; b < 4; ++b) {
    for (int a = 0; a < 4; ++a) {
      expect_rgba_eq(
          reference::bicubic(exact, level0(exact), WrapMode::repeat, WrapMode::repeat,
                             (a + 0.5) / 4, (b + 0.5) / 4, reference::CubicKernel::catmull_rom),
          level0_texel(exact, a, b));
    }
  }
}

TEST(SampleReference, BicubicReproducesLinearRamps) {
  // T(x, y) = 1 + x / 8 - y / 4 (and other ramps) on 16 x 16, queried where the 4 x 4 support
  // lies inside the texture. Both kernels reproduce degree-1 polynomials: sum w_i = 1 and
  // sum i w_i = 1 + f. Error: 16 texels of |T| <= 7.5 whose weight products are off by at most
  // 2 * 1.25 * 48 u = 120 u: 14400 u; 16 additions of terms <= 7.5 * 1.25^2: 190 u; the query
  // point (u + 0.5) / 16 * 16 - 0.5 misses u by 2 ulps of 16 (64 u) on slopes <= 1/2: 32 u; the
  // expected ramp, 3 roundings of values <= 8: 24 u. Below 15000 u (1.7e-12).
  const Texture texture = float_texture(16, 16, [](int x, int y) {
    return FloatTexel{1 + x / 8.0f - y / 4.0f, y / 32.0f, x / 2.0f, 1};
  });
  Random rng(5);
  for (reference::CubicKernel kernel :
       {reference::CubicKernel::catmull_rom, reference::CubicKernel::bspline}) {
    for (int i = 0; i < 200; ++i) {
      const double u = rng.uniform(1, 12.999), v = rng.uniform(1, 12.999);  // u = s w - 0.5
      const double s = (u + 0.5) / 16, t = (v + 0.5) / 16;
      const Rgba got = reference::bicubic(texture, level0(texture), WrapMode::clamp_to_edge,
                                          WrapMode::mirror, s, t, kernel);
      expect_rgba_near(got, {1 + u / 8 - v / 4, v / 32, u / 2, 1}, 15000 * kU);
    }
  }
}

TEST(SampleReference, BicubicOnASpikeAndAStep) {
  // A single 1 at texel (4, 4) of zeros. At f = 0 the B-spline weights are 1/6, 2/3, 1/6:
  // the spike's own centre reads (2/3)^2 = 4/9, a neighbour's (1/6)(2/3) = 1/9, so the B-spline
  // does not interpolate; Catmull-Rom reads 1 and 0. A few roundings of values < 1: 8 u.
  const Texture spike = float_texture(8, 8, [](int x, int y) {
    return FloatTexel{x == 4 && y == 4 ? 1.0f : 0.0f, 0, 0, 0};
  });
  auto red = [&](reference::CubicKernel kernel, double a, double b) {
    return reference::bicubic(spike, level0(spike), WrapMode::clamp_to_edge,
                              WrapMode::clamp_to_edge, (a + 0.5) / 8, (b + 0.5) / 8, kernel)[0];
  };
  EXPECT_NEAR(red(reference::CubicKernel::bspline, 4, 4), 4.0 / 9, 8 * kU);
  EXPECT_NEAR(red(reference::CubicKernel::bspline, 5, 4), 1.0 / 9, 8 * kU);
  EXPECT_NEAR(red(reference::CubicKernel::bspline, 5, 5), 1.0 / 36, 8 * kU);
  EXPECT_EQ(red(reference::CubicKernel::catmull_rom, 4, 4), 1.0);
  EXPECT_EQ(red(reference::CubicKernel::catmull_rom, 5, 4), 0.0);

  // A step 0 0 0 0 1 1 1 1. Half way between texels 2 and 3 Catmull-Rom's last weight is
  // (1/8 - 1/4) / 2 = -1/16 on texel 4: the result undershoots to -1/16, and between texels 4
  // and 5 overshoots to 1 + 1/16 (not clamped). Those weights are exact dyadic numbers.
  const Texture step = float_texture(8, 1, [](int x, int) {
    return FloatTexel{x >= 4 ? 1.0f : 0.0f, 0, 0, 0};
  });
  auto step_red = [&](reference::CubicKernel kernel, double u) {
    return reference::bicubic(step, level0(step), WrapMode::clamp_to_edge, WrapMode::clamp_to_edge,
                              (u + 0.5) / 8, 0.5, kernel)[0];
  };
  EXPECT_EQ(step_red(reference::CubicKernel::catmull_rom, 2.5), -0.0625);
  EXPECT_EQ(step_red(reference::CubicKernel::catmull_rom, 4.5), 1.0625);
  EXPECT_NEAR(step_red(reference::CubicKernel::bspline, 2.5), 0.125 / 6, 8 * kU);  // f^3 / 6
}

TEST(SampleReference, SrgbIsDecodedBeforeWeighting) {
  // Codes 0 and 255 decode to 0 and 1 exactly (pow(1, 2.4) = 1), so the midpoint is 0.5 in
  // every channel; weighting the codes first would give decode(127.5 / 255), about 0.21.
  const Texture texture = rgba8_texture(
      2, 1,
      [](int x, int) {
        return x == 0 ? CodeTexel{0, 0, 0, 0} : CodeTexel{255, 255, 255, 255};
      },
      ColorEncoding::srgb);
  expect_rgba_eq(reference::bilinear(texture, level0(texture), WrapMode::clamp_to_edge,
                                     WrapMode::clamp_to_edge, 0.5, 0.5),
                 {0.5, 0.5, 0.5, 0.5});

  // Codes 0 and 188: the midpoint is half of decode(188) (~0.25), not decode(94) (~0.11).
  const Texture mid = rgba8_texture(
      2, 1,
      [](int x, int) {
        return x == 0 ? CodeTexel{0, 0, 0, 0} : CodeTexel{188, 188, 188, 188};
      },
      ColorEncoding::srgb);
  const double decoded = level0_texel(mid, 1, 0)[0];
  const Rgba got = reference::bilinear(mid, level0(mid), WrapMode::clamp_to_edge,
                                       WrapMode::clamp_to_edge, 0.5, 0.5);
  EXPECT_EQ(got[0], decoded / 2);  // halving is exact
  EXPECT_GT(got[0], 0.2);
  EXPECT_EQ(got[3], 94.0 / 255.0);  // alpha is linear: (188 / 255) / 2, exact halving
}

// ---------------------------------------------------------------------------------------------
// Level of detail and the mip filters

TEST(SampleReference, LevelOfDetailFormulas) {
  const Texture texture = random_float_texture(64, 64, 21);
  SamplerOptions exact, max_axis;
  exact.lod = LodFormula::exact;
  max_axis.lod = LodFormula::max_axis;
  // lambda = log2(rho) - c, c = log2(3) / 2 (the box pyramid's level of equal variance,
  // kernels/texture/level_of_detail.hpp). Where log2(rho) is exact the subtraction rounds once.
  const double c = std::log2(3.0) / 2;
  // A footprint rotated 45 degrees: axes (4, 4) and (-4, 4) texels. rho = 4 sqrt(2) (exact) or
  // 4 (max_axis): log2(rho) 2.5 and 2, a ratio of sqrt(2) in rho. hypot, log2 and the
  // subtraction round once each: |error| <= 2.5 * 2u + u / ln 2 + 2.5 u < 10 u.
  const TextureQuery rotated{0.5f, 0.5f, 0.0625f, 0.0625f, -0.0625f, 0.0625f};
  EXPECT_NEAR(reference::level_of_detail(texture, exact, rotated), 2.5 - c, 10 * kU);
  EXPECT_NEAR(reference::level_of_detail(texture, max_axis, rotated), 2.0 - c, 2 * kU);
  // Axis-aligned 8 x 2 texels: both formulas give log2(8) = 3.
  const TextureQuery aligned{0.5f, 0.5f, 0.125f, 0, 0, 2.0f / 64};
  EXPECT_NEAR(reference::level_of_detail(texture, exact, aligned), 3.0 - c, 4 * kU);
  EXPECT_NEAR(reference::level_of_detail(texture, max_axis, aligned), 3.0 - c, 4 * kU);
  // Axes (1, 0) and (-6, 2): max_axis takes |uy| = 6, exact hypot(6, 2) = sqrt(40).
  const TextureQuery skewed{0.5f, 0.5f, 1.0f / 64, 0, -6.0f / 64, 2.0f / 64};
  EXPECT_NEAR(reference::level_of_detail(texture, exact, skewed), std::log2(40.0) / 2 - c, 10 * kU);
  EXPECT_NEAR(reference::level_of_detail(texture, max_axis, skewed), std::log2(6.0) - c, 10 * kU);
  // A footprint of sqrt(3) texels is the edge of magnification: lambda 0.
  const double root3 = std::sqrt(3.0) / 64;
  const TextureQuery edge{0.5f, 0.5f, static_cast<float>(root3), 0, 0, static_cast<float>(root3)};
  EXPECT_NEAR(reference::level_of_detail(texture, exact, edge), 0.0, 0x1p-22);  // float rho
  // The bias adds.
  max_axis.lod_bias = 0.25f;
  EXPECT_NEAR(reference::level_of_detail(texture, max_axis, rotated), 2.25 - c, 4 * kU);
  max_axis.lod_bias = -3.0f;
  EXPECT_NEAR(reference::level_of_detail(texture, max_axis, aligned), -c, 4 * kU);

  // Zero derivatives magnify (-inf, level 0); a non-finite one selects the coarsest level.
  const TextureQuery zero{0.3f, 0.7f, 0, 0, 0, 0};
  EXPECT_EQ(reference::level_of_detail(texture, exact, zero),
            -std::numeric_limits<double>::infinity());
  EXPECT_EQ(reference::clamp_level_of_detail(texture, -std::numeric_limits<double>::infinity()),
            0.0);
  for (float bad : {kInfF, -kInfF, kNaNF}) {
    for (int which = 0; which < 4; ++which) {
      TextureQuery q = rotated;
      field(q, 2 + which) = bad;
      EXPECT_EQ(reference::level_of_detail(texture, exact, q),
                std::numeric_limits<double>::infinity());
      EXPECT_EQ(reference::level_of_detail(texture, max_axis, q),
                std::numeric_limits<double>::infinity());
    }
  }
  EXPECT_EQ(reference::clamp_level_of_detail(texture, std::numeric_limits<double>::quiet_NaN()),
            6.0);
  EXPECT_EQ(reference::clamp_level_of_detail(texture, 1e300), 6.0);  // 64 x 64: 7 levels
}

TEST(SampleReference, ZeroDerivativesMagnify) {
  const Texture texture = random_float_texture(16, 8, 22, kFullBuild);
  const TextureQuery q{0.37f, 0.81f, 0, 0, 0, 0};
  for (WrapMode wrap : kWraps) {
    const Rgba bilinear = reference::bilinear(texture, level0(texture), wrap, wrap, q.s, q.t);
    for (TextureFilter filter : {TextureFilter::mip_nearest, TextureFilter::trilinear,
                                 TextureFilter::anisotropic, TextureFilter::ewa}) {
      expect_rgba_eq(reference::sample(texture, options_for(filter, wrap, wrap), q), bilinear,
                     describe(filter, wrap));
    }
  }
}

TEST(SampleReference, MipNearestRoundsHalfDown) {
  const Texture texture = random_float_texture(16, 16, 23);  // 5 levels
  EXPECT_EQ(reference::mip_nearest_level(texture, -2.0), 0);
  EXPECT_EQ(reference::mip_nearest_level(texture, 0.5), 0);
  EXPECT_EQ(reference::mip_nearest_level(texture, std::nextafter(0.5, 1.0)), 1);
  EXPECT_EQ(reference::mip_nearest_level(texture, 1.0), 1);
  EXPECT_EQ(reference::mip_nearest_level(texture, 1.5), 1);
  EXPECT_EQ(reference::mip_nearest_level(texture, std::nextafter(1.5, 2.0)), 2);
  EXPECT_EQ(reference::mip_nearest_level(texture, 3.7), 4);
  EXPECT_EQ(reference::mip_nearest_level(texture, 40.0), 4);
  EXPECT_EQ(reference::mip_nearest_level(texture, std::numeric_limits<double>::infinity()), 4);

  // Through sample(): rho = 2 texels (lambda 1 - log2(3) / 2 = 0.21) plus a bias of 0.5 is 0.71:
  // level 1; minus 0.5 is -0.29: level 0.
  const TextureQuery q{0.3f, 0.6f, 2.0f / 16, 0, 0, 1.0f / 16};
  for (float bias : {0.5f, -0.5f}) {
    SamplerOptions options =
        options_for(TextureFilter::mip_nearest, WrapMode::repeat, WrapMode::repeat);
    options.lod_bias = bias;
    const std::size_t level = bias > 0 ? 1 : 0;
    expect_rgba_eq(reference::sample(texture, options, q),
                   reference::bilinear(texture, texture.mip_levels()[level], WrapMode::repeat,
                                       WrapMode::repeat, q.s, q.t));
  }
}

TEST(SampleReference, TrilinearBlendsNeighbouringLevels) {
  const Texture texture = random_float_texture(16, 16, 24);  // 5 levels
  const std::span<const TextureLevel> levels = texture.mip_levels();
  const WrapMode wrap = WrapMode::mirror;
  const double s = 0.43, t = 0.71;
  auto bilinear = [&](std::size_t level) {
    return reference::bilinear(texture, levels[level], wrap, wrap, s, t);
  };
  // lambda 1.25: 0.75 of level 1 and 0.25 of level 2. The weights are exact; each side rounds
  // two products and a sum of terms <= 1: at most 4 u apart.
  const Rgba b1 = bilinear(1), b2 = bilinear(2);
  Rgba expected;
  for (int c = 0; c < 4; ++c)
    expected[c] = 0.75 * b1[c] + 0.25 * b2[c];
  expect_rgba_near(reference::trilinear(texture, wrap, wrap, s, t, 1.25), expected, 4 * kU);

  // Through sample(): rho = 4 texels, bias 0.25: lambda = 2 - log2(3) / 2 + 0.25 = 1.46, levels 1
  // and 2. f is computed as the reference does (two roundings apart from the exact value at
  // most, which moves each product by 2 u more): within 8 u.
  SamplerOptions options = options_for(TextureFilter::trilinear, wrap, wrap);
  options.lod_bias = 0.25f;
  const TextureQuery q{0.43f, 0.71f, 4.0f / 16, 0, 0, 1.0f / 16};
  const double f = 2 - std::log2(3.0) / 2 + 0.25 - 1;
  Rgba via_sample_expected;
  const Rgba q1 = reference::bilinear(texture, levels[1], wrap, wrap, q.s, q.t);
  const Rgba q2 = reference::bilinear(texture, levels[2], wrap, wrap, q.s, q.t);
  for (int c = 0; c < 4; ++c)
    via_sample_expected[c] = (1 - f) * q1[c] + f * q2[c];
  expect_rgba_near(reference::sample(texture, options, q), via_sample_expected, 8 * kU);

  // Integer lambda reads one level; at and beyond the last level only the 1 x 1 level.
  expect_rgba_eq(reference::trilinear(texture, wrap, wrap, s, t, 2.0), bilinear(2));
  expect_rgba_eq(reference::trilinear(texture, wrap, wrap, s, t, 4.0), bilinear(4));
  expect_rgba_eq(reference::trilinear(texture, wrap, wrap, s, t, 1e9), bilinear(4));
  const Rgba b3 = bilinear(3), b4 = bilinear(4);
  for (int c = 0; c < 4; ++c)
    expected[c] = 0.5 * b3[c] + 0.5 * b4[c];
  expect_rgba_near(reference::trilinear(texture, wrap, wrap, s, t, 3.5), expected, 4 * kU);
  // The 1 x 1 level's bilinear is its texel times weights summing to 1 (each weight <= 3
  // roundings, four of them plus the sum): within 16 u of it.
  expect_rgba_near(bilinear(4), reference::coarsest_texel(texture), 16 * kU);
}

// ---------------------------------------------------------------------------------------------
// Bad input

TEST(SampleReference, NonFiniteCoordinatesGiveZero) {
  const Texture texture = random_float_texture(6, 5, 31, kFullBuild);
  for (TextureFilter filter : kAllFilters) {
    for (float bad : {kNaNF, kInfF, -kInfF}) {
      for (const TextureQuery& q :
           {TextureQuery{bad, 0.5f, 0.1f, 0, 0, 0.1f}, TextureQuery{0.5f, bad, 0.1f, 0, 0, 0.1f},
            TextureQuery{bad, bad, kNaNF, 0, 0, kInfF}}) {
        expect_rgba_eq(
            reference::sample(texture, options_for(filter, WrapMode::repeat, WrapMode::mirror), q),
            {0, 0, 0, 0}, describe(q) + " " + std::string(name_of(filter)));
      }
    }
  }
}

TEST(SampleReference, NonFiniteDerivativesGiveTheCoarsestTexel) {
  const Texture texture = random_float_texture(6, 5, 32, kFullBuild);
  const Rgba coarsest = reference::coarsest_texel(texture);
  for (TextureFilter filter : kAllFilters) {
    if (!reads_derivatives(filter)) continue;
    for (float bad : {kNaNF, kInfF, -kInfF}) {
      for (int which = 0; which < 4; ++which) {
        TextureQuery q{0.3f, 0.4f, 0.01f, 0.02f, -0.03f, 0.04f};
        field(q, 2 + which) = bad;
        for (WrapMode wrap : kWraps) {
          expect_rgba_eq(reference::sample(texture, options_for(filter, wrap, wrap), q), coarsest,
                         describe(q) + " " + describe(filter, wrap));
        }
      }
    }
  }
}

TEST(SampleReference, MissingPyramidsThrow) {
  const Texture plain = random_float_texture(4, 4, 33);
  const TextureQuery q{0.5f, 0.5f, 0.1f, 0, 0, 0.1f};
  EXPECT_THROW(
      reference::sample(plain,
                        options_for(TextureFilter::ripmap, WrapMode::repeat, WrapMode::repeat), q),
      std::invalid_argument);
  EXPECT_THROW(
      reference::sample(
          plain, options_for(TextureFilter::summed_area, WrapMode::repeat, WrapMode::repeat), q),
      std::invalid_argument);
}

// A derivative in texture units: mostly ordinary, sometimes 0, tiny, huge or denormal.
float random_derivative(Random& rng) {
  const double sign = rng.sign();
  switch (rng.integer(0, 9)) {
    case 0:
      return 0.0f;
    case 1:
      return static_cast<float>(sign * 1e-30);
    case 2:
      return static_cast<float>(sign * 1e30);
    case 3:
      return static_cast<float>(sign * 1e-40);  // denormal float
    case 4:
      return static_cast<float>(sign * rng.log_uniform(1, 1e6));
    default:
      return static_cast<float>(sign * rng.log_uniform(1e-4, 2));
  }
}

float random_coordinate(Random& rng) {
  switch (rng.integer(0, 9)) {
    case 0:
      return static_cast<float>(rng.sign() * rng.log_uniform(1e3, 1e37));
    case 1:
      return static_cast<float>(rng.integer(-3, 3));  // on texel edges of every level
    default:
      return static_cast<float>(rng.uniform(-2, 3));
  }
}

TextureQuery random_query(Random& rng) {
  TextureQuery q{random_coordinate(rng), random_coordinate(rng), random_derivative(rng),
                 random_derivative(rng), random_derivative(rng), random_derivative(rng)};
  // Degenerate footprints: parallel axes, or one axis a multiple of the other.
  if (rng.chance(0.1)) {
    const float k = static_cast<float>(rng.uniform(-3, 3));
    q.dsdy = k * q.dsdx;
    q.dtdy = k * q.dtdx;
  }
  return q;
}

// The summed_area filter's box half extents, in level-0 texels (before the 2^20 cap).
struct HalfExtents {
  double hu, hv;
};

HalfExtents box_half_extents(const Texture& texture, const TextureQuery& q) {
  const double w = texture.width(), h = texture.height();
  return {std::max(0.5, (std::abs(q.dsdx * w) + std::abs(q.dsdy * w)) / 2),
          std::max(0.5, (std::abs(q.dtdx * h) + std::abs(q.dtdy * h)) / 2)};
}

// A bound on |computed - exact| of a box integral from the summed-area table divided by
// 4 hu hv (the summed_area filter's result), for texels of magnitude at most 1.
// The reference sums products coef_x coef_y S(i, j) with |S(i, j)| <= W H. On an axis of n
// texels, S_ext at a lattice point X expands into entries whose coefficients total at most
// 2 |X| + 5 (clamp_to_edge: (1 + b) S(n) - b S(n - 1) with b < |X|; repeat: k S(n) + S(r),
// |k| <= |X| + 1; mirror: 2k S(n) + 2 S(n) - S(2n - r)). Each box edge interpolates between
// two lattice points, so an axis' coefficients total P <= 4 (2 |X|max + 5), and the reference
// first moves the centre to within 2n + hu + 3 of the origin: |X| <= 2n + 2 hu + 4. At most
// 8 x 8 products of 3 roundings each, then their sum: error <= 70 u Px Py W H / (4 hu hv).
// Loose (the entries are rarely all that large), but it holds for every wrap mode.
double summed_area_tolerance(const Texture& texture, HalfExtents e) {
  const double w = texture.width(), h = texture.height();
  const double px = 4 * (2 * (2 * w + 2 * e.hu + 4) + 5);
  const double py = 4 * (2 * (2 * h + 2 * e.hv + 4) + 5);
  return 70 * px * py * w * h / (4 * e.hu * e.hv) * kU;
}

// How far a filter's result on a constant texture c may be from c, relative to |c|. Each filter
// is a weighted mean whose weights sum to 1 up to rounding; counts of roundings:
double constant_tolerance(TextureFilter filter, const Texture& texture, const SamplerOptions& o,
                          const TextureQuery& q) {
  switch (filter) {
    case TextureFilter::nearest:
      return 0;  // one texel, copied
    case TextureFilter::bilinear:
    case TextureFilter::mip_nearest:
      return 16 * kU;  // 4 weights of <= 3 roundings, 4 products, 4 sums
    case TextureFilter::trilinear:
      return 40 * kU;  // two bilinears, two products and a sum
    case TextureFilter::bicubic_catmull_rom:
    case TextureFilter::bicubic_bspline:
      // Each axis' weights sum to 1 within 200 u (CubicWeightsSumToOne), their products' sum
      // within 400 u; 16 products and 16 additions of terms totalling 1.25^2: 50 u more.
      return 500 * kU;
    case TextureFilter::supersample:
      return (o.supersample_taps * o.supersample_taps + 20) * kU;  // N^2 bilinears, summed
    case TextureFilter::ripmap:
      return 80 * kU;  // four bilinears, blended
    case TextureFilter::anisotropic:
      return (o.max_anisotropy + 50) * kU;  // N trilinears, summed
    case TextureFilter::summed_area: {
      // The box is capped at 2^20 texels per half extent.
      const HalfExtents e = box_half_extents(texture, q);
      return summed_area_tolerance(texture, {std::min(e.hu, 0x1p20), std::min(e.hv, 0x1p20)});
    }
    case TextureFilter::ewa: {
      // Per level a ratio of two sums of n positive terms (n u each) with n at most the
      // ellipse's bounding box: at lod_bias 0 the minor axis is below 2 texels of its level, the
      // major below 2 M, so each half extent is below 2 M + 1: n <= (4 M + 3)^2. Two levels
      // and a blend.
      const double n = (4.0 * o.max_anisotropy + 3) * (4.0 * o.max_anisotropy + 3);
      return (2 * n + 3) * kU;
    }
  }
  return 0;
}

TEST(SampleReference, ConstantTextureGivesTheConstant) {
  // Box pyramids of a constant are the constant exactly: 8-bit levels round back to the code,
  // and the float constants have few bits (their weighted means in double round back).
  struct Case {
    const char* name;
    Texture texture;
  };
  const Case cases[] = {
      {"rgba8 linear 7x5", rgba8_texture(
                               7, 5,
                               [](int, int) {
                                 return CodeTexel{10, 200, 77, 255};
                               },
                               ColorEncoding::linear, kFullBuild)},
      {"rgba8 srgb 5x9", rgba8_texture(
                             5, 9,
                             [](int, int) {
                               return CodeTexel{10, 200, 77, 128};
                             },
                             ColorEncoding::srgb, kFullBuild)},
      {"float 8x4", float_texture(
                        8, 4,
                        [](int, int) {
                          return FloatTexel{0.375f, -2, 5.5f, 1};
                        },
                        kFullBuild)},
  };
  Random rng(41);
  for (const Case& c : cases) {
    const Rgba constant = level0_texel(c.texture, 0, 0);
    // The summed-area table holds sRGB colours rounded to 1/65535: the box filter reads that.
    const SummedAreaTable& table = *c.texture.summed_area_table();
    const Rgba table_constant = {table.sums[4 * (table.width + 2) + 0] * table.scale,
                                 table.sums[4 * (table.width + 2) + 1] * table.scale,
                                 table.sums[4 * (table.width + 2) + 2] * table.scale,
                                 table.sums[4 * (table.width + 2) + 3] * table.scale};
    for (TextureFilter filter : kAllFilters) {
      for (WrapMode wrap_s : kWraps) {
        for (WrapMode wrap_t : kWraps) {
          SamplerOptions options = options_for(filter, wrap_s, wrap_t);
          options.max_anisotropy = static_cast<int>(rng.integer(1, 16));
          options.supersample_taps = static_cast<int>(rng.integer(1, 8));
          options.lod = rng.chance(0.5) ? LodFormula::exact : LodFormula::max_axis;
          const Rgba& expected = filter == TextureFilter::summed_area ? table_constant : constant;
          for (int i = 0; i < 12; ++i) {
            const TextureQuery q = random_query(rng);
            const double tolerance = constant_tolerance(filter, c.texture, options, q);
            const Rgba got = reference::sample(c.texture, options, q);
            for (int ch = 0; ch < 4; ++ch) {
              EXPECT_NEAR(got[ch], expected[ch], tolerance * std::abs(expected[ch]))
                  << c.name << " " << describe(filter, wrap_s) << "/" << name_of(wrap_t) << " "
                  << describe(q) << " channel " << ch;
            }
          }
        }
      }
    }
  }
}

TEST(SampleReference, EveryFilterIsFiniteOnBadQueries) {
  const Texture textures[] = {
      random_float_texture(9, 6, 51, kFullBuild),
      rgba8_texture(
          5, 7,
          [](int x, int y) {
            return CodeTexel{std::uint8_t(37 * x + 11 * y), std::uint8_t(90 * y), 255,
                             std::uint8_t(x * y)};
          },
          ColorEncoding::srgb, kFullBuild),
      random_float_texture(1, 1, 52, kFullBuild),
  };
  const float specials[] = {0.0f, -0.0f, 1e-40f, 1e-30f, 1e30f, -1e30f, kInfF, -kInfF, kNaNF};
  Random rng(53);
  for (const Texture& texture : textures) {
    const Rgba coarsest = reference::coarsest_texel(texture);
    for (TextureFilter filter : kAllFilters) {
      for (WrapMode wrap : kWraps) {
        SamplerOptions options = options_for(filter, wrap, kWraps[rng.integer(0, 2)]);
        options.max_anisotropy = static_cast<int>(rng.integer(1, 64));
        options.supersample_taps = static_cast<int>(rng.integer(1, 16));
        options.lod_bias = static_cast<float>(rng.uniform(0, 1));
        for (int i = 0; i < 30; ++i) {
          TextureQuery q = random_query(rng);
          for (int k = 0; k < 6; ++k) {
            if (rng.chance(0.15)) field(q, k) = specials[rng.integer(0, 8)];
          }
          const Rgba got = reference::sample(texture, options, q);
          const std::string context = describe(q) + " " + describe(filter, wrap);
          if (!std::isfinite(q.s) || !std::isfinite(q.t)) {
            expect_rgba_eq(got, {0, 0, 0, 0}, context);
          } else if (reads_derivatives(filter) &&
                     !(std::isfinite(q.dsdx) && std::isfinite(q.dtdx) && std::isfinite(q.dsdy) &&
                       std::isfinite(q.dtdy))) {
            expect_rgba_eq(got, coarsest, context);
          } else {
            for (double v : got)
              EXPECT_TRUE(std::isfinite(v)) << context;
          }
        }
      }
    }
  }
}

// ---------------------------------------------------------------------------------------------
// Footprint filters

TEST(SampleReference, SupersampleOfOneTapIsBilinear) {
  // One tap: offsets (0.5 / 1 - 0.5) = 0 exactly, weight 1: the bilinear value, bit for bit.
  const Texture texture = random_float_texture(7, 6, 61);
  Random rng(62);
  for (WrapMode wrap : kWraps) {
    SamplerOptions options = options_for(TextureFilter::supersample, wrap, wrap);
    options.supersample_taps = 1;
    for (int i = 0; i < 50; ++i) {
      TextureQuery q = random_query(rng);
      expect_rgba_eq(reference::sample(texture, options, q),
                     reference::bilinear(texture, level0(texture), wrap, wrap, q.s, q.t),
                     describe(q));
    }
  }
}

TEST(SampleReference, SupersampleTapsCoverTheParallelogram) {
  // N = 2: taps at (s, t) +- 1/4 of each axis. The mean of 4 values <= 1, summed in another
  // order: 8 u.
  const Texture texture = random_float_texture(8, 8, 63);
  SamplerOptions options =
      options_for(TextureFilter::supersample, WrapMode::repeat, WrapMode::repeat);
  options.supersample_taps = 2;
  const TextureQuery q{0.3f, 0.6f, 0.25f, 0.125f, -0.0625f, 0.5f};
  Rgba expected{};
  for (double a : {-0.25, 0.25}) {
    for (double b : {-0.25, 0.25}) {
      const Rgba tap =
          reference::bilinear(texture, level0(texture), WrapMode::repeat, WrapMode::repeat,
                              q.s + a * q.dsdx + b * q.dsdy, q.t + a * q.dtdx + b * q.dtdy);
      for (int c = 0; c < 4; ++c)
        expected[c] += tap[c] / 4;
    }
  }
  expect_rgba_near(reference::sample(texture, options, q), expected, 8 * kU);
}

// The integral of the wrap-extended level 0 over [x0, x1] x [y0, y1], by brute force: the
// length of each axis' interval over cells that wrap to texel a, then the sum over texels.
Rgba brute_force_integral(const Texture& texture, WrapMode wrap_s, WrapMode wrap_t, double x0,
                          double y0, double x1, double y1) {
  auto coverage = [](double lo, double hi, std::int64_t n, WrapMode wrap) {
    std::vector<double> cover(static_cast<std::size_t>(n), 0.0);
    for (auto a = static_cast<std::int64_t>(std::floor(lo)); static_cast<double>(a) < hi; ++a) {
      const double overlap = std::min(hi, a + 1.0) - std::max(lo, static_cast<double>(a));
      cover[static_cast<std::size_t>(reference::wrap_index(a, n, wrap))] += overlap;
    }
    return cover;
  };
  const std::vector<double> cx = coverage(x0, x1, texture.width(), wrap_s);
  const std::vector<double> cy = coverage(y0, y1, texture.height(), wrap_t);
  Rgba sum{};
  for (int b = 0; b < texture.height(); ++b) {
    for (int a = 0; a < texture.width(); ++a) {
      const Rgba value = level0_texel(texture, a, b);
      for (int c = 0; c < 4; ++c)
        sum[c] += cx[a] * cy[b] * value[c];
    }
  }
  return sum;
}

TEST(SampleReference, SummedAreaMatchesBruteForceIntegration) {
  const Texture textures[] = {
      random_float_texture(5, 3, 71, kFullBuild),
      random_float_texture(1, 4, 72, kFullBuild),
      rgba8_texture(
          6, 6,
          [](int x, int y) {
            return CodeTexel{std::uint8_t(40 * x + 7 * y), std::uint8_t(200 - 30 * y),
                             std::uint8_t(x * y * 7), 255};
          },
          ColorEncoding::linear, kFullBuild),
  };
  Random rng(73);
  for (const Texture& texture : textures) {
    const double w = texture.width(), h = texture.height();
    for (WrapMode wrap_s : kWraps) {
      for (WrapMode wrap_t : kWraps) {
        for (int i = 0; i < 40; ++i) {
          // Boxes from sub-texel (clamped up to one texel) to three times the texture.
          const TextureQuery q{static_cast<float>(rng.uniform(-2, 3)),
                               static_cast<float>(rng.uniform(-2, 3)),
                               static_cast<float>(rng.sign() * rng.uniform(0, 3)),
                               static_cast<float>(rng.sign() * rng.uniform(0, 1)),
                               static_cast<float>(rng.sign() * rng.uniform(0, 1)),
                               static_cast<float>(rng.sign() * rng.uniform(0, 3))};
          // The brute force's own error (W H products and sums of exact-ish overlaps) is far
          // below the table's bound.
          const HalfExtents e = box_half_extents(texture, q);
          const double cu = double{q.s} * w, cv = double{q.t} * h;
          Rgba expected = brute_force_integral(texture, wrap_s, wrap_t, cu - e.hu, cv - e.hv,
                                               cu + e.hu, cv + e.hv);
          for (double& v : expected)
            v /= 4 * e.hu * e.hv;
          expect_rgba_near(reference::sample(
                               texture, options_for(TextureFilter::summed_area, wrap_s, wrap_t), q),
                           expected, summed_area_tolerance(texture, e),
                           describe(q) + " " + describe(TextureFilter::summed_area, wrap_s));
        }
      }
    }
  }
}

TEST(SampleReference, ExtendedPrefixSumIsTheSignedIntegralFromTheOrigin) {
  const Texture texture = random_float_texture(4, 3, 74, kFullBuild);
  const SummedAreaTable& table = *texture.summed_area_table();
  Random rng(75);
  for (WrapMode wrap_s : kWraps) {
    for (WrapMode wrap_t : kWraps) {
      for (int i = 0; i < 40; ++i) {
        const double x = rng.uniform(-13, 13), y = rng.uniform(-10, 10);
        Rgba expected = brute_force_integral(texture, wrap_s, wrap_t, std::min(0.0, x),
                                             std::min(0.0, y), std::max(0.0, x), std::max(0.0, y));
        const double sign = (x < 0) == (y < 0) ? 1.0 : -1.0;
        for (double& v : expected)
          v *= sign;
        // As summed_area_tolerance for a box with hu, hv = 13 (it bounds |X| by 2n + 30 >= 14),
        // times that box's area, which it divides by.
        expect_rgba_near(reference::extended_prefix_sum(table, wrap_s, wrap_t, x, y), expected,
                         summed_area_tolerance(texture, {13, 13}) * 4 * 13 * 13,
                         std::to_string(x) + ", " + std::to_string(y) + " " +
                             std::string(name_of(wrap_s)) + "/" + std::string(name_of(wrap_t)));
      }
    }
  }
}

TEST(SampleReference, SummedAreaOfHugeAndTinyFootprints) {
  const Texture texture = random_float_texture(4, 4, 76, kFullBuild);
  Rgba mean{};
  for (int b = 0; b < 4; ++b) {
    for (int a = 0; a < 4; ++a) {
      const Rgba v = level0_texel(texture, a, b);
      for (int c = 0; c < 4; ++c)
        mean[c] += v[c] / 16;
    }
  }
  // A huge footprint is capped at half extents of 2^20 texels: a box of 2^21 x 2^21, a whole
  // number of periods (4 and 8) in repeat and mirror, so exactly the texture's mean.
  const TextureQuery huge{0.3f, 0.9f, 1e30f, 0, 0, -1e30f};
  for (WrapMode wrap : {WrapMode::repeat, WrapMode::mirror}) {
    expect_rgba_near(
        reference::sample(texture, options_for(TextureFilter::summed_area, wrap, wrap), huge), mean,
        summed_area_tolerance(texture, {0x1p20, 0x1p20}));
  }
  // clamp_to_edge: the brute force over the same capped box.
  const double cu = double{huge.s} * 4, cv = double{huge.t} * 4, half = 0x1p20;
  Rgba expected = brute_force_integral(texture, WrapMode::clamp_to_edge, WrapMode::clamp_to_edge,
                                       cu - half, cv - half, cu + half, cv + half);
  for (double& v : expected)
    v /= 4 * half * half;
  expect_rgba_near(reference::sample(texture,
                                     options_for(TextureFilter::summed_area,
                                                 WrapMode::clamp_to_edge, WrapMode::clamp_to_edge),
                                     huge),
                   expected, summed_area_tolerance(texture, {half, half}));
  // No footprint: a one-texel box; centred on a texel, that texel.
  for (WrapMode wrap : kWraps) {
    expect_rgba_near(reference::sample(texture, options_for(TextureFilter::summed_area, wrap, wrap),
                                       {0.625f, 0.125f, 0, 0, 0, 0}),
                     level0_texel(texture, 2, 0), summed_area_tolerance(texture, {0.5, 0.5}));
  }
}

TEST(SampleReference, AnisotropicProbeCounts) {
  const Texture texture = random_float_texture(16, 16, 81);
  struct Case {
    float ux, vx, uy, vy;  // texels
    LodFormula lod;
    int max_anisotropy;
    int probes;
    double lambda;
  };
  const Case cases[] = {
      {1, 0, 0, 8, LodFormula::exact, 16, 8, 0.0},  // 1 x 8: 8 probes
      {0, 1, 8, 0, LodFormula::exact, 16, 8, 0.0},  // same, axes swapped
      {1, 0, 0, 3.5f, LodFormula::exact, 16, 4, std::log2(3.5 / 4)},
      {2, 0, 0, 40, LodFormula::exact, 16, 16, std::log2(2.5)},  // clamped to M
      {4, 0, 0, 0, LodFormula::exact, 16, 16, std::log2(0.25)},  // Pmin = 0: M probes
      {0, 0, 0, 0, LodFormula::exact, 16, 1, -std::numeric_limits<double>::infinity()},
      {3, 4, 0, 1, LodFormula::exact, 16, 5, 0.0},     // Px = 5
      {3, 4, 0, 1, LodFormula::max_axis, 16, 4, 0.0},  // Px = max(3, 4)
      {2, 0, 0, 2, LodFormula::exact, 16, 1, 1.0},     // isotropic
      {1, 0, 0, 8, LodFormula::exact, 1, 1, 3.0},      // M = 1: trilinear
  };
  for (const Case& c : cases) {
    SamplerOptions options =
        options_for(TextureFilter::anisotropic, WrapMode::repeat, WrapMode::repeat);
    options.lod = c.lod;
    options.max_anisotropy = c.max_anisotropy;
    const TextureQuery q{0.4f, 0.3f, c.ux / 16, c.vx / 16, c.uy / 16, c.vy / 16};
    const reference::AnisotropicFootprint f = reference::anisotropic_footprint(texture, options, q);
    EXPECT_EQ(f.probes, c.probes) << c.ux << " " << c.vx << " " << c.uy << " " << c.vy;
    if (std::isinf(c.lambda)) {
      EXPECT_EQ(f.lambda, c.lambda);
    } else {
      // log2 of a quotient: two roundings of values below 4.
      EXPECT_NEAR(f.lambda, c.lambda, 8 * kU) << c.ux << " " << c.vx << " " << c.uy << " " << c.vy;
    }
  }

  // 1 x 8 texels at lambda 0: 8 bilinear probes at t + ((k + 0.5) / 8 - 0.5) 0.5 in level 0
  // (trilinear at lambda 0 is level 0's bilinear plus 0 times level 1's). Sums of 8 values <= 1
  // in the same order, scaled by 1/8 exactly: 8 u apart at most.
  const TextureQuery q{0.4f, 0.3f, 1.0f / 16, 0, 0, 0.5f};
  for (WrapMode wrap : kWraps) {
    Rgba expected{};
    for (int k = 0; k < 8; ++k) {
      const Rgba probe = reference::bilinear(texture, level0(texture), wrap, wrap, q.s,
                                             q.t + ((k + 0.5) / 8 - 0.5) * 0.5);
      for (int c = 0; c < 4; ++c)
        expected[c] += probe[c] / 8;
    }
    expect_rgba_near(
        reference::sample(texture, options_for(TextureFilter::anisotropic, wrap, wrap), q),
        expected, 8 * kU, describe(TextureFilter::anisotropic, wrap));
  }
}

TEST(SampleReference, IsotropicAnisotropicIsTrilinear) {
  // One probe at offset 0 with weight 1: the trilinear value, bit for bit, at the probe's own
  // lambda = log2(Pmax / N): the probes' level follows their spacing, without the isotropic
  // filters' variance offset (kernels/texture/level_of_detail.hpp).
  const Texture texture = random_float_texture(32, 32, 82);
  const auto probe_lambda = [](const TextureQuery& q) {
    return std::log2(std::max(std::hypot(double{q.dsdx} * 32, double{q.dtdx} * 32),
                              std::hypot(double{q.dsdy} * 32, double{q.dtdy} * 32)));
  };
  for (WrapMode wrap : kWraps) {
    for (const TextureQuery& q :
         {TextureQuery{0.4f, 0.3f, 2.0f / 32, 0, 0, 2.0f / 32},
          TextureQuery{0.7f, 0.1f, 3.0f / 32, 4.0f / 32, -4.0f / 32, 3.0f / 32}}) {
      const SamplerOptions options = options_for(TextureFilter::anisotropic, wrap, wrap);
      expect_rgba_eq(reference::sample(texture, options, q),
                     reference::trilinear(texture, wrap, wrap, q.s, q.t, probe_lambda(q)),
                     describe(q));
    }
  }
}

TEST(SampleReference, RipmapPicksLevelsPerAxis) {
  const Texture texture = random_float_texture(32, 32, 91, TextureBuild{.ripmaps = true});
  const int columns = texture.ripmap_columns();
  ASSERT_EQ(columns, 6);
  auto rip = [&](int i, int j) -> const TextureLevel& {
    return texture.ripmap_levels()[static_cast<std::size_t>(j * columns + i)];
  };
  ASSERT_EQ(rip(0, 3).width, 32);
  ASSERT_EQ(rip(0, 3).height, 4);
  for (WrapMode wrap : kWraps) {
    const SamplerOptions options = options_for(TextureFilter::ripmap, wrap, wrap);
    // 1 x 8 texels: lambda_s = log2(1) = 0, lambda_t = log2(8) = 3, no fractions: rip (0, 3)
    // with weight 1 and the others with weight 0, bit for bit.
    const TextureQuery q{0.41f, 0.77f, 1.0f / 32, 0, 0, 8.0f / 32};
    expect_rgba_eq(reference::sample(texture, options, q),
                   reference::bilinear(texture, rip(0, 3), wrap, wrap, q.s, q.t));
    // 1 x 6 texels: lambda_t = log2(6), between rows 2 and 3. Weights within 4 u; sums of
    // values <= 1: 8 u.
    const TextureQuery q6{0.41f, 0.77f, 1.0f / 32, 0, 0, 6.0f / 32};
    const double ft = std::log2(6.0) - 2;
    const Rgba b2 = reference::bilinear(texture, rip(0, 2), wrap, wrap, q.s, q.t);
    const Rgba b3 = reference::bilinear(texture, rip(0, 3), wrap, wrap, q.s, q.t);
    Rgba expected;
    for (int c = 0; c < 4; ++c)
      expected[c] = (1 - ft) * b2[c] + ft * b3[c];
    expect_rgba_near(reference::sample(texture, options, q6), expected, 8 * kU);
    // The extents come from the bounding box: axes (3, 4) and (0, 1) give 3 x 4 texels.
    const TextureQuery box{0.41f, 0.77f, 3.0f / 32, 4.0f / 32, 0, 1.0f / 32};
    const double fs = std::log2(3.0) - 1;
    Rgba box_expected{};
    const Rgba r12 = reference::bilinear(texture, rip(1, 2), wrap, wrap, box.s, box.t);
    const Rgba r22 = reference::bilinear(texture, rip(2, 2), wrap, wrap, box.s, box.t);
    for (int c = 0; c < 4; ++c)
      box_expected[c] = (1 - fs) * r12[c] + fs * r22[c];
    expect_rgba_near(reference::sample(texture, options, box), box_expected, 8 * kU);
  }
}

TEST(SampleReference, EwaWeightTable) {
  const std::span<const double> table = reference::ewa_weight_table();
  ASSERT_EQ(table.size(), 128u);
  EXPECT_NEAR(table[0], 1 - std::exp(-2.0), 2 * kU);
  EXPECT_EQ(table[127], 0.0);
  for (std::size_t i = 0; i < table.size(); ++i) {
    // exp rounds within an ulp on both sides: 2 ulps of values <= 1, plus the subtraction.
    EXPECT_NEAR(table[i], std::exp(-2.0 * static_cast<double>(i) / 127) - std::exp(-2.0), 6 * kU);
    if (i > 0) {
      EXPECT_LT(table[i], table[i - 1]);
    }
  }
}

TEST(SampleReference, EwaEccentricityClamp) {
  const Texture texture = random_float_texture(128, 128, 101);  // 8 levels
  // 1 x 1000 texels with M = 16: the minor axis becomes 1000 / 16 = 62.5 texels, perpendicular
  // to the major; lambda = log2(62.5) (about 5.97). log2 and the division round: 8 u.
  SamplerOptions options = options_for(TextureFilter::ewa, WrapMode::repeat, WrapMode::repeat);
  options.max_anisotropy = 16;
  const TextureQuery thin{0.3f, 0.6f, 1.0f / 128, 0, 0, 1000.0f / 128};
  const reference::EwaFootprint f = reference::ewa_footprint(texture, options, thin);
  EXPECT_EQ(f.major_u, 0.0);
  EXPECT_EQ(f.major_v, 1000.0);
  EXPECT_EQ(f.minor_u, -62.5);
  EXPECT_EQ(f.minor_v, 0.0);
  EXPECT_NEAR(f.lambda, std::log2(62.5), 8 * kU);
  // So it filters exactly like the unclamped 62.5 x 1000 footprint (same ellipse: only the
  // minor axis' sign differs, and A, B, C are quadratic in it).
  const TextureQuery wide{0.3f, 0.6f, 62.5f / 128, 0, 0, 1000.0f / 128};
  expect_rgba_eq(reference::sample(texture, options, thin),
                 reference::sample(texture, options, wide));
  // ... blended between levels 5 and 6.
  const double frac = f.lambda - 5;
  const Rgba l5 = reference::ewa_level(texture, texture.mip_levels()[5], WrapMode::repeat,
                                       WrapMode::repeat, thin.s, thin.t, f);
  const Rgba l6 = reference::ewa_level(texture, texture.mip_levels()[6], WrapMode::repeat,
                                       WrapMode::repeat, thin.s, thin.t, f);
  Rgba expected;
  for (int c = 0; c < 4; ++c)
    expected[c] = (1 - frac) * l5[c] + frac * l6[c];
  expect_rgba_near(reference::sample(texture, options, thin), expected, 4 * kU);
  // With M = 64 the minor axis is 1000 / 64 = 15.625: a finer level.
  options.max_anisotropy = 64;
  EXPECT_NEAR(reference::ewa_footprint(texture, options, thin).lambda, std::log2(15.625), 8 * kU);
  // An axis of length 0 is clamped the same way; both 0 magnify.
  const TextureQuery line{0.3f, 0.6f, 0, 0, 0, 8.0f / 128};
  EXPECT_NEAR(reference::ewa_footprint(texture, options, line).lambda, std::log2(8.0 / 64), 8 * kU);
  // Beyond the last level: the coarsest texel.
  const TextureQuery huge{0.3f, 0.6f, 1e6f, 0, 0, 1e6f};
  expect_rgba_eq(reference::sample(texture, options, huge), reference::coarsest_texel(texture));
}

TEST(SampleReference, EwaLevelMatchesTheMatrixForm) {
  // Heckbert's coefficients against the ellipse written as a matrix: with J = [[au, bu],
  // [av, bv]] (the axes as columns, in the level's texels) the ellipse is d^T G^-1 d < 1 for
  // G = J J^T + I. Every texel within 12 of the centre is tried (more than any half extent
  // here: sqrt(6^2 + 6^2 + 1) < 9). The weight is the table interpolated at 127 Q, which is
  // continuous in Q, so the two forms' different roundings of Q (a few ulps) move a weight by
  // at most |slope| <= 127 * (table[0] - table[1]) < 2 times that.
  // Both sides are ratios of sums of n positive weights times texels <= 1: 8 n u apart.
  const Texture texture = random_float_texture(16, 16, 103);
  const std::span<const double> table = reference::ewa_weight_table();
  Random rng(104);
  for (int i = 0; i < 300; ++i) {
    const std::size_t level_index = static_cast<std::size_t>(rng.integer(0, 1));
    const TextureLevel& level = texture.mip_levels()[level_index];
    const WrapMode wrap_s = kWraps[rng.integer(0, 2)], wrap_t = kWraps[rng.integer(0, 2)];
    reference::EwaFootprint f;  // level-0 texels
    f.major_u = rng.uniform(-6, 6);
    f.major_v = rng.uniform(-6, 6);
    f.minor_u = rng.uniform(-3, 3);
    f.minor_v = rng.uniform(-3, 3);
    const double s = rng.uniform(-0.5, 1.5), t = rng.uniform(-0.5, 1.5);

    const double scale = static_cast<double>(level.width) / texture.width();  // square levels
    const double au = f.major_u * scale, av = f.major_v * scale;
    const double bu = f.minor_u * scale, bv = f.minor_v * scale;
    const double g11 = au * au + bu * bu + 1, g12 = au * av + bu * bv, g22 = av * av + bv * bv + 1;
    const double det = g11 * g22 - g12 * g12;
    const double cu = s * level.width - 0.5, cv = t * level.height - 0.5;
    Rgba sum{};
    double weight_sum = 0;
    int terms = 0;
    for (auto y = static_cast<std::int64_t>(std::floor(cv)) - 12; y <= cv + 12; ++y) {
      for (auto x = static_cast<std::int64_t>(std::floor(cu)) - 12; x <= cu + 12; ++x) {
        const double du = static_cast<double>(x) - cu, dv = static_cast<double>(y) - cv;
        const double q = (g22 * du * du - 2 * g12 * du * dv + g11 * dv * dv) / det;
        if (q >= 1) continue;
        const double position = q * 127;
        const auto bin = std::min(static_cast<std::size_t>(position), std::size_t{126});
        const double fraction = position - static_cast<double>(bin);
        const double weight = table[bin] * (1 - fraction) + table[bin + 1] * fraction;
        const Rgba value = reference::texel(texture, level, wrap_s, wrap_t, x, y);
        for (int c = 0; c < 4; ++c)
          sum[c] += weight * value[c];
        weight_sum += weight;
        ++terms;
      }
    }
    for (double& v : sum)
      v /= weight_sum;
    expect_rgba_near(reference::ewa_level(texture, level, wrap_s, wrap_t, s, t, f), sum,
                     8 * terms * kU, "level " + std::to_string(level_index));
  }
}

TEST(SampleReference, EwaNextToTheLastLevelBlendsWithIt) {
  // 16 x 16: 5 levels. An isotropic 12-texel footprint: lambda = log2(12), about 3.58, so
  // levels 3 (2 x 2) and 4 (1 x 1) are blended; only lambda >= 4 returns the last texel.
  const Texture texture = random_float_texture(16, 16, 105);
  const SamplerOptions options =
      options_for(TextureFilter::ewa, WrapMode::repeat, WrapMode::repeat);
  const TextureQuery q{0.3f, 0.45f, 12.0f / 16, 0, 0, 12.0f / 16};
  const reference::EwaFootprint f = reference::ewa_footprint(texture, options, q);
  ASSERT_NEAR(f.lambda, std::log2(12.0), 8 * kU);
  const double frac = f.lambda - 3;
  const Rgba l3 = reference::ewa_level(texture, texture.mip_levels()[3], WrapMode::repeat,
                                       WrapMode::repeat, q.s, q.t, f);
  const Rgba l4 = reference::ewa_level(texture, texture.mip_levels()[4], WrapMode::repeat,
                                       WrapMode::repeat, q.s, q.t, f);
  Rgba expected;
  for (int c = 0; c < 4; ++c)
    expected[c] = (1 - frac) * l3[c] + frac * l4[c];
  expect_rgba_near(reference::sample(texture, options, q), expected, 4 * kU);
  // The 1 x 1 level's weighted mean is its texel (a ratio of equal sums: n u per sum).
  expect_rgba_near(l4, reference::coarsest_texel(texture), 64 * kU);
  // And the blend is not the last texel alone: level 3 differs from it on this texture.
  EXPECT_GT(std::abs(l3[0] - l4[0]) + std::abs(l3[1] - l4[1]), 1e-3);
}

TEST(SampleReference, EwaBoundsItsWorkUnderANegativeBias) {
  // A 1000-texel isotropic footprint with lod_bias -20: lambda < 0 picks level 0, where the
  // ellipse's box would hold about 4 10^6 texels. Level l's half extents are
  // sqrt((1000 / 2^l)^2 + 1), its box (2 e + 1)^2. M = 16 allows 2 (4 16 + 3)^2 = 8978 texels:
  // level 4 holds about 15,880 (e about 62.5), level 5 about 4036 (e about 31.3), which is then
  // read alone. M = 64 allows 134,162: level 2 holds about 251,000, level 3 about 63,000.
  const Texture texture = random_float_texture(64, 64, 106);
  SamplerOptions options = options_for(TextureFilter::ewa, WrapMode::repeat, WrapMode::mirror);
  options.lod_bias = -20;
  const TextureQuery q{0.3f, 0.7f, 1000.0f / 64, 0, 0, 1000.0f / 64};
  const reference::EwaFootprint f = reference::ewa_footprint(texture, options, q);
  ASSERT_LT(f.lambda, 0);
  const auto level = [&](std::size_t l) {
    return reference::ewa_level(texture, texture.mip_levels()[l], WrapMode::repeat,
                                WrapMode::mirror, q.s, q.t, f);
  };
  options.max_anisotropy = 16;
  expect_rgba_eq(reference::sample(texture, options, q), level(5));
  options.max_anisotropy = 64;
  expect_rgba_eq(reference::sample(texture, options, q), level(3));
  // ewa_level() refuses a box larger than any max_anisotropy allows.
  EXPECT_THROW(level(2), std::invalid_argument);
  // A footprint too big for every level but the last: the coarsest texel.
  options.lod_bias = -200;
  expect_rgba_eq(reference::sample(texture, options, {0.3f, 0.7f, 1e30f, 0, 0, 1e30f}),
                 reference::coarsest_texel(texture));
}

// The box of the ellipse in `level`, in its texels, from the footprint's axes (sample.hpp).
double ewa_box(const Texture& texture, const TextureLevel& level,
               const reference::EwaFootprint& f) {
  const double su = double(level.width) / texture.width();
  const double sv = double(level.height) / texture.height();
  const double eu = std::sqrt(std::pow(f.major_u * su, 2) + std::pow(f.minor_u * su, 2) + 1);
  const double ev = std::sqrt(std::pow(f.major_v * sv, 2) + std::pow(f.minor_v * sv, 2) + 1);
  return (2 * eu + 1) * (2 * ev + 1);
}

// EWA's work is bounded relative to what lod_bias 0 needs (sample_reference.hpp, ewa_box_limit):
// under lod_bias -8 and -20 large footprints of every shape read the first level from
// floor(lambda) whose box holds at most 2 (4 M + 3)^2 texels, alone when it moved; with
// lod_bias >= -1 the level never moves (a square texture: its levels halve both sides).
TEST(SampleReference, EwaReadsABoxWithinTheLimitOfItsAnisotropy) {
  const Texture texture = random_float_texture(256, 256, 107);
  const std::span<const TextureLevel> levels = texture.mip_levels();
  Random rng(108);
  int moves = 0;
  for (const int m : {1, 2, 4, 16, 64}) {
    const double limit = 2.0 * (4.0 * m + 3) * (4.0 * m + 3);
    for (const float bias : {-20.0f, -8.0f, -1.0f, -0.5f, 0.0f}) {
      SamplerOptions options = options_for(TextureFilter::ewa, WrapMode::repeat, WrapMode::mirror);
      options.max_anisotropy = m;
      options.lod_bias = bias;
      for (int i = 0; i < 10; ++i) {
        // Major axis 1 to 4096 texels, minor up to 256 times shorter, any direction.
        const double major = rng.log_uniform(1.0, 4096.0), minor = major / rng.log_uniform(1, 256);
        const double angle = rng.uniform(0, 2 * std::numbers::pi);
        const double c = std::cos(angle), s = std::sin(angle);
        const TextureQuery q{
            static_cast<float>(rng.uniform(0, 1)), static_cast<float>(rng.uniform(0, 1)),
            static_cast<float>(major * c / 256),   static_cast<float>(major * s / 256),
            static_cast<float>(-minor * s / 256),  static_cast<float>(minor * c / 256)};
        const reference::EwaFootprint f = reference::ewa_footprint(texture, options, q);
        const double lambda_c = reference::clamp_level_of_detail(texture, f.lambda);
        auto l = static_cast<std::size_t>(std::floor(lambda_c));
        double blend = lambda_c - static_cast<double>(l);
        bool moved = false;
        while (l + 1 < levels.size() && !(ewa_box(texture, levels[l], f) <= limit)) {
          ++l;
          blend = 0;
          moved = true;
        }
        moves += moved;
        SCOPED_TRACE("M " + std::to_string(m) + ", lod_bias " + std::to_string(bias) + ", query " +
                     std::to_string(i));
        if (bias >= -1.0f) {
          EXPECT_FALSE(moved);
        }
        Rgba expected = reference::coarsest_texel(texture);
        if (l + 1 < levels.size()) {
          const auto read = [&](std::size_t k) {
            return reference::ewa_level(texture, levels[k], WrapMode::repeat, WrapMode::mirror, q.s,
                                        q.t, f);
          };
          expected = read(l);
          if (blend > 0) {
            const Rgba coarse = read(l + 1);
            for (int k = 0; k < 4; ++k)
              expected[k] = (1 - blend) * expected[k] + blend * coarse[k];
          }
        }
        // The reference's operations on the same levels: (1 - blend) x + blend y, texels in
        // [-1, 1], differs from them at most by a product's rounding where one side contracts
        // it into a fused multiply-add (2 u).
        expect_rgba_near(reference::sample(texture, options, q), expected, 4 * kU);
      }
    }
  }
  EXPECT_GT(moves, 50);  // of the 100 queries under lod_bias -8 and -20
}

// The limit's formula, and the proof's edge: with lod_bias -1, -1/2 or 0 a clamped footprint whose
// minor axis is just under 2^(1 - lod_bias) texels of its level (the most floor(lambda) leaves)
// and whose major axis is M times that, in any direction, fits the limit for every M in 1 .. 64.
TEST(SampleReference, EwaBoxLimitHoldsWhatLodBiasMinusOneNeeds) {
  const Texture texture = random_float_texture(64, 64, 109);
  const std::span<const TextureLevel> levels = texture.mip_levels();
  for (int m = 1; m <= kMaxAnisotropyLimit; ++m) {
    EXPECT_EQ(reference::ewa_box_limit(m), 2.0 * (4 * m + 3) * (4 * m + 3));
    for (const float bias : {-1.0f, -0.5f, 0.0f}) {
      SamplerOptions options = options_for(TextureFilter::ewa, WrapMode::repeat, WrapMode::repeat);
      options.max_anisotropy = m;
      options.lod_bias = bias;
      for (int step = 0; step < 16; ++step) {
        // Level 2's texels are 4 of level 0's: lambda = 3 - 2^-20, just under level 3.
        const double minor = std::exp2(3.0 - bias - 0x1p-20), major = m * minor;
        const double angle = step * std::numbers::pi / 32;
        const double c = std::cos(angle), s = std::sin(angle);
        const TextureQuery q{0.5f,
                             0.5f,
                             static_cast<float>(major * c / 64),
                             static_cast<float>(major * s / 64),
                             static_cast<float>(-minor * s / 64),
                             static_cast<float>(minor * c / 64)};
        const reference::EwaFootprint f = reference::ewa_footprint(texture, options, q);
        const reference::EwaLevels chosen = reference::ewa_levels(texture, options, f);
        EXPECT_EQ(chosen.level, 2u) << "M " << m << ", lod_bias " << bias;
        EXPECT_GT(chosen.blend, 0.99) << "M " << m << ", lod_bias " << bias;
        EXPECT_LE(reference::ewa_box_texels(texture, levels[2], f), reference::ewa_box_limit(m))
            << "M " << m << ", lod_bias " << bias;
      }
    }
  }
}

TEST(SampleReference, EwaIsotropicIsCloseToBilinearOnARamp) {
  // R = x / 32, G = y / 32 on 32 x 32. Axes (1, 0) and (0, 1) texels: lambda = 0, one level,
  // the ellipse Q = (du^2 + dv^2) / 2 < 1, a disk of radius sqrt(2) (half extents sqrt(2)).
  // EWA's R is the weighted mean of x / 32 over the texel centres in the disk, bilinear's is
  // the centre's u / 32: they differ by less than the disk's radius, sqrt(2) / 32. Where the
  // centre is on a texel or half way between texels the lattice is symmetric about it and so
  // are the weights (B = 0): then the means agree up to rounding (sums of <= 13 terms <= 1 and
  // a division: 64 u).
  const Texture texture = float_texture(32, 32, [](int x, int y) {
    return FloatTexel{x / 32.0f, y / 32.0f, 0.5f, 1};
  });
  const TextureQuery axes{0, 0, 1.0f / 32, 0, 0, 1.0f / 32};
  for (WrapMode wrap : kWraps) {
    const SamplerOptions options = options_for(TextureFilter::ewa, wrap, wrap);
    for (double a = 2; a <= 29; a += 0.5) {
      const double b = 31 - a;
      TextureQuery q = axes;
      q.s = static_cast<float>((a + 0.5) / 32);
      q.t = static_cast<float>((b + 0.5) / 32);
      expect_rgba_near(reference::sample(texture, options, q),
                       reference::bilinear(texture, level0(texture), wrap, wrap, q.s, q.t), 64 * kU,
                       describe(q));
    }
    Random rng(102);
    for (int i = 0; i < 100; ++i) {
      TextureQuery q = axes;
      q.s = static_cast<float>(rng.uniform(2.5, 29.5) / 32);
      q.t = static_cast<float>(rng.uniform(2.5, 29.5) / 32);
      const Rgba ewa = reference::sample(texture, options, q);
      const Rgba bilinear = reference::bilinear(texture, level0(texture), wrap, wrap, q.s, q.t);
      EXPECT_LT(std::abs(ewa[0] - bilinear[0]), std::sqrt(2.0) / 32) << describe(q);
      EXPECT_LT(std::abs(ewa[1] - bilinear[1]), std::sqrt(2.0) / 32) << describe(q);
      EXPECT_NEAR(ewa[2], 0.5, 64 * kU);
    }
  }
}

}  // namespace
}  // namespace edgewise::test
