// Texture construction: argument checks, level sizes and alignment, texel decoding, the sRGB
// transfer functions and their table, pyramid filter names.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "edgewise/texture.hpp"

namespace edgewise::test {
namespace {

std::vector<std::uint8_t> gray8(std::int32_t width, std::int32_t height, std::uint8_t value) {
  return std::vector<std::uint8_t>(static_cast<std::size_t>(width) * height * 4, value);
}

TEST(Texture, RejectsBadSizesAndSpanLengths) {
  const std::vector<std::uint8_t> bytes = gray8(2, 2, 0);
  const std::vector<float> floats(16, 0.0f);
  for (const auto& [w, h] : {std::pair{0, 1}, std::pair{1, 0}, std::pair{-3, 2},
                             std::pair{(1 << 15) + 1, 1}, std::pair{1, (1 << 15) + 1}}) {
    EXPECT_THROW(Texture::from_rgba8(w, h, bytes, ColorEncoding::linear), std::invalid_argument)
        << w << "x" << h;
    EXPECT_THROW(Texture::from_rgba32f(w, h, floats), std::invalid_argument) << w << "x" << h;
  }
  EXPECT_THROW(Texture::from_rgba8(2, 2, std::span(bytes).first(15), ColorEncoding::linear),
               std::invalid_argument);
  EXPECT_THROW(Texture::from_rgba8(1, 2, bytes, ColorEncoding::linear), std::invalid_argument);
  EXPECT_THROW(Texture::from_rgba32f(2, 2, std::span(floats).first(12)), std::invalid_argument);
  try {
    Texture::from_rgba8(3, 2, bytes, ColorEncoding::linear);
    FAIL() << "no exception";
  } catch (const std::invalid_argument& e) {
    EXPECT_NE(std::string(e.what()).find("16 values for 3x2 texels, expected 24"),
              std::string::npos)
        << e.what();
  }
  // The largest size per axis is accepted.
  const Texture wide = Texture::from_rgba8(1 << 15, 1, gray8(1 << 15, 1, 7), ColorEncoding::linear);
  EXPECT_EQ(wide.width(), 1 << 15);
  EXPECT_EQ(wide.mip_levels().size(), 16u);
}

// Level i + 1 is max(1, floor(w / 2)) x max(1, floor(h / 2)); the last level is 1 x 1.
TEST(Texture, MipLevelSizes) {
  struct Case {
    std::int32_t width, height;
    std::vector<std::pair<std::int32_t, std::int32_t>> sizes;
  };
  const Case cases[] = {
      {7, 3, {{7, 3}, {3, 1}, {1, 1}}},         {1, 9, {{1, 9}, {1, 4}, {1, 2}, {1, 1}}},
      {5, 5, {{5, 5}, {2, 2}, {1, 1}}},         {1, 1, {{1, 1}}},
      {8, 2, {{8, 2}, {4, 1}, {2, 1}, {1, 1}}},
  };
  for (const Case& c : cases) {
    const Texture texture =
        Texture::from_rgba8(c.width, c.height, gray8(c.width, c.height, 9), ColorEncoding::linear);
    ASSERT_EQ(texture.mip_levels().size(), c.sizes.size()) << c.width << "x" << c.height;
    for (std::size_t i = 0; i < c.sizes.size(); ++i) {
      EXPECT_EQ(texture.mip_levels()[i].width, c.sizes[i].first) << c.width << "x" << c.height;
      EXPECT_EQ(texture.mip_levels()[i].height, c.sizes[i].second) << c.width << "x" << c.height;
    }
  }
  const Texture line = Texture::from_rgba8(1024, 1, gray8(1024, 1, 9), ColorEncoding::linear);
  ASSERT_EQ(line.mip_levels().size(), 11u);
  for (std::size_t i = 0; i < 11; ++i) {
    EXPECT_EQ(line.mip_levels()[i].width, 1024 >> i);
    EXPECT_EQ(line.mip_levels()[i].height, 1);
  }
}

// Every level (mip and rip) starts 64-byte aligned, inside the storage, without overlapping
// another level.
TEST(Texture, LevelsAreAlignedAndDisjoint) {
  for (const auto& [w, h] :
       {std::pair{7, 3}, std::pair{13, 29}, std::pair{1, 9}, std::pair{64, 1}}) {
    for (bool is_float : {false, true}) {
      const TextureBuild build{PyramidFilter::box, true, false};
      const Texture texture =
          is_float
              ? Texture::from_rgba32f(w, h, std::vector<float>(std::size_t(w) * h * 4, 0.5f), build)
              : Texture::from_rgba8(w, h, gray8(w, h, 3), ColorEncoding::srgb, build);
      const std::size_t texel = is_float ? 16 : 4;
      std::vector<std::pair<std::size_t, std::size_t>> ranges;
      for (std::span<const TextureLevel> levels : {texture.mip_levels(), texture.ripmap_levels()}) {
        for (const TextureLevel& level : levels) {
          EXPECT_EQ(level.offset % 64, 0u);
          EXPECT_EQ(reinterpret_cast<std::uintptr_t>(texture.texels(level)) % 64, 0u);
          ranges.emplace_back(level.offset,
                              level.offset + std::size_t(level.width) * level.height * texel);
        }
      }
      std::sort(ranges.begin(), ranges.end());
      ranges.erase(std::unique(ranges.begin(), ranges.end()), ranges.end());  // shared diagonal
      for (std::size_t i = 1; i < ranges.size(); ++i) {
        EXPECT_LE(ranges[i - 1].second, ranges[i].first) << w << "x" << h;
      }
    }
  }
}

TEST(Texture, LinearTexelDecodes) {
  std::vector<std::uint8_t> bytes = {0, 51, 255, 128, 10, 200, 188, 255};
  const Texture linear = Texture::from_rgba8(2, 1, bytes, ColorEncoding::linear);
  const Texture srgb = Texture::from_rgba8(2, 1, bytes, ColorEncoding::srgb);
  EXPECT_EQ(linear.format(), TexelFormat::rgba8);
  EXPECT_EQ(srgb.encoding(), ColorEncoding::srgb);
  for (std::int32_t x = 0; x < 2; ++x) {
    float l[4], s[4];
    linear.linear_texel(linear.mip_levels()[0], x, 0, l);
    srgb.linear_texel(srgb.mip_levels()[0], x, 0, s);
    for (int ch = 0; ch < 4; ++ch) {
      const int code = bytes[x * 4 + ch];
      // One float rounding of the exact value: half an ulp, at most 2^-24 relative.
      EXPECT_NEAR(l[ch], code / 255.0, code / 255.0 * 0x1p-24);
      const double expected = ch < 3 ? srgb_to_linear(code / 255.0) : code / 255.0;
      EXPECT_NEAR(s[ch], expected, expected * 0x1p-24) << "channel " << ch;
    }
  }
  const std::vector<float> floats = {-1.5f, 0.25f, 1e30f, 1.0f};
  const Texture hdr = Texture::from_rgba32f(1, 1, floats);
  float out[4];
  hdr.linear_texel(hdr.mip_levels()[0], 0, 0, out);
  for (int ch = 0; ch < 4; ++ch)
    EXPECT_EQ(out[ch], floats[ch]);
}

// Float texels are stored as given, NaN and infinity included; they spread to the coarser
// texels whose footprint holds them, and only to those.
TEST(Texture, NonFiniteFloatTexelsAreStoredAsGiven) {
  std::vector<float> floats(4 * 4 * 4, 0.5f);
  floats[0] = std::numeric_limits<float>::quiet_NaN();                   // texel (0, 0), R
  floats[(3 * 4 + 3) * 4 + 1] = std::numeric_limits<float>::infinity();  // texel (3, 3), G
  const Texture texture = Texture::from_rgba32f(4, 4, floats);
  float out[4];
  texture.linear_texel(texture.mip_levels()[0], 0, 0, out);
  EXPECT_TRUE(std::isnan(out[0]));
  texture.linear_texel(texture.mip_levels()[0], 3, 3, out);
  EXPECT_EQ(out[1], std::numeric_limits<float>::infinity());
  const TextureLevel& half = texture.mip_levels()[1];
  texture.linear_texel(half, 0, 0, out);
  EXPECT_TRUE(std::isnan(out[0]));
  EXPECT_EQ(out[1], 0.5f);
  texture.linear_texel(half, 1, 0, out);
  EXPECT_EQ(out[0], 0.5f);
  texture.linear_texel(half, 1, 1, out);
  EXPECT_EQ(out[1], std::numeric_limits<float>::infinity());
}

// IEC 61966-2-1: the two pieces meet (within their published rounding), the functions invert
// each other, and the table is srgb_to_linear rounded once to float.
// Every texel of every level lies within its block's range and its coarse cell's, and each
// block's bounds are attained within one float step (8-bit: decoded; float: a NaN makes the
// block's range everything).
void expect_ranges_hold(const Texture& texture) {
  ASSERT_EQ(texture.texel_ranges().size(), texture.mip_levels().size());
  for (std::size_t i = 0; i < texture.mip_levels().size(); ++i) {
    const TextureLevel& level = texture.mip_levels()[i];
    const TexelRanges& r = texture.texel_ranges()[i];
    ASSERT_EQ(r.columns, (level.width + 7) / 8);
    ASSERT_EQ(r.rows, (level.height + 7) / 8);
    std::vector<float> seen_low(r.low.size(), std::numeric_limits<float>::infinity());
    std::vector<float> seen_high(r.high.size(), -std::numeric_limits<float>::infinity());
    std::vector<bool> nan(r.low.size(), false);
    for (std::int32_t y = 0; y < level.height; ++y) {
      for (std::int32_t x = 0; x < level.width; ++x) {
        float v[4];
        texture.linear_texel(level, x, y, v);
        const std::size_t block = 4 * (static_cast<std::size_t>(y / 8) * r.columns + x / 8);
        const std::size_t cell = 4 * (static_cast<std::size_t>(y / 32) * r.coarse_columns + x / 32);
        for (int k = 0; k < 4; ++k) {
          if (std::isnan(v[k])) {
            nan[block + k] = true;
            continue;
          }
          EXPECT_LE(r.low[block + k], v[k]);
          EXPECT_GE(r.high[block + k], v[k]);
          EXPECT_LE(r.coarse_low[cell + k], v[k]);
          EXPECT_GE(r.coarse_high[cell + k], v[k]);
          seen_low[block + k] = std::min(seen_low[block + k], v[k]);
          seen_high[block + k] = std::max(seen_high[block + k], v[k]);
        }
      }
    }
    for (std::size_t b = 0; b < r.low.size(); ++b) {
      if (nan[b]) {
        EXPECT_EQ(r.low[b], -std::numeric_limits<float>::infinity());
        EXPECT_EQ(r.high[b], std::numeric_limits<float>::infinity());
      } else {
        EXPECT_EQ(r.low[b], std::nextafter(seen_low[b], -INFINITY)) << "level " << i;
        EXPECT_EQ(r.high[b], std::nextafter(seen_high[b], INFINITY)) << "level " << i;
      }
    }
  }
}

TEST(Texture, TexelRangesBoundEveryLevel) {
  std::vector<std::uint8_t> bytes(static_cast<std::size_t>(53) * 37 * 4);
  std::uint32_t state = 12345;
  for (std::uint8_t& b : bytes) {
    state = state * 1664525u + 1013904223u;
    b = static_cast<std::uint8_t>(state >> 24);
  }
  for (ColorEncoding encoding : {ColorEncoding::linear, ColorEncoding::srgb}) {
    for (PyramidFilter filter : {PyramidFilter::box, PyramidFilter::lanczos3})
      expect_ranges_hold(Texture::from_rgba8(53, 37, bytes, encoding, {filter}));
  }
  std::vector<float> floats(static_cast<std::size_t>(40) * 24 * 4);
  for (std::size_t i = 0; i < floats.size(); ++i)
    floats[i] = static_cast<float>((i * 2654435761u) % 1000) / 250.0f - 1.0f;
  floats[4 * (9 * 40 + 17) + 2] = std::numeric_limits<float>::quiet_NaN();
  expect_ranges_hold(Texture::from_rgba32f(40, 24, floats));
}

TEST(Srgb, TransferFunctionsAndTable) {
  EXPECT_EQ(srgb_to_linear(0.0), 0.0);
  EXPECT_EQ(srgb_to_linear(1.0), 1.0);
  EXPECT_EQ(linear_to_srgb(0.0), 0.0);
  // 1.055 - 0.055 rounds to 1 within an ulp or two of pow's result.
  EXPECT_NEAR(linear_to_srgb(1.0), 1.0, 4e-16);
  // The published constants make the pieces meet within 1e-7 (0.04045 / 12.92 = 0.0031308...).
  EXPECT_NEAR(srgb_to_linear(0.04045), std::pow((0.04045 + 0.055) / 1.055, 2.4), 1e-7);
  for (int i = 0; i <= 1000; ++i) {
    const double c = i / 1000.0;
    // Each direction is a few double operations and a pow (< 1 ulp each): 1e-14 is generous for
    // values of at most 1, and far below any code step (1/255).
    EXPECT_NEAR(linear_to_srgb(srgb_to_linear(c)), c, 1e-14) << c;
  }
  // Outside [0, 1] clamps; NaN reads as 0.
  EXPECT_EQ(srgb_to_linear(-2.0), 0.0);
  EXPECT_EQ(srgb_to_linear(7.0), 1.0);
  EXPECT_EQ(linear_to_srgb(std::numeric_limits<double>::quiet_NaN()), 0.0);
  EXPECT_EQ(srgb_to_linear(std::numeric_limits<double>::quiet_NaN()), 0.0);
  // Linear 0.5 is code 187.5...: 188.
  EXPECT_EQ(std::lround(255.0 * linear_to_srgb(0.5)), 188);
  const std::span<const float, 256> table = srgb_decode_table();
  for (int code = 0; code < 256; ++code) {
    EXPECT_EQ(table[code], static_cast<float>(srgb_to_linear(code / 255.0))) << code;
    if (code > 0) {
      EXPECT_LT(table[code - 1], table[code]);
    }
  }
  EXPECT_EQ(table[0], 0.0f);
  EXPECT_EQ(table[255], 1.0f);
}

TEST(Texture, PyramidFilterNames) {
  for (PyramidFilter filter : {PyramidFilter::box, PyramidFilter::lanczos3}) {
    EXPECT_EQ(parse_name<PyramidFilter>(name_of(filter)), filter);
  }
  EXPECT_EQ(name_of(PyramidFilter::lanczos3), "lanczos3");
  EXPECT_FALSE(parse_name<PyramidFilter>("Box").has_value());
  EXPECT_FALSE(parse_name<PyramidFilter>("").has_value());
}

}  // namespace
}  // namespace edgewise::test
