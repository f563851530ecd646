// Textures: level 0 and the pyramids built from it (mipmaps, ripmaps, a summed-area table).
//
// Conventions (docs/design/textures.md): texture coordinates (s, t) cover [0, 1) over the
// image, s to the right, t down; texel (a, b) of a W x H level is centered at
// ((a + 0.5) / W, (b + 0.5) / H).
// Texels are RGBA, row-major, row 0 first. 8-bit texels are linear values v / 255, or sRGB-encoded
// when the texture says so; every filter works on linear values.
//
// The kernels take memory: loading image files is left to the caller (the tools use OpenImageIO).
//
// Thread safety: a built Texture never changes; its const members, and sample() and draw() on
// it, may be used from any number of threads at once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "edgewise/framebuffer.hpp"  // detail::TileAlignedAllocator
#include "edgewise/names.hpp"

namespace edgewise {

enum class TexelFormat : std::uint8_t {
  rgba8,    // 4 bytes per texel: R, G, B, A in memory order
  rgba32f,  // 4 floats per texel, linear, any value (HDR allowed)
};

enum class ColorEncoding : std::uint8_t {
  linear,  // 8-bit texel v means v / 255
  srgb,    // R, G and B are sRGB-encoded (IEC 61966-2-1); alpha stays linear
};

// How a pyramid level is made from the finer one.
enum class PyramidFilter : std::uint8_t {
  // The area average over each coarse texel's footprint: a 2x2 box where the size is even, and
  // for an odd size the exact box of width 2 + 1/n spread over three texels, so no level shifts.
  box,
  // Lanczos (a = 3) scaled to the coarse level's spacing: sharper, with some ringing, clamped to
  // the storable range for 8-bit levels.
  lanczos3,
};

// What to build besides the mipmaps (each costs memory: ripmaps about 4x level 0, the
// summed-area table 32 bytes per texel).
struct TextureBuild {
  PyramidFilter filter = PyramidFilter::box;
  bool ripmaps = false;
  bool summed_area_table = false;
};

// One level of a pyramid: width x height texels, row-major, in the texture's format.
struct TextureLevel {
  std::int32_t width = 0;
  std::int32_t height = 0;
  std::size_t offset = 0;  // into Texture::storage(), in bytes; a multiple of 64
};

// Prefix sums of level 0's linear values. Entry (x, y), 0 <= x <= W, 0 <= y <= H, at
// sums[4 * (y * (W + 1) + x) + channel], is the sum over texels [0, x) x [0, y).
//
// Precision: 8-bit texels are summed as integers in units of 1/65535 (257 v for a linear v, and
// the sRGB-decoded value rounded to 16 bits for an sRGB one), so every entry is an integer below
// 65535 W H, exact in double while W H < 2^37; box sums taken as differences of entries are then
// exact for any texture that fits in memory. Float texels are summed in double: an entry's
// rounding error is below (x + y) 2^-53 times the sum of |value| over its rectangle.
// (float32 entries would lose exactness once 255 W H passes 2^24, about 256 x 256 texels.)
struct SummedAreaTable {
  std::int32_t width = 0;   // of level 0
  std::int32_t height = 0;  // of level 0
  double scale = 1.0;       // linear value = sum * scale (1/65535 for 8-bit textures, else 1)
  std::vector<double> sums;
};

// Per block of kBlock x kBlock texels of one level (the blocks of the last row and column cut
// by the edges), the least and the greatest linear value of each channel, sRGB decoded and
// rounded outwards: every filter that reads a level's texels with weights from 0 to 1 lands
// within the range of the blocks it reads. draw() reads them to bound a texture over a tile
// under an error budget (draw.hpp). A block holding a NaN texel has the range [-inf, +inf].
struct TexelRanges {
  static constexpr std::int32_t kBlock = 8;
  std::int32_t columns = 0, rows = 0;  // blocks per row and per column
  std::vector<float> low, high;        // 4 per block: block (i, j) at 4 * (j * columns + i)
  // The same over coarse cells of kCoarse x kCoarse blocks, for wide regions.
  static constexpr std::int32_t kCoarse = 4;
  std::int32_t coarse_columns = 0, coarse_rows = 0;
  std::vector<float> coarse_low, coarse_high;
};

// An immutable texture: level 0 and its mipmaps, optionally ripmaps and a summed-area table.
// Level i + 1 is max(1, floor(w_i / 2)) x max(1, floor(h_i / 2)) down to 1 x 1. Ripmap level (i, j)
// is mip width i by mip height j, filtered one axis at a time; level (i, i) is mip level i for the
// box filter. Every level's texels start 64-byte aligned.
class Texture {
 public:
  // Copies width x height texels (row stride `width`). Throws std::invalid_argument for a size
  // below 1, above 2^15 on either axis, or a span of the wrong length.
  static Texture from_rgba8(std::int32_t width, std::int32_t height,
                            std::span<const std::uint8_t> texels, ColorEncoding encoding,
                            const TextureBuild& build = {});
  static Texture from_rgba32f(std::int32_t width, std::int32_t height,
                              std::span<const float> texels, const TextureBuild& build = {});

  TexelFormat format() const { return format_; }
  ColorEncoding encoding() const { return encoding_; }
  std::int32_t width() const { return levels_[0].width; }
  std::int32_t height() const { return levels_[0].height; }

  std::span<const TextureLevel> mip_levels() const { return levels_; }
  // Ripmap levels, (i, j) at [j * ripmap_columns() + i]; empty when not built.
  std::span<const TextureLevel> ripmap_levels() const { return ripmaps_; }
  int ripmap_columns() const { return static_cast<int>(ripmap_columns_); }
  // Null when not built.
  const SummedAreaTable* summed_area_table() const { return sat_.sums.empty() ? nullptr : &sat_; }
  // The filter the mipmaps (and ripmaps) were made with.
  PyramidFilter pyramid_filter() const { return pyramid_; }
  // Per mip level, always built (1/64 of the texel count in blocks).
  std::span<const TexelRanges> texel_ranges() const { return ranges_; }

  const std::byte* storage() const { return storage_.data(); }
  const std::byte* texels(const TextureLevel& level) const {
    return storage_.data() + level.offset;
  }
  // Linear RGBA of texel (x, y) of `level` (0 <= x < width, 0 <= y < height), sRGB decoded.
  void linear_texel(const TextureLevel& level, std::int32_t x, std::int32_t y, float out[4]) const;

 private:
  TexelFormat format_ = TexelFormat::rgba8;
  ColorEncoding encoding_ = ColorEncoding::linear;
  std::vector<TextureLevel> levels_;
  std::vector<TextureLevel> ripmaps_;
  std::size_t ripmap_columns_ = 0;
  SummedAreaTable sat_;
  std::vector<TexelRanges> ranges_;
  PyramidFilter pyramid_ = PyramidFilter::box;
  std::vector<std::byte, detail::TileAlignedAllocator<std::byte>> storage_;

  friend class TextureBuilder;  // the library's: fills a Texture from level 0
};

// sRGB transfer functions (IEC 61966-2-1), on [0, 1].
double srgb_to_linear(double encoded);
double linear_to_srgb(double linear);
// The 256 decoded values of 8-bit sRGB codes, as float (the fast kernels' table).
std::span<const float, 256> srgb_decode_table();

// Names of the values (names.hpp).
std::string_view name_of(TexelFormat value);
template <>
std::span<const TexelFormat> values_of<TexelFormat>();
std::string_view name_of(ColorEncoding value);
template <>
std::span<const ColorEncoding> values_of<ColorEncoding>();
std::string_view name_of(PyramidFilter value);
template <>
std::span<const PyramidFilter> values_of<PyramidFilter>();

}  // namespace edgewise
