// A validated resolve() call (resolve.hpp) as the kernels see it: the source's tiles, the output
// span, and what is found once per call: the filter's taps and the 8-bit codes of the results.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>

namespace edgewise::detail {

// One sample every output pixel weighs alike: sample `sample` of the source pixel (i, j) from the
// output pixel's first source pixel (f x, f y).
struct ResolveTap {
  std::int32_t i, j;
  std::int32_t sample;
  float weight;  // normalized: a call's weights sum to 1
};

// The linear values where each sRGB code begins: code c + 1 is the nearest for values from
// thresholds[c] (the linear value of the encoding (c + 1/2) / 255).
const std::array<float, 255>& srgb_code_thresholds();

// The 8-bit code of the filtered value v: clamped to [0, 1] (NaN to 0), then linear or, for
// colour channels of an sRGB output, sRGB-encoded, rounded to nearest. The reference's: the sRGB
// code found by binary search over the thresholds.
std::uint8_t encode_resolved(float v, bool srgb_colour);

// The sRGB code of a value in [0, 1] in constant time, equal to encode_resolved()'s: [0, 1] cut
// into 4096 cells, narrower than the thresholds' smallest gap (1 / (255 * 12.92) at 0), so a cell
// holds at most one threshold (checked as the table is made) and the code is the cell's first
// code, plus one from that threshold on.
struct SrgbCodeCells {
  static constexpr int kCells = 4096;
  std::array<std::uint8_t, kCells + 1> first_code;  // the code of the cell's lowest value
  std::array<float, kCells + 1> next_threshold;     // the first threshold above it (or 2)

  std::uint8_t code(float clamped) const {
    const auto cell = static_cast<std::size_t>(clamped * static_cast<float>(kCells));
    return static_cast<std::uint8_t>(first_code[cell] + (clamped >= next_threshold[cell] ? 1 : 0));
  }
};
const SrgbCodeCells& srgb_code_cells();

struct ResolveCall {
  const std::uint32_t* tiles;  // the source's colour tiles (framebuffer.hpp)
  std::int32_t tiles_x;
  std::int32_t source_width, source_height;
  std::int32_t samples;
  std::int32_t factor;         // supersampling, per axis
  std::int32_t width, height;  // the output's
  std::uint8_t* rgba;          // width * height * 4 bytes, row-major
  bool srgb;
  const SrgbCodeCells* srgb_cells;
  // Box filter at factor 1: the code of each channel sum of a pixel's `samples` values, index
  // 0 to 255 samples (the mean rounded to nearest, R, G and B sRGB-encoded when srgb).
  std::span<const std::uint8_t> colour_codes;
  // The other filters: every output pixel's taps.
  std::span<const ResolveTap> taps;

  // Sample `sample` of pixel (x, y) in the tiled storage; the tile row's 8 pixels follow it
  // when x is a multiple of 8.
  const std::uint32_t* pixel(std::int32_t x, std::int32_t y, std::int32_t sample) const {
    const std::size_t tile = static_cast<std::size_t>(y / 8) * static_cast<std::size_t>(tiles_x) +
                             static_cast<std::size_t>(x / 8);
    return tiles +
           (tile * static_cast<std::size_t>(samples) + static_cast<std::size_t>(sample)) * 64 +
           static_cast<std::size_t>((y % 8) * 8 + x % 8);
  }
  std::uint32_t color(std::int32_t x, std::int32_t y, std::int32_t sample) const {
    return *pixel(x, y, sample);
  }
};

}  // namespace edgewise::detail
