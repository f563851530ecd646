// The rectangle test of the occlusion queries, written once over xsimd batches: a tile whose
// exact maximum lies at or below the rectangle's depth is passed over whole; in the others, the
// depths above it are found in lanes and masked by the rectangle's rows and columns (no branch per
// sample). The first such depth decides visible.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "edgewise/occlusion.hpp"
#include "occlusion_call.hpp"
#include "../simd/lane_arch-inl.hpp"
#include "../simd/simd_ops-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// The rectangle's samples in tile (tx, ty) as a tile mask (bit row * 8 + column, as coverage
// masks are laid out).
inline std::uint64_t rect_tile_mask(const detail::SampleRect& r, std::int32_t tx, std::int32_t ty) {
  const std::int32_t column0 = std::max(r.x0 - tx * 8, 0), column1 = std::min(r.x1 - tx * 8, 7);
  const std::int32_t row0 = std::max(r.y0 - ty * 8, 0), row1 = std::min(r.y1 - ty * 8, 7);
  const std::uint64_t columns = (0xFFull >> (7 - column1)) & (0xFFull << column0);
  const std::uint64_t rows = (~0ull >> (8 * (7 - row1))) & (~0ull << (8 * row0));
  return columns * 0x0101010101010101ull & rows;
}

// Bit i of the result: depth i of the tile lies above `limit`.
template <class Arch>
[[gnu::always_inline]] inline std::uint64_t depths_above(const float* tile, float limit) {
  using Floats = xsimd::batch<float, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  const Floats bound(limit);
  std::uint64_t above = 0;
  for (std::size_t i = 0; i < 64; i += kLanes) {
    const std::uint64_t bits = bits_of_lanes<Arch>(Floats::load_aligned(tile + i) > bound);
    above |= bits << i;
  }
  return above;
}

// Visible when some sample of the rectangle holds a depth above the rectangle's: tiles whose
// maximum lies at or below it are passed over whole, the others compared sample by sample.
template <class Arch>
Visibility test_rect(const detail::OcclusionDepth& depth, const detail::SampleRect& r) {
  if (r.x0 > r.x1 || r.y0 > r.y1) return Visibility::outside;
  for (std::int32_t ty = r.y0 >> 3; ty <= r.y1 >> 3; ++ty) {
    for (std::int32_t tx = r.x0 >> 3; tx <= r.x1 >> 3; ++tx) {
      const std::size_t tile = static_cast<std::size_t>(ty) * depth.tiles_x + tx;
      if (!(depth.tile_max[tile] > r.depth)) continue;
      if ((depths_above<Arch>(depth.tiles + tile * 64, r.depth) & rect_tile_mask(r, tx, ty)) != 0)
        return Visibility::visible;
    }
  }
  return Visibility::occluded;
}

// The largest depth of each tile of [first, last).
template <class Arch>
void tile_maxima(const float* tiles, std::size_t first, std::size_t last, float* out) {
  using Floats = xsimd::batch<float, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  for (std::size_t t = first; t < last; ++t) {
    const float* tile = tiles + t * 64;
    Floats largest = Floats::load_aligned(tile);
    for (std::size_t i = kLanes; i < 64; i += kLanes)
      largest = xsimd::max(largest, Floats::load_aligned(tile + i));
    out[t] = lane_max<Arch>(largest);
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
