// A plain linear RGBA float image: the texture data and the ground-truth and filtered results
// that the accuracy tools compare, independent of edgewise::Texture's storage.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "edgewise/vector.hpp"

namespace edgewise::texture_scene {

struct LinearImage {
  std::int32_t width = 0;
  std::int32_t height = 0;
  std::vector<float> rgba;  // 4 per texel, row-major, row 0 first

  // A width x height image filled with `value` in every channel. Throws std::invalid_argument
  // for a negative size.
  static LinearImage filled(std::int32_t width, std::int32_t height, float value);

  std::size_t texel_index(std::int32_t x, std::int32_t y) const {
    return 4 * (static_cast<std::size_t>(y) * static_cast<std::size_t>(width) +
                static_cast<std::size_t>(x));
  }
  float* texel(std::int32_t x, std::int32_t y) { return rgba.data() + texel_index(x, y); }
  const float* texel(std::int32_t x, std::int32_t y) const {
    return rgba.data() + texel_index(x, y);
  }
};

// Rounds once to float; magnitudes beyond float's range become +-inf, NaN stays NaN (a plain
// conversion would be undefined behaviour there).
float round_to_float(double value);

// The 8-bit value q / 255 as stored in a LinearImage: float(q) / 255, which is also what an
// 8-bit linear texel decodes to in float.
float unorm8_value(std::uint8_t q);

// The RGBA8 bytes (linear encoding) of an image whose every value is some unorm8_value(q), so a
// Texture built from them holds exactly the image's values. Throws std::invalid_argument when a
// value is not of that form (or the image's rgba size does not match its width and height).
std::vector<std::uint8_t> to_rgba8(const LinearImage& image);

// A width x height image from one RGBA result per pixel, row-major (the layout of sample()'s
// output for a view's queries). Throws std::invalid_argument when the sizes disagree.
LinearImage image_from_samples(std::int32_t width, std::int32_t height,
                               std::span<const Vec4> samples);

}  // namespace edgewise::texture_scene
