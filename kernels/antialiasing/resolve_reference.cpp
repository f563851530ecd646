// resolve() in plain scalar code, a pixel at a time: the reference's kernels (kernel_table.hpp)
// and the oracle of every ISA's (resolve_box-inl.hpp, resolve_taps-inl.hpp).
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "../core/reference_kernels.hpp"
#include "resolve_call.hpp"

namespace edgewise::reference {

// Box filter at factor 1, output rows [8 first_tile_row, 8 last_tile_row): each channel's sum over
// the pixel's samples, its mean rounded to nearest (half up), or its sRGB code.
void resolve_box(const detail::ResolveCall& call, std::int32_t first_tile_row,
                 std::int32_t last_tile_row) {
  const auto samples = static_cast<std::uint64_t>(call.samples);
  const float scale = 1.0f / (255.0f * static_cast<float>(samples));
  const double inverse = 1.0 / static_cast<double>(samples);
  const std::int32_t last_row = std::min(last_tile_row * 8, call.height);
  for (std::int32_t y = first_tile_row * 8; y < last_row; ++y) {
    for (std::int32_t x = 0; x < call.width; ++x) {
      std::uint64_t sums[4] = {0, 0, 0, 0};
      for (std::int32_t k = 0; k < call.samples; ++k) {
        const std::uint32_t c = call.color(x, y, k);
        for (int channel = 0; channel < 4; ++channel)
          sums[channel] += (c >> (8 * channel)) & 0xFFu;
      }
      std::uint8_t* out = call.rgba + (static_cast<std::size_t>(y) * call.width + x) * 4;
      for (int channel = 0; channel < 4; ++channel) {
        // The mean rounded half up (the sum over a power of two is exact in double).
        out[channel] =
            call.srgb && channel < 3
                ? detail::encode_resolved(static_cast<float>(sums[channel]) * scale, true)
                : static_cast<std::uint8_t>(static_cast<double>(sums[channel]) * inverse + 0.5);
      }
    }
  }
}

// Tent and Mitchell, output rows [first_row, last_row): each channel's weighted sum over the
// taps in their order, source coordinates clamped to the image, then encoded.
void resolve_taps(const detail::ResolveCall& call, std::int32_t first_row, std::int32_t last_row) {
  const std::int32_t f = call.factor;
  for (std::int32_t y = first_row; y < last_row; ++y) {
    for (std::int32_t x = 0; x < call.width; ++x) {
      float sums[4] = {0.0f, 0.0f, 0.0f, 0.0f};
      for (const detail::ResolveTap& tap : call.taps) {
        const std::int32_t sx = std::clamp(x * f + tap.i, 0, call.source_width - 1);
        const std::int32_t sy = std::clamp(y * f + tap.j, 0, call.source_height - 1);
        const std::uint32_t c = call.color(sx, sy, tap.sample);
        for (int channel = 0; channel < 4; ++channel)
          sums[channel] += tap.weight * static_cast<float>((c >> (8 * channel)) & 0xFFu);
      }
      std::uint8_t* out = call.rgba + (static_cast<std::size_t>(y) * call.width + x) * 4;
      for (int channel = 0; channel < 4; ++channel)
        out[channel] =
            detail::encode_resolved(sums[channel] * (1.0f / 255.0f), call.srgb && channel < 3);
    }
  }
}

}  // namespace edgewise::reference
