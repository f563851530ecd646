// The common case of shading, in loops of its own: an untextured tile whose colour comes from the
// colour planes (Gouraud, or diffuse when Lit), depth written. The same operations as the
// generic loop (shade-inl.hpp), with the choices made once per tile and the counts kept in
// registers. A full tile (every sample covered) runs all eight rows without lane masks; a Uniform
// triangle's colour is the same at every pixel; Divide: perspective-correct colour. The colour
// planes' row terms come from `colour_row_bases`, or, with RowTermsPerRow (small triangles, which
// cover few of a tile's rows), are computed per covered row with the same float operations.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <type_traits>

#include <xsimd/xsimd.hpp>

#include "../../simd/row_pairs-inl.hpp"
#include "../../simd/simd_ops-inl.hpp"
#include "shade_colour-inl.hpp"
#include "shade_depth-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// Whether colour from planes with depth writes steps two tile rows per batch
// (shade_planar_row_pairs()).
template <class Arch>
inline constexpr bool kPlanarRowPairs =
#if defined(EDGEWISE_HAS_AVX512_256)
    std::is_same_v<Arch, avx512_256>;
#else
    false;
#endif

#if defined(EDGEWISE_HAS_AVX512_256)
// shade_planar_rows() on AVX-512, two tile rows per 512-bit batch: a small triangle covers about
// two pixels of each tile row it touches, so pairs of rows halve the steps (their row terms, mask
// handling and loop) for the same lanes of work. Each lane takes the same float operations on the
// same dx and dy as in the 8-lane loop (row r + 1's centre, r + 1.5, is exact), so the results are
// identical. (PairFloats and the other row-pair operations: simd/row_pairs-inl.hpp.)
template <DepthTest Test, bool Divide, bool Full, bool Lit, bool Uniform>
[[gnu::always_inline]] inline void shade_planar_row_pairs(
    DepthStage<avx512_256>& depth_stage, const ColourSource<avx512_256>& colour, std::uint64_t mask,
    std::uint32_t rows, float* depth, std::uint32_t* color, std::int32_t py,
    const TileColumnTerms<avx512_256>& columns, xsimd::batch<float, avx512_256>& stored_max) {
  using Floats = xsimd::batch<float, avx512_256>;
  static_assert(Floats::size == kTileSize, "one batch per tile row");
  const detail::DepthPlane& plane = depth_stage.plane();
  // Bit r set for each pair of rows r and r + 1 (r even) with a covered sample.
  std::uint32_t pairs = Full ? 0x55u : (rows | rows >> 1) & 0x55u;
  alignas(64) static constexpr float kPairRowCentre[16] = {0.5f, 0.5f, 0.5f, 0.5f, 0.5f, 0.5f,
                                                           0.5f, 0.5f, 1.5f, 1.5f, 1.5f, 1.5f,
                                                           1.5f, 1.5f, 1.5f, 1.5f};
  const PairFloats row_centre = PairFloats::load_aligned(kPairRowCentre);
  const PairFloats depth_column = both_halves(columns.depth[0]);
  PairFloats colour_column[kShadingPlanes];
  for (int k = Uniform ? kFirstNormalPlane : 0; k < kShadingPlanes; ++k) {
    if (k == 4 && !Divide) continue;
    if (k >= kFirstNormalPlane && !Lit) break;
    colour_column[k] = both_halves(columns.colour[k][0]);
  }
  std::uint64_t passed = 0;
  PairFloats largest(-std::numeric_limits<float>::infinity());
  for (; pairs != 0; pairs &= pairs - 1) {
    const int row = std::countr_zero(pairs);
    // depth_row_base()'s dy, the colour planes' too.
    const PairFloats dy =
        (PairFloats(static_cast<float>(py + row)) + row_centre) - PairFloats(plane.y0);
    const PairFloats z =
        clamp01((PairFloats(plane.z0) + PairFloats(plane.dzdy) * dy) + depth_column);
    float* depth_at = depth + static_cast<std::size_t>(row) * kTileSize;
    const PairFloats stored = PairFloats::load_aligned(depth_at);
    PairMask write = passes<Test>(z, stored);
    if constexpr (!Full) write = write && pair_mask_of_bits(mask >> (8 * row));
    const PairFloats updated = xsimd::select(write, z, stored);
    updated.store_aligned(depth_at);
    largest = xsimd::max(largest, updated);
    passed += static_cast<std::uint64_t>(std::popcount(bits_of_pair_mask(write)));
    const auto plane_at = [&](int k) {
      const ColourPlane& p = colour.plane(k);
      return (PairFloats(p.at_vertex) + PairFloats(p.dy) * dy) + colour_column[k];
    };
    PairFloats channel[4];
    for (int k = 0; k < 4; ++k)
      channel[k] = Uniform ? PairFloats(colour.uniform_channel(k)) : plane_at(k);
    if constexpr (Divide) {
      const PairFloats w =
          PairFloats(1.0f) / xsimd::max(plane_at(4), PairFloats(colour.min_inverse_w()));
      for (int k = 0; k < 4; ++k)
        channel[k] = channel[k] * w;
    }
    if constexpr (Lit) {
      PairFloats normal[kNormalPlanes];
      for (int k = 0; k < kNormalPlanes; ++k)
        normal[k] = plane_at(kFirstNormalPlane + k);
      colour.apply_light(normal, channel);
    }
    std::uint32_t* color_at = color + static_cast<std::size_t>(row) * kTileSize;
    store_masked(color_at, write, pack_rgba8_lanes<xsimd::avx512bw>(channel));
  }
  depth_stage.add_passed(passed);
  stored_max = xsimd::max(stored_max, Floats(max_of_halves(largest)));
}
#endif

template <DepthTest Test, bool Divide, bool Full, bool RowTermsPerRow, bool Lit,
          bool Uniform = false, class Arch>
[[gnu::always_inline]] inline void shade_planar_rows(
    DepthStage<Arch>& depth_stage, const ColourSource<Arch>& colour, std::uint64_t mask,
    std::uint32_t rows, float* depth, std::uint32_t* color, std::int32_t py,
    const TileColumnTerms<Arch>& columns, const float (*colour_row_bases)[kTileSize],
    xsimd::batch<float, Arch>& stored_max) {
#if defined(EDGEWISE_HAS_AVX512_256)
  if constexpr (kPlanarRowPairs<Arch>) {
    return shade_planar_row_pairs<Test, Divide, Full, Lit, Uniform>(
        depth_stage, colour, mask, rows, depth, color, py, columns, stored_max);
  }
#endif
  using Floats = xsimd::batch<float, Arch>;
  using Mask = xsimd::batch_bool<float, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  const detail::DepthPlane& plane = depth_stage.plane();
  std::uint64_t passed = 0;
  Floats largest = stored_max;
  for (int next = 0; Full ? next < kTileSize : rows != 0; ++next, rows &= rows - 1) {
    const int row = Full ? next : std::countr_zero(rows);
    const std::uint32_t row_mask = static_cast<std::uint32_t>(mask >> (8 * row)) & 0xFF;
    const Floats row_base(detail::depth_row_base(plane, py + row));
    for (std::size_t h = 0; h < kTileSize / kLanes; ++h) {
      const std::size_t offset = static_cast<std::size_t>(row) * kTileSize + h * kLanes;
      const Floats z = clamp01(row_base + columns.depth[h]);
      const Floats stored = Floats::load_aligned(depth + offset);
      Mask write = passes<Test>(z, stored);
      if constexpr (!Full) write = write && lanes_of_bits<Arch>(row_mask >> (h * kLanes));
      const Floats updated = xsimd::select(write, z, stored);
      updated.store_aligned(depth + offset);
      largest = xsimd::max(largest, updated);
      passed += static_cast<std::uint64_t>(std::popcount(bits_of_lanes<Arch>(write)));
      float row_term[kShadingPlanes];
      for (int k = Uniform ? kFirstNormalPlane : 0; k < kShadingPlanes; ++k) {
        if (k == 4 && !Divide) continue;
        if (k >= kFirstNormalPlane && !Lit) break;
        if constexpr (RowTermsPerRow) {
          // ColourSource::set_up_rows()'s operations for this one row.
          const float dy = (static_cast<float>(py + row) + 0.5f) - plane.y0;
          row_term[k] = colour.plane(k).at_vertex + colour.plane(k).dy * dy;
        } else {
          row_term[k] = colour_row_bases[k][row];
        }
      }
      Floats channel[4];
      for (int k = 0; k < 4; ++k) {
        if constexpr (Uniform) {
          channel[k] = Floats(colour.uniform_channel(k));
        } else {
          channel[k] = Floats(row_term[k]) + columns.colour[k][h];
        }
      }
      if constexpr (Divide) {
        const Floats w = Floats(1.0f) / xsimd::max(Floats(row_term[4]) + columns.colour[4][h],
                                                   Floats(colour.min_inverse_w()));
        for (int k = 0; k < 4; ++k)
          channel[k] = channel[k] * w;
      }
      if constexpr (Lit) {
        Floats normal[kNormalPlanes];
        for (int k = 0; k < kNormalPlanes; ++k) {
          normal[k] =
              Floats(row_term[kFirstNormalPlane + k]) + columns.colour[kFirstNormalPlane + k][h];
        }
        colour.apply_light(normal, channel);
      }
      write_colour<Arch>(color, row, h, write, pack_rgba8_lanes<Arch>(channel));
    }
  }
  depth_stage.add_passed(passed);
  stored_max = largest;
}

// shade_planar_rows() for the tile's division (perspective), coverage (full or not) and colour
// (uniform or not).
template <DepthTest Test, bool RowTermsPerRow, bool Lit, class Arch>
[[gnu::always_inline]] inline void shade_planar_choice(
    DepthStage<Arch>& depth_stage, const ColourSource<Arch>& colour, std::uint64_t mask,
    std::uint32_t rows, float* depth, std::uint32_t* color, std::int32_t py,
    const TileColumnTerms<Arch>& columns, const float (*colour_row_bases)[kTileSize],
    xsimd::batch<float, Arch>& stored_max) {
  const auto run = [&]<bool Divide, bool Full, bool Uniform>() EDGEWISE_INLINE_LAMBDA {
    shade_planar_rows<Test, Divide, Full, RowTermsPerRow, Lit, Uniform>(
        depth_stage, colour, mask, rows, depth, color, py, columns, colour_row_bases, stored_max);
  };
  const bool full = mask == ~std::uint64_t{0};
  if (colour.uniform()) {
    return full ? run.template operator()<false, true, true>()
                : run.template operator()<false, false, true>();
  }
  if (full) {
    return colour.perspective() ? run.template operator()<true, true, false>()
                                : run.template operator()<false, true, false>();
  }
  return colour.perspective() ? run.template operator()<true, false, false>()
                              : run.template operator()<false, false, false>();
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
