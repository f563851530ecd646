// Masks of whole rows and columns of an 8x8 tile (bit y * 8 + x).
#pragma once

#include <cstdint>

#include "edgewise/coverage.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

static_assert(kTileSize == 8, "tile masks are 64-bit: 8 x 8 pixels");

// Rows first .. end - 1 (0 <= first < end <= 8).
inline std::uint64_t row_bits(int first, int end) {
  return (~std::uint64_t{0} << (8 * first)) & (~std::uint64_t{0} >> (8 * (kTileSize - end)));
}

// Columns first .. end - 1 in every row (0 <= first < end <= 8).
inline std::uint64_t column_bits(int first, int end) {
  const std::uint64_t byte = (0xFFu << first) & (0xFFu >> (kTileSize - end));
  return byte * 0x0101010101010101ull;
}

// Bit y set when row y of `mask` has any bit set. Each row's bits are first folded into its
// lowest bit (bit 8y); multiplying by the constant then moves bit 8y to bit 56 + y (it adds
// copies shifted by 7k + 7 for k = 0 .. 7, and 8y + 7k + 7 = 56 + y exactly when k = 7 - y),
// and no two (y, k) pairs meet at one bit, so nothing carries.
inline std::uint32_t covered_rows(std::uint64_t mask) {
  mask |= mask >> 4;
  mask |= mask >> 2;
  mask |= mask >> 1;
  mask &= 0x0101010101010101ull;
  return static_cast<std::uint32_t>((mask * 0x0102040810204080ull) >> 56);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
