// The values of a tile kept as planes (plane_tiles.hpp), per batch of lanes: each pixel's depth
// by the shared formula (depth_plane.hpp) in the order of operations draw()'s depth step uses
// (shade_depth-inl.hpp), so the values are those draw() would have written, bit for bit.
#pragma once

#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "depth_plane.hpp"
#include "plane_tiles.hpp"
#include "shade_depth-inl.hpp"
#include "../../interpolation/interpolation-inl.hpp"
#include "../../simd/simd_ops-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// One plane over one tile: its row bases z0 + dzdy * dy for the tile's 8 rows, and its dx terms
// dzdx * dx for the tile's columns, a batch of lanes at a time. A row base computed in lanes is
// depth_row_base()'s: lane r's dy, (r + (py + 0.5)) - y0, equals ((py + r) + 0.5) - y0, both
// exact (integers and halves below 2^23).
template <class Arch>
struct TilePlaneTerms {
  using Floats = xsimd::batch<float, Arch>;
  static constexpr std::size_t kLanes = Floats::size;
  static constexpr std::size_t kParts = kTileSize / kLanes;

  alignas(32) float row_base[kTileSize];
  Floats column[kParts];

  [[gnu::always_inline]] TilePlaneTerms(const detail::DepthPlane& plane, std::int32_t px,
                                        std::int32_t py) {
    for (std::size_t h = 0; h < kParts; ++h) {
      const std::int32_t offset = static_cast<std::int32_t>(h * kLanes);
      const Floats dy = interpolation_detail::lane_centers<Arch>(py + offset) - Floats(plane.y0);
      (Floats(plane.z0) + Floats(plane.dzdy) * dy).store_aligned(row_base + offset);
      column[h] = Floats(plane.dzdx) *
                  (interpolation_detail::lane_centers<Arch>(px + offset) - Floats(plane.x0));
    }
  }

  // The depths of lanes h of `row`.
  [[gnu::always_inline]] Floats depth(int row, std::size_t h) const {
    return clamp01(Floats(row_base[row]) + column[h]);
  }
};

// Writes the 64 depths of a tile kept as planes, whose first pixel is (px, py), to `depth`;
// `slots` are the tile's, read when it has several planes, which `planes` holds.
template <class Arch>
inline void write_plane_tile(const detail::PlaneTile& tile, const detail::PlaneSlots& slots,
                             const detail::DepthPlane* planes, std::int32_t px, std::int32_t py,
                             float* depth) {
  using Terms = TilePlaneTerms<Arch>;
  using Floats = typename Terms::Floats;
  constexpr std::size_t kLanes = Terms::kLanes, kParts = Terms::kParts;
  // The first plane in use everywhere, then each other's values where its mask holds the pixel.
  int first = 0;
  if (tile.kind == detail::TileKind::slots) {
    while (slots.mask[first] == 0)
      ++first;
  }
  const Terms everywhere(
      planes[tile.kind == detail::TileKind::plane ? tile.plane : slots.plane[first]], px, py);
  for (int row = 0; row < kTileSize; ++row) {
    for (std::size_t h = 0; h < kParts; ++h)
      everywhere.depth(row, h).store_aligned(depth + row * kTileSize + h * kLanes);
  }
  if (tile.kind != detail::TileKind::slots) return;
  for (int s = first + 1; s < detail::kPlaneTileSlots; ++s) {
    if (slots.mask[s] == 0) continue;
    const Terms terms(planes[slots.plane[s]], px, py);
    for (int row = 0; row < kTileSize; ++row) {
      const auto row_bits = static_cast<std::uint32_t>(slots.mask[s] >> (row * 8)) & 0xFFu;
      if (row_bits == 0) continue;
      for (std::size_t h = 0; h < kParts; ++h) {
        float* at = depth + row * kTileSize + h * kLanes;
        const Floats values = xsimd::select(lanes_of_bits<Arch>(row_bits >> (h * kLanes)),
                                            terms.depth(row, h), Floats::load_aligned(at));
        values.store_aligned(at);
      }
    }
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
