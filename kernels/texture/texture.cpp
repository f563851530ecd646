// Texture construction: validation, the layout of every level in one 64-byte-aligned block, and
// the pyramids made from level 0.
//
// Float texels are stored as given, NaN and infinity included: they are the caller's data (HDR
// values are legitimate), and a coarser level or summed-area entry whose footprint holds a
// non-finite texel is non-finite too.
#include <algorithm>
#include <bit>
#include <cmath>
#include <cstring>
#include <limits>
#include <stdexcept>
#include <string>

#include "edgewise/texture.hpp"
#include "pyramid_resample.hpp"
#include "summed_area_table.hpp"

namespace edgewise {
namespace {

constexpr std::int32_t kMaxTextureSize = 1 << 15;
// Every level starts on the storage's own alignment.
constexpr std::size_t kLevelAlignment = 64;
static_assert(static_cast<std::size_t>(detail::TileAlignedAllocator<std::byte>::kAlignment) ==
              kLevelAlignment);

std::size_t texel_bytes(TexelFormat format) {
  return format == TexelFormat::rgba8 ? 4 : 16;
}

void validate(const char* function, std::int32_t width, std::int32_t height, std::size_t values) {
  if (width < 1 || width > kMaxTextureSize || height < 1 || height > kMaxTextureSize) {
    throw std::invalid_argument(std::string(function) + ": size " + std::to_string(width) + "x" +
                                std::to_string(height) + " is outside 1.." +
                                std::to_string(kMaxTextureSize) + " texels per side");
  }
  const std::size_t expected = static_cast<std::size_t>(width) * height * 4;
  if (values != expected) {
    throw std::invalid_argument(std::string(function) + ": " + std::to_string(values) +
                                " values for " + std::to_string(width) + "x" +
                                std::to_string(height) + " texels, expected " +
                                std::to_string(expected) + " (4 per texel)");
  }
}

}  // namespace

// Fills a Texture: level sizes and offsets first, then one allocation, then the levels in the
// order they depend on each other.
class TextureBuilder {
 public:
  static Texture build(TexelFormat format, ColorEncoding encoding, std::int32_t width,
                       std::int32_t height, const std::byte* level0, const TextureBuild& build) {
    Texture texture;
    texture.format_ = format;
    texture.encoding_ = encoding;
    texture.pyramid_ = build.filter;
    TextureBuilder builder(texture, format);

    // Mipmaps: halve (rounding down, never below 1) until 1 x 1.
    for (std::int32_t w = width, h = height;; w = std::max(1, w / 2), h = std::max(1, h / 2)) {
      texture.levels_.push_back(builder.place(w, h));
      if (w == 1 && h == 1) break;
    }
    // Ripmaps: every mip width by every mip height; (i, i) is mip level i itself.
    const int columns = std::bit_width(static_cast<std::uint32_t>(width));
    const int rows = std::bit_width(static_cast<std::uint32_t>(height));
    if (build.ripmaps) {
      texture.ripmap_columns_ = static_cast<std::size_t>(columns);
      for (int j = 0; j < rows; ++j) {
        for (int i = 0; i < columns; ++i) {
          texture.ripmaps_.push_back(i == j ? texture.levels_[i]
                                            : builder.place(width >> i, height >> j));
        }
      }
    }
    texture.storage_.assign(builder.bytes_, std::byte{0});

    std::memcpy(texture.storage_.data(), level0,
                static_cast<std::size_t>(width) * height * texel_bytes(format));
    for (std::size_t i = 1; i < texture.levels_.size(); ++i) {
      builder.resample(build.filter, texture.levels_[i - 1], texture.levels_[i]);
    }
    if (build.ripmaps) {
      // Away from the diagonal one axis at a time: along each row of rip levels (width halving)
      // right of the diagonal, along each column (height halving) below it.
      auto rip = [&](int i, int j) -> const TextureLevel& {
        return texture.ripmaps_[static_cast<std::size_t>(j) * columns + i];
      };
      for (int j = 0; j < rows; ++j) {
        for (int i = j + 1; i < columns; ++i)
          builder.resample(build.filter, rip(i - 1, j), rip(i, j));
      }
      for (int i = 0; i < columns; ++i) {
        for (int j = i + 1; j < rows; ++j)
          builder.resample(build.filter, rip(i, j - 1), rip(i, j));
      }
    }
    if (build.summed_area_table) {
      texture.sat_ =
          detail::build_summed_area_table(format, encoding, builder.view(texture.levels_[0]));
    }
    for (const TextureLevel& level : texture.levels_)
      texture.ranges_.push_back(build_texel_ranges(texture, level));
    return texture;
  }

 private:
  // TexelRanges of a level: the blocks' least and greatest codes (or floats), decoded as the
  // sampler decodes them and widened by one float step each way; then the coarse cells' from
  // their blocks'.
  static TexelRanges build_texel_ranges(const Texture& texture, const TextureLevel& level) {
    constexpr std::int32_t kBlock = TexelRanges::kBlock;
    TexelRanges ranges;
    ranges.columns = (level.width + kBlock - 1) / kBlock;
    ranges.rows = (level.height + kBlock - 1) / kBlock;
    const std::size_t blocks = static_cast<std::size_t>(ranges.columns) * ranges.rows;
    ranges.low.assign(4 * blocks, kInfinityF);
    ranges.high.assign(4 * blocks, -kInfinityF);
    if (texture.format_ == TexelFormat::rgba8) {
      code_block_ranges(texture, level, ranges);
    } else {
      float_block_ranges(texture, level, ranges);
    }
    coarse_ranges(ranges);
    return ranges;
  }

  static constexpr float kInfinityF = std::numeric_limits<float>::infinity();

  // The blocks' ranges of an 8-bit level: least and greatest codes, then decoded.
  static void code_block_ranges(const Texture& texture, const TextureLevel& level,
                                TexelRanges& ranges) {
    constexpr std::int32_t kBlock = TexelRanges::kBlock;
    const std::size_t blocks = ranges.low.size() / 4;
    std::vector<std::uint8_t> low(4 * blocks, 255), high(4 * blocks, 0);
    const auto* codes = reinterpret_cast<const std::uint8_t*>(texture.texels(level));
    for (std::int32_t y = 0; y < level.height; ++y) {
      const std::uint8_t* row = codes + 4 * static_cast<std::size_t>(y) * level.width;
      const std::size_t first_block = static_cast<std::size_t>(y / kBlock) * ranges.columns;
      for (std::int32_t bx = 0; bx < ranges.columns; ++bx) {
        // The block's part of this row, channel by channel in registers.
        const std::int32_t end = std::min(level.width, (bx + 1) * kBlock);
        std::uint8_t* block_low = &low[4 * (first_block + static_cast<std::size_t>(bx))];
        std::uint8_t* block_high = &high[4 * (first_block + static_cast<std::size_t>(bx))];
        std::uint8_t lo[4], hi[4];
        for (int ch = 0; ch < 4; ++ch) {
          lo[ch] = block_low[ch];
          hi[ch] = block_high[ch];
        }
        for (std::int32_t x = bx * kBlock; x < end; ++x) {
          for (int ch = 0; ch < 4; ++ch) {
            lo[ch] = std::min(lo[ch], row[4 * x + ch]);
            hi[ch] = std::max(hi[ch], row[4 * x + ch]);
          }
        }
        for (int ch = 0; ch < 4; ++ch) {
          block_low[ch] = lo[ch];
          block_high[ch] = hi[ch];
        }
      }
    }
    const std::span<const float, 256> srgb = srgb_decode_table();
    for (std::size_t i = 0; i < 4 * blocks; ++i) {
      const bool decode = texture.encoding_ == ColorEncoding::srgb && i % 4 < 3;
      const auto linear = [&](std::uint8_t code) {
        return decode ? srgb[code] : static_cast<float>(code) / 255.0f;
      };
      ranges.low[i] = std::nextafter(linear(low[i]), -kInfinityF);
      ranges.high[i] = std::nextafter(linear(high[i]), kInfinityF);
    }
  }

  // The blocks' ranges of a float level; a NaN makes its channel's range unbounded.
  static void float_block_ranges(const Texture& texture, const TextureLevel& level,
                                 TexelRanges& ranges) {
    constexpr std::int32_t kBlock = TexelRanges::kBlock;
    const std::size_t blocks = ranges.low.size() / 4;
    std::vector<bool> has_nan(4 * blocks, false);
    for (std::int32_t y = 0; y < level.height; ++y) {
      const std::size_t first_block = static_cast<std::size_t>(y / kBlock) * ranges.columns;
      for (std::int32_t x = 0; x < level.width; ++x) {
        const std::size_t at = 4 * (first_block + static_cast<std::size_t>(x / kBlock));
        float v[4];
        std::memcpy(v, texture.texels(level) + 16 * (static_cast<std::size_t>(y) * level.width + x),
                    16);
        for (int ch = 0; ch < 4; ++ch) {
          if (std::isnan(v[ch])) has_nan[at + ch] = true;
          ranges.low[at + ch] = std::fmin(ranges.low[at + ch], v[ch]);
          ranges.high[at + ch] = std::fmax(ranges.high[at + ch], v[ch]);
        }
      }
    }
    for (std::size_t i = 0; i < 4 * blocks; ++i) {
      ranges.low[i] = has_nan[i] ? -kInfinityF : std::nextafter(ranges.low[i], -kInfinityF);
      ranges.high[i] = has_nan[i] ? kInfinityF : std::nextafter(ranges.high[i], kInfinityF);
    }
  }

  // Coarse cells: kCoarse x kCoarse blocks each.
  static void coarse_ranges(TexelRanges& ranges) {
    constexpr std::int32_t kCoarse = TexelRanges::kCoarse;
    ranges.coarse_columns = (ranges.columns + kCoarse - 1) / kCoarse;
    ranges.coarse_rows = (ranges.rows + kCoarse - 1) / kCoarse;
    const std::size_t cells = static_cast<std::size_t>(ranges.coarse_columns) * ranges.coarse_rows;
    ranges.coarse_low.assign(4 * cells, kInfinityF);
    ranges.coarse_high.assign(4 * cells, -kInfinityF);
    for (std::int32_t by = 0; by < ranges.rows; ++by) {
      for (std::int32_t bx = 0; bx < ranges.columns; ++bx) {
        const std::size_t from = 4 * (static_cast<std::size_t>(by) * ranges.columns + bx);
        const std::size_t to =
            4 * (static_cast<std::size_t>(by / kCoarse) * ranges.coarse_columns + bx / kCoarse);
        for (int ch = 0; ch < 4; ++ch) {
          ranges.coarse_low[to + ch] = std::min(ranges.coarse_low[to + ch], ranges.low[from + ch]);
          ranges.coarse_high[to + ch] =
              std::max(ranges.coarse_high[to + ch], ranges.high[from + ch]);
        }
      }
    }
  }

  TextureBuilder(Texture& texture, TexelFormat format)
      : texture_(texture), texel_bytes_(texel_bytes(format)) {}

  // The next level's place in the storage, 64-byte aligned.
  TextureLevel place(std::int32_t width, std::int32_t height) {
    const TextureLevel level{width, height, bytes_};
    const std::size_t size = static_cast<std::size_t>(width) * height * texel_bytes_;
    bytes_ += (size + kLevelAlignment - 1) / kLevelAlignment * kLevelAlignment;
    return level;
  }

  detail::LevelView view(const TextureLevel& level) const {
    return {texture_.storage_.data() + level.offset, level.width, level.height};
  }

  void resample(PyramidFilter filter, const TextureLevel& from, const TextureLevel& to) {
    detail::resample_level(texture_.format_, texture_.encoding_, filter, view(from),
                           texture_.storage_.data() + to.offset, to.width, to.height);
  }

  Texture& texture_;
  std::size_t texel_bytes_;
  std::size_t bytes_ = 0;
};

Texture Texture::from_rgba8(std::int32_t width, std::int32_t height,
                            std::span<const std::uint8_t> texels, ColorEncoding encoding,
                            const TextureBuild& build) {
  validate("Texture::from_rgba8", width, height, texels.size());
  return TextureBuilder::build(TexelFormat::rgba8, encoding, width, height,
                               reinterpret_cast<const std::byte*>(texels.data()), build);
}

Texture Texture::from_rgba32f(std::int32_t width, std::int32_t height,
                              std::span<const float> texels, const TextureBuild& build) {
  validate("Texture::from_rgba32f", width, height, texels.size());
  return TextureBuilder::build(TexelFormat::rgba32f, ColorEncoding::linear, width, height,
                               reinterpret_cast<const std::byte*>(texels.data()), build);
}

void Texture::linear_texel(const TextureLevel& level, std::int32_t x, std::int32_t y,
                           float out[4]) const {
  const std::size_t index = static_cast<std::size_t>(y) * level.width + x;
  if (format_ == TexelFormat::rgba32f) {
    std::memcpy(out, texels(level) + index * 16, 16);
    return;
  }
  const auto* code = reinterpret_cast<const std::uint8_t*>(texels(level)) + index * 4;
  const std::span<const float, 256> srgb = srgb_decode_table();
  for (int ch = 0; ch < 3; ++ch) {
    out[ch] = encoding_ == ColorEncoding::srgb ? srgb[code[ch]] : code[ch] / 255.0f;
  }
  out[3] = code[3] / 255.0f;
}

}  // namespace edgewise
