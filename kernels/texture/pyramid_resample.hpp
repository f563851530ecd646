// Making a pyramid level from the next finer one (texture.hpp, PyramidFilter).
#pragma once

#include <cstddef>
#include <cstdint>

#include "edgewise/texture.hpp"

namespace edgewise::detail {

// Stored texels of one level (row-major, RGBA, in the texture's format).
struct LevelView {
  const std::byte* texels;
  std::int32_t width;
  std::int32_t height;
};

// Resamples `source` to `width` x `height` (each at most the source's size) into `destination`,
// which holds width * height texels of the same format. Each axis whose size changes is filtered
// on its own (the filters are separable); an axis that keeps its size is copied. Values are
// filtered as linear doubles: 8-bit sRGB texels are decoded first and re-encoded after, 8-bit
// results are rounded to the nearest code and clamped to 0 .. 255, float results are rounded
// to float and not clamped (NaN and infinity spread to every texel whose filter reads them).
void resample_level(TexelFormat format, ColorEncoding encoding, PyramidFilter filter,
                    const LevelView& source, std::byte* destination, std::int32_t width,
                    std::int32_t height);

}  // namespace edgewise::detail
