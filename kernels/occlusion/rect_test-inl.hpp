// The rectangle test of the occlusion queries, written once over xsimd batches: a tile whose
// exact maximum lies at or below the rectangle's depth is passed over whole; in the others, the
// depths above it are found in lanes and masked by the rectangle's rows and columns (no branch per
// sample). The first such depth decides visible.
#pragma once

#include <algorithm>
#include <bit>
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

// Bit i of the result: depth i of the tile lies above `limit`. No branch: the tile's 64 depths
// are compared whatever part of it the rectangle holds.
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

// Whether a sample of the rectangle in the tiles of bits `above` (tile tx + bit, ty), whose
// maxima lie above the rectangle's depth, does too: a tile wholly inside the rectangle does at
// once (its maximum is one of the rectangle's samples), the others are compared sample by sample.
template <class Arch>
[[gnu::noinline]] bool some_sample_above(const detail::OcclusionDepth& depth,
                                         const detail::SampleRect& r, std::int32_t tx,
                                         std::int32_t ty, std::uint32_t above) {
  const bool rows_whole = r.y0 <= ty * 8 && r.y1 >= ty * 8 + 7;
  for (; above != 0; above &= above - 1) {
    const std::int32_t t = tx + std::countr_zero(above);
    if (rows_whole && r.x0 <= t * 8 && r.x1 >= t * 8 + 7) return true;
    const std::size_t tile = static_cast<std::size_t>(ty) * depth.tiles_x + t;
    if ((depths_above<Arch>(depth.tiles + tile * 64, r.depth) & rect_tile_mask(r, t, ty)) != 0)
      return true;
  }
  return false;
}

// Visible when some sample of the rectangle holds a depth above the rectangle's. The maxima of a
// column of tiles a batch of lanes wide (one batch for rectangles up to that many tiles across)
// are compared row after row, and only the tiles whose maximum lies above the depth are looked
// into (some_sample_above(), out of line: most rows have none). The maxima array holds
// kTileMaximaPadding entries past its last tile, so that a batch may read past a row's end.
template <class Arch>
Visibility test_rect(const detail::OcclusionDepth& depth, const detail::SampleRect& r) {
  using Floats = xsimd::batch<float, Arch>;
  constexpr std::int32_t kLanes = static_cast<std::int32_t>(Floats::size);
  static_assert(kLanes <= detail::kTileMaximaPadding);
  if (r.x0 > r.x1 || r.y0 > r.y1) return Visibility::outside;
  const Floats limit(r.depth);
  const std::int32_t tx1 = r.x1 >> 3, ty0 = r.y0 >> 3, ty1 = r.y1 >> 3;
  const std::size_t stride = static_cast<std::size_t>(depth.tiles_x);
  for (std::int32_t tx = r.x0 >> 3; tx <= tx1; tx += kLanes) {
    const std::int32_t lanes = std::min(kLanes, tx1 - tx + 1);
    const std::uint32_t wanted = (2u << (lanes - 1)) - 1u;
    const float* maxima = depth.tile_max + static_cast<std::size_t>(ty0) * stride + tx;
    for (std::int32_t ty = ty0; ty <= ty1; ++ty, maxima += stride) {
      const std::uint32_t above =
          bits_of_lanes<Arch>(Floats::load_unaligned(maxima) > limit) & wanted;
      if (above != 0 && some_sample_above<Arch>(depth, r, tx, ty, above))
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
