// The summed-area table: entries against brute-force sums, exact integers for 8-bit textures,
// the texture-average identity, and the stability measurement that motivates the integer
// representation (float32 accumulation stops being exact past about 256 x 256 8-bit texels).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <cstdio>
#include <limits>
#include <string>
#include <utility>
#include <vector>

#include "edgewise/texture.hpp"
#include "random.hpp"
#include "texture/random_codes.hpp"

namespace edgewise::test {
namespace {

#if defined(__SANITIZE_ADDRESS__)
constexpr bool kSanitized = true;
#elif defined(__has_feature)
#if __has_feature(address_sanitizer)
constexpr bool kSanitized = true;
#else
constexpr bool kSanitized = false;
#endif
#else
constexpr bool kSanitized = false;
#endif

using Size = std::pair<std::int32_t, std::int32_t>;

const TextureBuild kWithTable{PyramidFilter::box, false, true};

double entry(const SummedAreaTable& table, std::int32_t x, std::int32_t y, int ch) {
  return table.sums[4 * (static_cast<std::size_t>(y) * (table.width + 1) + x) + ch];
}

// The header's units, written out: 257 v for a linear code, round(65535 * decode(v)) for an
// sRGB colour code, 257 v for alpha.
std::int64_t units(std::uint8_t code, ColorEncoding encoding, int ch) {
  if (encoding == ColorEncoding::srgb && ch < 3) {
    return std::llround(65535.0 * srgb_to_linear(code / 255.0));
  }
  return 257 * std::int64_t{code};
}

TEST(SummedAreaTable, NotBuiltUnlessAsked) {
  const std::vector<std::uint8_t> codes(4 * 4 * 4, 9);
  EXPECT_EQ(Texture::from_rgba8(4, 4, codes, ColorEncoding::linear).summed_area_table(), nullptr);
  const Texture texture = Texture::from_rgba8(4, 4, codes, ColorEncoding::linear, kWithTable);
  ASSERT_NE(texture.summed_area_table(), nullptr);
  EXPECT_EQ(texture.summed_area_table()->width, 4);
  EXPECT_EQ(texture.summed_area_table()->height, 4);
  EXPECT_EQ(texture.summed_area_table()->sums.size(), 5u * 5u * 4u);
  EXPECT_EQ(texture.summed_area_table()->scale, 1.0 / 65535.0);
}

// Every entry equals the brute-force integer sum over its rectangle, exactly; row 0 and column
// 0 are zero.
TEST(SummedAreaTable, EightBitEntriesAreExactIntegerSums) {
  for (ColorEncoding encoding : {ColorEncoding::linear, ColorEncoding::srgb}) {
    for (const auto& [w, h] : {Size{1, 1}, Size{7, 3}, Size{37, 23}, Size{1, 17}, Size{19, 1}}) {
      const std::vector<std::uint8_t> codes = random_codes(w, h, 5 + w * 7 + h);
      const Texture texture = Texture::from_rgba8(w, h, codes, encoding, kWithTable);
      const SummedAreaTable& table = *texture.summed_area_table();
      ASSERT_EQ(table.sums.size(), std::size_t(w + 1) * (h + 1) * 4);
      for (std::int32_t y = 0; y <= h; ++y) {
        for (std::int32_t x = 0; x <= w; ++x) {
          for (int ch = 0; ch < 4; ++ch) {
            std::int64_t sum = 0;
            for (std::int32_t b = 0; b < y; ++b) {
              for (std::int32_t a = 0; a < x; ++a) {
                sum += units(codes[(std::size_t(b) * w + a) * 4 + ch], encoding, ch);
              }
            }
            const double e = entry(table, x, y, ch);
            EXPECT_EQ(e, std::floor(e));
            EXPECT_EQ(e, static_cast<double>(sum)) << w << "x" << h << " entry " << x << "," << y;
          }
        }
      }
    }
  }
}

// Float texels (any sign, HDR range) are summed in double. The header's bound on an entry's
// error is (x + y) 2^-53 times the sum of |value| over its rectangle; the brute-force sum here
// runs in long double, whose own error is below x y eps_ld / 2 times the same sum.
TEST(SummedAreaTable, FloatEntriesAreWithinTheDocumentedBound) {
  const double ld_unit = std::numeric_limits<long double>::epsilon() / 2;
  for (const auto& [w, h] : {Size{1, 1}, Size{9, 4}, Size{31, 27}}) {
    Random random(77 + w);
    std::vector<float> texels(std::size_t(w) * h * 4);
    for (float& v : texels)
      v = static_cast<float>(random.sign() * random.log_uniform(1e-3, 1e4));
    const Texture texture = Texture::from_rgba32f(w, h, texels, kWithTable);
    const SummedAreaTable& table = *texture.summed_area_table();
    EXPECT_EQ(table.scale, 1.0);
    for (std::int32_t y = 0; y <= h; ++y) {
      for (std::int32_t x = 0; x <= w; ++x) {
        for (int ch = 0; ch < 4; ++ch) {
          long double sum = 0, magnitude = 0;
          for (std::int32_t b = 0; b < y; ++b) {
            for (std::int32_t a = 0; a < x; ++a) {
              const float v = texels[(std::size_t(b) * w + a) * 4 + ch];
              sum += v;
              magnitude += std::abs(v);
            }
          }
          const double bound = static_cast<double>(
              magnitude * ((x + y) * 0x1p-53L + static_cast<long double>(x) * y * ld_unit));
          EXPECT_NEAR(entry(table, x, y, ch), static_cast<double>(sum), bound)
              << w << "x" << h << " entry " << x << "," << y;
        }
      }
    }
  }
}

// S(W, H) scale / (W H) is the texture's average linear value. For 8-bit linear it is exact:
// S(W, H) = 257 * (sum of codes) and the mean of v / 255 is that sum / (255 W H); for sRGB each
// texel's units are within half a unit (0.5 / 65535) of 65535 times the decoded value; the
// double divisions add a few 2^-53.
TEST(SummedAreaTable, LastEntryGivesTheTextureAverage) {
  const std::int32_t w = 45, h = 17;
  const std::vector<std::uint8_t> codes = random_codes(w, h, 99);
  for (ColorEncoding encoding : {ColorEncoding::linear, ColorEncoding::srgb}) {
    const Texture texture = Texture::from_rgba8(w, h, codes, encoding, kWithTable);
    const SummedAreaTable& table = *texture.summed_area_table();
    for (int ch = 0; ch < 4; ++ch) {
      std::int64_t code_sum = 0;
      double decoded_sum = 0.0;
      for (std::size_t i = ch; i < codes.size(); i += 4) {
        code_sum += codes[i];
        decoded_sum += encoding == ColorEncoding::srgb && ch < 3 ? srgb_to_linear(codes[i] / 255.0)
                                                                 : codes[i] / 255.0;
      }
      const double average = entry(table, w, h, ch) * table.scale / (w * h);
      if (encoding == ColorEncoding::linear || ch == 3) {
        EXPECT_EQ(entry(table, w, h, ch), 257.0 * static_cast<double>(code_sum));
      }
      EXPECT_NEAR(average, decoded_sum / (w * h), 0.5 / 65535 + 1e-14) << "channel " << ch;
    }
  }
}

// Stability: the same table accumulated in float32, in code units (entries up to 255 W H), for
// random 8-bit textures of growing size. A box sum taken from float32 entries is exact only
// while every entry is below 2^24; with random codes (mean 127.5) that fails between 256 x 256
// (largest entry about 2^23) and 512 x 512 (about 2^25). The integer table stays exact at every
// size. The worst error is measured over boxes whose corners lie on a grid of n / 64 texels
// (one grid cell, and from each grid corner to the far edges), as a code sum and as a box average
// in linear units.
TEST(SummedAreaTable, StabilityOfFloat32AgainstTheExactTable) {
  const std::int32_t largest = kSanitized ? 1024 : 2048;
  std::string report;
  std::int64_t first_error = 0, last_error = 0;
  for (std::int32_t n = 64; n <= largest; n *= 2) {
    const std::vector<std::uint8_t> codes = random_codes(n, n, 2024);
    const Texture texture = Texture::from_rgba8(n, n, codes, ColorEncoding::linear, kWithTable);
    const SummedAreaTable& table = *texture.summed_area_table();
    // The exact reference (int64 code sums, red channel) and the float32 accumulation.
    const std::size_t stride = std::size_t(n) + 1;
    std::vector<std::int64_t> exact(stride * stride, 0);
    std::vector<float> single(stride * stride, 0.0f);
    for (std::int32_t y = 0; y < n; ++y) {
      std::int64_t row = 0;
      float row_single = 0.0f;
      for (std::int32_t x = 0; x < n; ++x) {
        const std::uint8_t code = codes[(std::size_t(y) * n + x) * 4];
        row += code;
        row_single += code;
        exact[(y + 1) * stride + x + 1] = exact[y * stride + x + 1] + row;
        single[(y + 1) * stride + x + 1] = single[y * stride + x + 1] + row_single;
      }
    }
    bool table_exact = true;
    for (std::size_t i = 0; i < exact.size(); ++i) {
      table_exact = table_exact && table.sums[4 * i] == 257.0 * static_cast<double>(exact[i]);
    }
    EXPECT_TRUE(table_exact) << n << "x" << n;
    // 64 x 64 grid corners at every size, so the cost stays flat as n grows.
    const std::int32_t step = std::max(1, n / 64);
    auto box = [&](const auto& s, std::int32_t x0, std::int32_t y0, std::int32_t x1,
                   std::int32_t y1) {
      return static_cast<double>(s[y1 * stride + x1]) - static_cast<double>(s[y0 * stride + x1]) -
             static_cast<double>(s[y1 * stride + x0]) + static_cast<double>(s[y0 * stride + x0]);
    };
    double worst_sum = 0.0, worst_average = 0.0;
    for (std::int32_t y0 = 0; y0 < n; y0 += step) {
      for (std::int32_t x0 = 0; x0 < n; x0 += step) {
        for (const auto& [x1, y1] :
             {Size{x0 + step, y0 + step}, Size{n, n}, Size{n, y0 + step}, Size{x0 + step, n}}) {
          const double error = std::abs(box(single, x0, y0, x1, y1) - box(exact, x0, y0, x1, y1));
          worst_sum = std::max(worst_sum, error);
          worst_average = std::max(worst_average, error / (255.0 * (x1 - x0) * (y1 - y0)));
        }
      }
    }
    if (n == 64) first_error = static_cast<std::int64_t>(worst_sum);
    last_error = static_cast<std::int64_t>(worst_sum);
    char line[160];
    std::snprintf(line, sizeof line,
                  "%4dx%-4d float32 SAT: worst box-sum error %.0f codes, worst box-average "
                  "error %.3g (linear); exact table: %s",
                  n, n, worst_sum, worst_average, table_exact ? "exact" : "NOT EXACT");
    std::printf("%s\n", line);
    report += std::string(report.empty() ? "" : "; ") + line;
    RecordProperty("float32_worst_box_sum_error_" + std::to_string(n), std::to_string(worst_sum));
    RecordProperty("float32_worst_box_average_error_" + std::to_string(n),
                   std::to_string(worst_average));
  }
  EXPECT_EQ(first_error, 0) << "float32 should still be exact at 64x64";
  EXPECT_GE(last_error, 1) << "float32 should have lost exactness at " << largest << "x" << largest;
}

}  // namespace
}  // namespace edgewise::test
