// Pyramid levels: the box filter's exact area average (mean preserved, 2x2 on even sizes, the
// three-tap polyphase box on odd ones), Lanczos 3 against its definition, sRGB-aware filtering,
// 8-bit rounding and clamping, ripmaps.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <utility>
#include <vector>

#include "edgewise/texture.hpp"
#include "random.hpp"
#include "texture/random_codes.hpp"

namespace edgewise::test {
namespace {

constexpr double kFloatUlp = 0x1p-24;   // float rounding, relative (half an ulp of [1, 2))
constexpr double kDoubleUlp = 0x1p-53;  // double rounding, relative

using Size = std::pair<std::int32_t, std::int32_t>;

std::vector<float> random_floats(std::int32_t width, std::int32_t height, double lo, double hi,
                                 std::uint64_t seed) {
  Random random(seed);
  std::vector<float> texels(static_cast<std::size_t>(width) * height * 4);
  for (float& v : texels)
    v = static_cast<float>(random.uniform(lo, hi));
  return texels;
}

// A diagonal ramp, 0 at the top-left corner to 255 at the bottom-right, on every channel:
// dropping or shifting an edge row or column moves its mean by far more than rounding does.
std::vector<std::uint8_t> ramp_codes(std::int32_t width, std::int32_t height) {
  std::vector<std::uint8_t> texels;
  const double span = std::max(1, width + height - 2);
  for (std::int32_t y = 0; y < height; ++y) {
    for (std::int32_t x = 0; x < width; ++x) {
      const auto code = static_cast<std::uint8_t>(std::lround(255.0 * (x + y) / span));
      texels.insert(texels.end(), {code, code, code, code});
    }
  }
  return texels;
}

std::vector<double> level_values(const Texture& texture, const TextureLevel& level) {
  std::vector<double> values;
  for (std::int32_t y = 0; y < level.height; ++y) {
    for (std::int32_t x = 0; x < level.width; ++x) {
      float rgba[4];
      texture.linear_texel(level, x, y, rgba);
      values.insert(values.end(), rgba, rgba + 4);
    }
  }
  return values;
}

// Per-channel mean of a level's linear values.
void level_mean(const Texture& texture, const TextureLevel& level, double mean[4]) {
  const std::vector<double> values = level_values(texture, level);
  for (int ch = 0; ch < 4; ++ch) {
    double sum = 0.0;
    for (std::size_t i = ch; i < values.size(); i += 4)
      sum += values[i];
    mean[ch] = sum / (static_cast<double>(level.width) * level.height);
  }
}

const Size kSizes[] = {{7, 3}, {1, 9}, {5, 5}, {13, 29}, {64, 48}, {1024, 1}, {3, 3}, {2, 1}};

// The exact area average keeps the mean: source texel k lies in the footprints of the coarse
// texels with total weight n_out / n_in, so the coarse mean is the fine one (for any sizes).
//
// Float levels: a coarse texel is a double sum of at most 3 x 3 products whose weights are
// rounded once (< 16 double roundings in all, each relative 2^-53 of at most max |v| = 1), then
// rounded to float (2^-24 of |v| <= 1). The mean moves by at most the largest texel error per
// level, so level l's mean is within l (2^-24 + 16 2^-53) of level 0's; the test's own double
// means of N <= 2^16 values add N 2^-53 each.
TEST(PyramidBox, PreservesTheMeanOfFloatTextures) {
  for (const auto& [w, h] : kSizes) {
    const Texture texture =
        Texture::from_rgba32f(w, h, random_floats(w, h, 0.0, 1.0, 100 + w * 131 + h));
    double mean0[4];
    level_mean(texture, texture.mip_levels()[0], mean0);
    const double sum_error = 2.0 * w * h * kDoubleUlp;
    for (std::size_t l = 1; l < texture.mip_levels().size(); ++l) {
      double mean[4];
      level_mean(texture, texture.mip_levels()[l], mean);
      const double bound = l * (kFloatUlp + 16 * kDoubleUlp) + sum_error;
      for (int ch = 0; ch < 4; ++ch) {
        EXPECT_NEAR(mean[ch], mean0[ch], bound) << w << "x" << h << " level " << l;
      }
    }
  }
}

// 8-bit levels: each coarse texel is rounded to the nearest code, moving it by at most half a
// code (0.5 / 255 linear); for sRGB the half code is in encoded units, and the decode's slope is
// at most 2.4 / 1.055 (at 1), so at most 2.4 / 1.055 * 0.5 / 255 linear. Level l's mean is then
// within l times that of level 0's, plus double rounding (far below 1e-12) and the float
// rounding of the linear_texel values both means are taken from (2^-24 of values <= 1, each).
TEST(PyramidBox, PreservesTheMeanOf8BitTexturesWithinRounding) {
  for (ColorEncoding encoding : {ColorEncoding::linear, ColorEncoding::srgb}) {
    const double half_code = (encoding == ColorEncoding::srgb ? 2.4 / 1.055 : 1.0) * 0.5 / 255;
    for (const auto& [w, h] : kSizes) {
      const Texture texture = Texture::from_rgba8(w, h, ramp_codes(w, h), encoding);
      double mean0[4];
      level_mean(texture, texture.mip_levels()[0], mean0);
      for (std::size_t l = 1; l < texture.mip_levels().size(); ++l) {
        double mean[4];
        level_mean(texture, texture.mip_levels()[l], mean);
        for (int ch = 0; ch < 4; ++ch) {
          EXPECT_NEAR(mean[ch], mean0[ch], l * half_code + 2 * kFloatUlp + 1e-12)
              << w << "x" << h << " level " << l
              << (encoding == ColorEncoding::srgb ? " sRGB" : "");
        }
      }
    }
  }
}

// A constant level filters to the same constant, exactly: the weights sum to 1 within a few
// double roundings (relative < 2^-48 even with Lanczos's negative lobes), far below half a float
// ulp (2^-25) or half a code, and an sRGB code survives decode and encode (both within 1e-14).
TEST(Pyramid, ConstantTexturesStayConstant) {
  for (PyramidFilter filter : {PyramidFilter::box, PyramidFilter::lanczos3}) {
    for (const auto& [w, h] : kSizes) {
      const TextureBuild build{filter, true, false};
      const std::vector<float> floats(std::size_t(w) * h * 4, 0.3f);
      const std::vector<std::uint8_t> codes(std::size_t(w) * h * 4, 77);
      const Texture textures[] = {Texture::from_rgba32f(w, h, floats, build),
                                  Texture::from_rgba8(w, h, codes, ColorEncoding::linear, build),
                                  Texture::from_rgba8(w, h, codes, ColorEncoding::srgb, build)};
      for (const Texture& texture : textures) {
        const std::vector<double> expected = level_values(texture, texture.mip_levels()[0]);
        for (std::span<const TextureLevel> levels :
             {texture.mip_levels(), texture.ripmap_levels()}) {
          for (const TextureLevel& level : levels) {
            const std::vector<double> values = level_values(texture, level);
            for (std::size_t i = 0; i < values.size(); ++i) {
              ASSERT_EQ(values[i], expected[i % 4])
                  << name_of(filter) << " " << w << "x" << h << " level " << level.width << "x"
                  << level.height;
            }
          }
        }
      }
    }
  }
}

// On even sizes the box is the 2x2 average. Float texels in [2^-10, 1) carry 24-bit
// significands within 10 binades, so the sum of four needs at most 24 + 10 + 2 bits: the
// double computation is exact and the level holds the exact average rounded once to float.
TEST(PyramidBox, EvenSizesAreThe2x2Average) {
  const std::int32_t w = 8, h = 6;
  const std::vector<float> floats = random_floats(w, h, 0x1p-10, 1.0, 7);
  const Texture texture = Texture::from_rgba32f(w, h, floats);
  const TextureLevel& half = texture.mip_levels()[1];
  ASSERT_EQ(half.width, 4);
  ASSERT_EQ(half.height, 3);
  auto at = [&](int x, int y, int ch) { return static_cast<double>(floats[(y * w + x) * 4 + ch]); };
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      float out[4];
      texture.linear_texel(half, x, y, out);
      for (int ch = 0; ch < 4; ++ch) {
        const double sum = at(2 * x, 2 * y, ch) + at(2 * x + 1, 2 * y, ch) +
                           at(2 * x, 2 * y + 1, ch) + at(2 * x + 1, 2 * y + 1, ch);
        EXPECT_EQ(out[ch], static_cast<float>(sum / 4)) << x << "," << y;
      }
    }
  }
  // 8-bit: the nearest code of the average of four codes; a tie (sum = 2 mod 4) may go either
  // way, since the decoded values v / 255 are not exact in double.
  const std::vector<std::uint8_t> codes = random_codes(w, h, 8);
  const Texture texture8 = Texture::from_rgba8(w, h, codes, ColorEncoding::linear);
  const auto* coarse =
      reinterpret_cast<const std::uint8_t*>(texture8.texels(texture8.mip_levels()[1]));
  for (int y = 0; y < 3; ++y) {
    for (int x = 0; x < 4; ++x) {
      for (int ch = 0; ch < 4; ++ch) {
        auto code = [&](int cx, int cy) { return int{codes[(cy * w + cx) * 4 + ch]}; };
        const int sum = code(2 * x, 2 * y) + code(2 * x + 1, 2 * y) + code(2 * x, 2 * y + 1) +
                        code(2 * x + 1, 2 * y + 1);
        const int got = coarse[(y * 4 + x) * 4 + ch];
        if (sum % 4 == 2) {
          EXPECT_TRUE(got == sum / 4 || got == sum / 4 + 1) << got << " for sum " << sum;
        } else {
          EXPECT_EQ(got, (sum + 2) / 4) << "sum " << sum;
        }
      }
    }
  }
}

// Odd sizes by hand: 2n + 1 texels to n, coarse texel c reads texels 2c, 2c + 1, 2c + 2 with
// weights (n - c, n, c + 1) / (2n + 1). The expected values are fractions k / 5 and k / 7,
// which lie at least 2^-26 / 7 (relative) from any float rounding boundary, far more than the
// double computation's error (< 2^-50): the level holds them rounded once to float.
TEST(PyramidBox, OddSizesUseThePolyphaseBox) {
  struct Case {
    std::int32_t n;  // coarse size
    std::vector<float> texels;
    std::vector<double> expected;
  };
  const Case cases[] = {
      // n = 2: (2, 2, 1) / 5 and (1, 2, 2) / 5.
      {2, {1, 2, 4, 8, 16}, {(2 * 1 + 2 * 2 + 1 * 4) / 5.0, (1 * 4 + 2 * 8 + 2 * 16) / 5.0}},
      // n = 3: (3, 3, 1), (2, 3, 2), (1, 3, 3) over 7.
      {3,
       {1, 2, 4, 8, 16, 32, 64},
       {(3 * 1 + 3 * 2 + 1 * 4) / 7.0, (2 * 4 + 3 * 8 + 2 * 16) / 7.0,
        (1 * 16 + 3 * 32 + 3 * 64) / 7.0}},
      // n = 1: three equal thirds.
      {1, {3, 6, 12}, {7.0}},
  };
  for (const Case& c : cases) {
    const auto n_in = static_cast<std::int32_t>(c.texels.size());
    std::vector<float> rgba;
    for (float v : c.texels)
      rgba.insert(rgba.end(), {v, v, v, v});
    // Along x (a row) and along y (a column): the same weights.
    for (bool column : {false, true}) {
      const Texture texture =
          column ? Texture::from_rgba32f(1, n_in, rgba) : Texture::from_rgba32f(n_in, 1, rgba);
      const TextureLevel& coarse = texture.mip_levels()[1];
      ASSERT_EQ(column ? coarse.height : coarse.width, c.n);
      for (std::int32_t i = 0; i < c.n; ++i) {
        float out[4];
        texture.linear_texel(coarse, column ? 0 : i, column ? i : 0, out);
        for (int ch = 0; ch < 4; ++ch) {
          EXPECT_EQ(out[ch], static_cast<float>(c.expected[i])) << n_in << " texels, " << i;
        }
      }
    }
  }
  // 3 x 3 to 1 x 1 in both axes at once: the mean of the nine.
  std::vector<float> nine;
  for (int k = 0; k < 9; ++k)
    nine.insert(nine.end(), 4, static_cast<float>(1 << k));
  const Texture texture = Texture::from_rgba32f(3, 3, nine);
  float out[4];
  texture.linear_texel(texture.mip_levels()[1], 0, 0, out);
  EXPECT_EQ(out[0], static_cast<float>(511.0 / 9.0));
}

// Lanczos 3 on a ramp: on an even size the taps of coarse texel c sit symmetrically around its
// centre 2c + 0.5, so the normalized weights reproduce a linear function exactly; away from
// the border (taps 2c - 5 .. 2c + 6 inside the level) the value is the ramp at the centre.
// Error: at most 13 x 13 products of weights (|sum| of |w| < 1.3, each rounded a few times) and
// integer texels < 128, in double: below 1e-11; then one float rounding, 2^-24 relative.
TEST(PyramidLanczos, ReproducesARampOnEvenSizes) {
  const std::int32_t w = 32, h = 40;
  std::vector<float> texels;
  for (std::int32_t y = 0; y < h; ++y) {
    for (std::int32_t x = 0; x < w; ++x) {
      texels.insert(texels.end(), {float(x), float(y), float(x + y), 1.0f});
    }
  }
  const Texture texture =
      Texture::from_rgba32f(w, h, texels, {PyramidFilter::lanczos3, false, false});
  const TextureLevel& half = texture.mip_levels()[1];
  int interior = 0;
  for (std::int32_t y = 3; 2 * y + 6 < h; ++y) {
    for (std::int32_t x = 3; 2 * x + 6 < w; ++x) {
      float out[4];
      texture.linear_texel(half, x, y, out);
      const double cx = 2 * x + 0.5, cy = 2 * y + 0.5;
      for (const auto& [got, expected] : {std::pair{out[0], cx}, std::pair{out[1], cy},
                                          std::pair{out[2], cx + cy}, std::pair{out[3], 1.0}}) {
        EXPECT_NEAR(got, expected, expected * kFloatUlp + 1e-11) << x << "," << y;
      }
      ++interior;
    }
  }
  EXPECT_EQ(interior, 10 * 14);
}

// The definition, written directly in two dimensions: coarse texel (cx, cy) is the normalized
// sum over source texels (clamped to the edge) within 3 coarse texels of its centre, each
// weighted by L(dx / sx) L(dy / sy) with L(x) = sinc(x) sinc(x / 3).
double lanczos_definition(const std::vector<double>& source, std::int32_t w, std::int32_t h,
                          std::int32_t out_w, std::int32_t out_h, std::int32_t cx, std::int32_t cy,
                          int ch) {
  auto sinc = [](double x) {
    return x == 0.0 ? 1.0 : std::sin(std::numbers::pi * x) / (std::numbers::pi * x);
  };
  auto kernel = [&](double x) { return std::abs(x) < 3.0 ? sinc(x) * sinc(x / 3.0) : 0.0; };
  const double sx = double(w) / out_w, sy = double(h) / out_h;
  const double centre_x = (cx + 0.5) * sx - 0.5, centre_y = (cy + 0.5) * sy - 0.5;
  double sum = 0.0, weights = 0.0;
  for (int ky = int(std::floor(centre_y - 3 * sy)); ky <= int(std::ceil(centre_y + 3 * sy)); ++ky) {
    for (int kx = int(std::floor(centre_x - 3 * sx)); kx <= int(std::ceil(centre_x + 3 * sx));
         ++kx) {
      // An axis that keeps its size is not filtered.
      const double weight = (out_w == w ? (kx == cx) : kernel((kx - centre_x) / sx)) *
                            (out_h == h ? (ky == cy) : kernel((ky - centre_y) / sy));
      const int x = std::clamp(kx, 0, w - 1), y = std::clamp(ky, 0, h - 1);
      sum += weight * source[(std::size_t(y) * w + x) * 4 + ch];
      weights += weight;
    }
  }
  return sum / weights;
}

// Every level, odd and even sizes, against the definition applied to the finer stored level.
// Both sides sum at most 15 x 15 products of weights (sum of |w| < 1.5) and values in [0, 1) in
// double, each within 1e-13 of the exact sum; the level then rounds to float (2^-24 relative).
TEST(PyramidLanczos, MatchesItsDefinition) {
  for (const auto& [w, h] : {Size{7, 5}, Size{9, 3}, Size{16, 11}, Size{1, 9}, Size{12, 1}}) {
    const Texture texture = Texture::from_rgba32f(w, h, random_floats(w, h, 0.0, 1.0, 55 + w),
                                                  {PyramidFilter::lanczos3, false, false});
    const auto levels = texture.mip_levels();
    for (std::size_t l = 1; l < levels.size(); ++l) {
      const std::vector<double> fine = level_values(texture, levels[l - 1]);
      const std::vector<double> coarse = level_values(texture, levels[l]);
      for (std::int32_t y = 0; y < levels[l].height; ++y) {
        for (std::int32_t x = 0; x < levels[l].width; ++x) {
          for (int ch = 0; ch < 4; ++ch) {
            const double expected =
                lanczos_definition(fine, levels[l - 1].width, levels[l - 1].height, levels[l].width,
                                   levels[l].height, x, y, ch);
            EXPECT_NEAR(coarse[(std::size_t(y) * levels[l].width + x) * 4 + ch], expected,
                        std::abs(expected) * kFloatUlp + 2e-13)
                << w << "x" << h << " level " << l << " texel " << x << "," << y;
          }
        }
      }
    }
  }
}

// A step rings under Lanczos: the float level over- and undershoots [0, 1], and the 8-bit level
// of the same step holds those values clamped, every texel the nearest code of the float
// result (which is within 2^-24 of the exact value: half a code plus 255 2^-24 at most).
TEST(PyramidLanczos, Clamps8BitOvershoot) {
  const std::int32_t w = 16;
  std::vector<float> floats;
  std::vector<std::uint8_t> codes;
  for (std::int32_t x = 0; x < w; ++x) {
    const bool bright = x >= w / 2 + 1;  // the edge between texels 8 and 9: off the coarse grid
    floats.insert(floats.end(), 4, bright ? 1.0f : 0.0f);
    codes.insert(codes.end(), 4, bright ? 255 : 0);
  }
  const TextureBuild build{PyramidFilter::lanczos3, false, false};
  const Texture hdr = Texture::from_rgba32f(w, 1, floats, build);
  const Texture ldr = Texture::from_rgba8(w, 1, codes, ColorEncoding::linear, build);
  const std::vector<double> ringing = level_values(hdr, hdr.mip_levels()[1]);
  const auto* clamped = reinterpret_cast<const std::uint8_t*>(ldr.texels(ldr.mip_levels()[1]));
  EXPECT_LT(*std::min_element(ringing.begin(), ringing.end()), -0.01);
  EXPECT_GT(*std::max_element(ringing.begin(), ringing.end()), 1.01);
  for (std::size_t i = 0; i < ringing.size(); ++i) {
    const double scaled = std::clamp(255.0 * ringing[i], 0.0, 255.0);
    EXPECT_LE(std::abs(clamped[i] - scaled), 0.5 + 255 * kFloatUlp) << i;
    if (ringing[i] < 0.0) {
      EXPECT_EQ(clamped[i], 0) << i;
    }
    if (ringing[i] > 1.0) {
      EXPECT_EQ(clamped[i], 255) << i;
    }
  }
}

// Overshoot past the largest float becomes infinity (the float rounding of the double sum),
// never undefined behaviour; no NaN appears from finite input.
TEST(PyramidLanczos, OvershootPastTheLargestFloatIsInfinite) {
  const float big = std::numeric_limits<float>::max();
  std::vector<float> floats;
  for (std::int32_t x = 0; x < 16; ++x)
    floats.insert(floats.end(), 4, x >= 9 ? big : 0.0f);
  const Texture texture =
      Texture::from_rgba32f(16, 1, floats, {PyramidFilter::lanczos3, false, false});
  const std::vector<double> level = level_values(texture, texture.mip_levels()[1]);
  EXPECT_TRUE(std::any_of(level.begin(), level.end(), [](double v) { return std::isinf(v); }));
  EXPECT_TRUE(std::none_of(level.begin(), level.end(), [](double v) { return std::isnan(v); }));
}

// Filtering happens on linear values: black and white texels average to linear 0.5, which is
// sRGB code 187.5...: 188, not the 128 of averaging codes. Linear 8-bit gives 127.5, a tie: the
// box's weights are exactly 1/2 and it rounds half away from zero to 128; Lanczos's two weight
// sums are equal only up to double rounding, so its tie may fall on 127 or 128. Alpha is linear
// either way.
TEST(Pyramid, SrgbTexturesAreFilteredInLinear) {
  const std::vector<std::uint8_t> checker = {0,   0,   0,   255, 255, 255, 255, 255,
                                             255, 255, 255, 255, 0,   0,   0,   255};
  for (PyramidFilter filter : {PyramidFilter::box, PyramidFilter::lanczos3}) {
    for (ColorEncoding encoding : {ColorEncoding::srgb, ColorEncoding::linear}) {
      const Texture texture = Texture::from_rgba8(2, 2, checker, encoding, {filter, false, false});
      const auto* texel =
          reinterpret_cast<const std::uint8_t*>(texture.texels(texture.mip_levels()[1]));
      for (int ch = 0; ch < 3; ++ch) {
        if (encoding == ColorEncoding::srgb) {
          EXPECT_EQ(texel[ch], 188) << name_of(filter);
        } else if (filter == PyramidFilter::box) {
          EXPECT_EQ(texel[ch], 128);
        } else {
          EXPECT_TRUE(texel[ch] == 127 || texel[ch] == 128) << int{texel[ch]};
        }
      }
      EXPECT_EQ(texel[3], 255);
    }
  }
}

// Ripmap (i, j) is mip width i by mip height j: floor(log2 W) + 1 columns, floor(log2 H) + 1
// rows.
TEST(Ripmap, LevelSizes) {
  for (const auto& [w, h] : {Size{7, 3}, Size{13, 29}, Size{1024, 1}, Size{1, 9}, Size{1, 1}}) {
    const std::vector<std::uint8_t> codes(std::size_t(w) * h * 4, 1);
    const Texture plain = Texture::from_rgba8(w, h, codes, ColorEncoding::linear);
    EXPECT_TRUE(plain.ripmap_levels().empty());
    const Texture texture =
        Texture::from_rgba8(w, h, codes, ColorEncoding::linear, {PyramidFilter::box, true, false});
    const int columns = int(std::floor(std::log2(w))) + 1, rows = int(std::floor(std::log2(h))) + 1;
    ASSERT_EQ(texture.ripmap_columns(), columns);
    ASSERT_EQ(texture.ripmap_levels().size(), std::size_t(columns * rows));
    for (int j = 0; j < rows; ++j) {
      for (int i = 0; i < columns; ++i) {
        const TextureLevel& rip = texture.ripmap_levels()[j * columns + i];
        EXPECT_EQ(rip.width, std::max(1, w >> i)) << i << "," << j;
        EXPECT_EQ(rip.height, std::max(1, h >> j)) << i << "," << j;
      }
    }
  }
}

// Rip level (i, i) holds mip level i's texels, and a 1-texel-high texture's rips (i, 0),
// filtered along x only, equal its mips bit for bit (the vertical pass of a 1-high level is
// the identity).
TEST(Ripmap, DiagonalIsTheMipChain) {
  for (PyramidFilter filter : {PyramidFilter::box, PyramidFilter::lanczos3}) {
    for (const auto& [w, h] : {Size{13, 29}, Size{64, 16}, Size{1024, 1}}) {
      const Texture texture = Texture::from_rgba8(w, h, random_codes(w, h, 3 + w),
                                                  ColorEncoding::srgb, {filter, true, false});
      const int columns = texture.ripmap_columns();
      const int rows = static_cast<int>(texture.ripmap_levels().size()) / columns;
      for (int i = 0; i < std::max(columns, rows); ++i) {
        const bool on_grid = i < columns && (i < rows || rows == 1);
        if (!on_grid) continue;
        const TextureLevel& rip = texture.ripmap_levels()[(rows == 1 ? 0 : i) * columns + i];
        const TextureLevel& mip = texture.mip_levels()[i];
        ASSERT_EQ(rip.width, mip.width);
        ASSERT_EQ(rip.height, mip.height);
        EXPECT_EQ(level_values(texture, rip), level_values(texture, mip))
            << name_of(filter) << " " << w << "x" << h << " level " << i;
      }
    }
  }
}

// Off the diagonal, box rips of a power-of-two float texture are block averages of level 0:
// rip (i, j) texel (x, y) = the mean of the 2^i x 2^j block at (2^i x, 2^j y). Each of the
// max(i, j) steps that made it rounds a texel to float once (2^-24 relative) after an exact
// double average (texels in [2^-10, 1), as in EvenSizesAreThe2x2Average).
TEST(Ripmap, BoxRipsAreBlockAverages) {
  const std::int32_t w = 16, h = 8;
  const std::vector<float> floats = random_floats(w, h, 0x1p-10, 1.0, 21);
  const Texture texture = Texture::from_rgba32f(w, h, floats, {PyramidFilter::box, true, false});
  const int columns = texture.ripmap_columns();
  for (int j = 0; j < 4; ++j) {
    for (int i = 0; i < 5; ++i) {
      const TextureLevel& rip = texture.ripmap_levels()[j * columns + i];
      for (std::int32_t y = 0; y < rip.height; ++y) {
        for (std::int32_t x = 0; x < rip.width; ++x) {
          float out[4];
          texture.linear_texel(rip, x, y, out);
          for (int ch = 0; ch < 4; ++ch) {
            double sum = 0.0;
            for (int by = 0; by < 1 << j; ++by) {
              for (int bx = 0; bx < 1 << i; ++bx) {
                sum += floats[((std::size_t(y) << j) + by) * w * 4 + ((x << i) + bx) * 4 + ch];
              }
            }
            const double mean = sum / (1 << (i + j));
            EXPECT_NEAR(out[ch], mean, std::max(i, j) * kFloatUlp * mean)
                << "rip " << i << "," << j << " texel " << x << "," << y;
          }
        }
      }
    }
  }
}

}  // namespace
}  // namespace edgewise::test
