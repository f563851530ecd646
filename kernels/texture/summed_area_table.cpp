// The summed-area table: entry (x, y) = entry (x, y - 1) + the sum of row y - 1's first x texels.
#include "summed_area_table.hpp"

#include <array>
#include <cmath>
#include <cstring>

namespace edgewise::detail {
namespace {

// 8-bit texels as integers in units of 1/65535: 257 v is exactly v / 255, and an sRGB colour
// code's decoded value is rounded to the nearest unit (alpha is always linear).
struct IntegerUnits {
  std::array<double, 256> colour;
  std::array<double, 256> alpha;
  explicit IntegerUnits(ColorEncoding encoding) {
    for (int v = 0; v < 256; ++v) {
      alpha[v] = 257.0 * v;
      colour[v] = encoding == ColorEncoding::srgb ? std::round(65535.0 * srgb_to_linear(v / 255.0))
                                                  : alpha[v];
    }
  }
};

}  // namespace

SummedAreaTable build_summed_area_table(TexelFormat format, ColorEncoding encoding,
                                        const LevelView& level0) {
  SummedAreaTable table;
  table.width = level0.width;
  table.height = level0.height;
  table.scale = format == TexelFormat::rgba8 ? 1.0 / 65535.0 : 1.0;
  const std::size_t stride = (static_cast<std::size_t>(level0.width) + 1) * 4;
  table.sums.assign(stride * (static_cast<std::size_t>(level0.height) + 1), 0.0);

  const IntegerUnits units(encoding);
  for (std::int32_t y = 0; y < level0.height; ++y) {
    const double* above = table.sums.data() + static_cast<std::size_t>(y) * stride;
    double* entry = table.sums.data() + static_cast<std::size_t>(y + 1) * stride;
    double row_sum[4] = {0.0, 0.0, 0.0, 0.0};
    for (std::int32_t x = 0; x < level0.width; ++x) {
      const std::size_t index = static_cast<std::size_t>(y) * level0.width + x;
      double value[4];
      if (format == TexelFormat::rgba8) {
        const auto* code = reinterpret_cast<const std::uint8_t*>(level0.texels) + index * 4;
        for (int ch = 0; ch < 3; ++ch)
          value[ch] = units.colour[code[ch]];
        value[3] = units.alpha[code[3]];
      } else {
        float texel[4];
        std::memcpy(texel, level0.texels + index * sizeof(texel), sizeof(texel));
        for (int ch = 0; ch < 4; ++ch)
          value[ch] = texel[ch];
      }
      for (int ch = 0; ch < 4; ++ch) {
        row_sum[ch] += value[ch];
        entry[(x + 1) * 4 + ch] = above[(x + 1) * 4 + ch] + row_sum[ch];
      }
    }
  }
  return table;
}

}  // namespace edgewise::detail
