// The box resolve of a multisampled target (factor 1): each pixel's samples summed in integers, a
// tile row of pixels per batch, R and B in the two 16-bit halves of one lane and G and A in
// those of another (at most 16 samples of 255: below 2^16). A tile's samples are consecutive
// (framebuffer.hpp), so the source is read once, in order. The sample counts are powers of two,
// so the mean rounded half up is (sum + samples / 2) >> log2(samples) in each half, as the
// reference's exact quotient rounds; sRGB codes of the colour sums come from the call's table.
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <cstring>

#include <xsimd/xsimd.hpp>

#include "resolve_call.hpp"
#include "../simd/lane_arch-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// Output rows [8 first_tile_row, 8 last_tile_row).
template <class Arch>
void resolve_box_tiles(const detail::ResolveCall& call, std::int32_t first_tile_row,
                       std::int32_t last_tile_row) {
  static_assert(std::endian::native == std::endian::little,
                "packed colour is R | G << 8 | B << 16 | A << 24, stored as bytes R, G, B, A");
  using Words = xsimd::batch<std::uint32_t, Arch>;
  constexpr std::size_t kLanes = Words::size;
  static_assert(64 % kLanes == 0);
  const auto samples = static_cast<std::size_t>(call.samples);
  const auto shift = static_cast<std::int32_t>(std::countr_zero(samples));
  const Words low_bytes(0x00FF00FFu);
  const Words rounding(static_cast<std::uint32_t>(samples / 2) * 0x00010001u);
  alignas(64) std::uint32_t packed[64];
  alignas(64) std::uint32_t red_blue[64], green_alpha[64];
  for (std::int32_t ty = first_tile_row; ty < last_tile_row; ++ty) {
    const std::int32_t rows = std::min(8, call.height - ty * 8);
    for (std::int32_t tx = 0; tx < call.tiles_x; ++tx) {
      const std::uint32_t* tile =
          call.tiles + (static_cast<std::size_t>(ty) * call.tiles_x + tx) * samples * 64;
      const std::int32_t x0 = tx * 8;
      const auto columns = static_cast<std::size_t>(std::min(8, call.width - x0));
      // Linear codes of a tile's whole rows go straight to the image; the others through
      // `packed`.
      const bool direct = !call.srgb && columns == 8;
      const auto row_start = [&](std::size_t row) {
        const std::size_t y = static_cast<std::size_t>(ty) * 8 + row;
        return call.rgba + (y * static_cast<std::size_t>(call.width) + x0) * 4;
      };
      for (std::size_t p = 0; p < 64; p += kLanes) {
        Words even(0u), odd(0u);
        for (std::size_t k = 0; k < samples; ++k) {
          const Words c = Words::load_aligned(tile + k * 64 + p);
          even += c & low_bytes;
          odd += (c >> 8) & low_bytes;
        }
        const Words mean_even = ((even + rounding) >> shift) & low_bytes;
        const Words mean_odd = ((odd + rounding) >> shift) & low_bytes;
        const Words codes = mean_even | (mean_odd << 8);
        if (direct) {
          if (static_cast<std::int32_t>(p / 8) < rows) {
            alignas(64) std::uint32_t lanes[kLanes];  // a constant-size copy: one store
            codes.store_aligned(lanes);
            std::memcpy(row_start(p / 8) + (p % 8) * 4, lanes, sizeof lanes);
          }
          continue;
        }
        codes.store_aligned(packed + p);
        if (call.srgb) {
          even.store_aligned(red_blue + p);
          odd.store_aligned(green_alpha + p);
        }
      }
      if (direct) continue;
      if (call.srgb) {  // R, G and B by the table; alpha stays the linear mean
        const std::uint8_t* table = call.colour_codes.data();
        for (std::size_t p = 0; p < 64; ++p) {
          packed[p] = table[red_blue[p] & 0xFFFFu] |
                      std::uint32_t{table[green_alpha[p] & 0xFFFFu]} << 8 |
                      std::uint32_t{table[red_blue[p] >> 16]} << 16 | (packed[p] & 0xFF000000u);
        }
      }
      for (std::int32_t row = 0; row < rows; ++row)
        std::memcpy(row_start(static_cast<std::size_t>(row)), packed + row * 8, columns * 4);
    }
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
