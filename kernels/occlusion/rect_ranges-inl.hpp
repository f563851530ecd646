// Rectangles to the ranges of samples they hold (rect_samples(), sample_blocks()), a batch of
// lanes at a time, written once over xsimd batches. The reference clamps in double; float gives
// the same ranges: a coordinate c below 2^22 in magnitude makes c - 0.5 exactly (its float
// spacing is at most 0.5), and any larger one, rounded or not, lies beyond every view side
// (kMaxTargetSize) and clamps to the same end. The clamped bounds are integers or lie within
// [-1, size], where ceil, floor and the conversion to int32 are exact.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "edgewise/coverage.hpp"
#include "edgewise/occlusion.hpp"
#include "occlusion_call.hpp"
#include "../simd/simd_ops-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

static_assert(kMaxTargetSize < (1 << 22), "view sides stay below where c - 0.5 rounds");

template <class Arch>
std::size_t rect_ranges(const OcclusionRect* rects, std::size_t count, std::int32_t width,
                        std::int32_t height, std::int32_t reduction, detail::SampleRect* out) {
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  const Floats half(0.5f), zero(0.0f), minus_one(-1.0f);
  const Floats last_column(static_cast<float>(width - 1)), last_row(static_cast<float>(height - 1));
  const Floats columns(static_cast<float>(width)), rows(static_cast<float>(height));
  // reduction is 1, 2 or 4: a shift divides the non-negative bounds of a range that holds samples.
  const std::int32_t shift = std::countr_zero(static_cast<std::uint32_t>(reduction));
  alignas(64) float field[5][kLanes];
  alignas(64) std::int32_t bound[4][kLanes];
  alignas(64) float depth[kLanes];
  for (std::size_t first = 0; first < count; first += kLanes) {
    const std::size_t lanes = count - first < kLanes ? count - first : kLanes;
    for (std::size_t l = 0; l < kLanes; ++l) {
      const OcclusionRect& r = rects[first + (l < lanes ? l : lanes - 1)];
      field[0][l] = r.x0;
      field[1][l] = r.y0;
      field[2][l] = r.x1;
      field[3][l] = r.y1;
      field[4][l] = r.depth;
    }
    const Floats x0 = Floats::load_aligned(field[0]), y0 = Floats::load_aligned(field[1]);
    const Floats x1 = Floats::load_aligned(field[2]), y1 = Floats::load_aligned(field[3]);
    const Floats z = Floats::load_aligned(field[4]);
    // NaN fails every comparison: a lane is valid when none is NaN and neither side is inverted.
    const std::uint32_t valid = bits_of_lanes<Arch>((x0 <= x1) && (y0 <= y1) && (z == z));
    const std::uint32_t wanted = (2u << (lanes - 1)) - 1u;
    const std::uint32_t rejected = ~valid & wanted;
    // Beyond the far plane nothing is drawn: the empty range, depth 0, as SampleRect{}.
    const auto near = z <= Floats(1.0f);
    Ints column0 =
        xsimd::batch_cast<std::int32_t>(xsimd::ceil(xsimd::clip(x0 - half, zero, columns)));
    Ints row0 = xsimd::batch_cast<std::int32_t>(xsimd::ceil(xsimd::clip(y0 - half, zero, rows)));
    Ints column1 = xsimd::batch_cast<std::int32_t>(
        xsimd::floor(xsimd::clip(x1 - half, minus_one, last_column)));
    Ints row1 =
        xsimd::batch_cast<std::int32_t>(xsimd::floor(xsimd::clip(y1 - half, minus_one, last_row)));
    const Ints near_lanes = mask_lanes<Arch>(near);  // -1 where near, else 0
    column0 = column0 & near_lanes;
    row0 = row0 & near_lanes;
    column1 = (column1 & near_lanes) | ~near_lanes;
    row1 = (row1 & near_lanes) | ~near_lanes;
    if (shift != 0) {
      const auto holds = column0 <= column1 && row0 <= row1;
      column0 = xsimd::select(holds, column0 >> shift, column0);
      row0 = xsimd::select(holds, row0 >> shift, row0);
      column1 = xsimd::select(holds, column1 >> shift, column1);
      row1 = xsimd::select(holds, row1 >> shift, row1);
    }
    column0.store_aligned(bound[0]);
    row0.store_aligned(bound[1]);
    column1.store_aligned(bound[2]);
    row1.store_aligned(bound[3]);
    xsimd::select(near, z, zero).store_aligned(depth);
    const std::size_t written = rejected != 0 ? std::countr_zero(rejected) : lanes;
    for (std::size_t l = 0; l < written; ++l)
      out[first + l] = {bound[0][l], bound[1][l], bound[2][l], bound[3][l], depth[l]};
    if (rejected != 0) return first + written;
  }
  return count;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
