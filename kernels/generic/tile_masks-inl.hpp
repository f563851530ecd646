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

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
