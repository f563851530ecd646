// Texel addressing and fetching for a batch of queries: coordinates reduced by the wrap mode,
// integer texel indices wrapped per lane, texels gathered and decoded to linear float RGBA.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <limits>
#include <type_traits>
#include <utility>

#include <xsimd/xsimd.hpp>

#include "sample_kernels.hpp"
#include "../simd/byte_lanes-inl.hpp"
#include "../simd/lane_loads-inl.hpp"
#include "../simd/simd_ops-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
struct Rgba {
  xsimd::batch<float, Arch> c[4];
};

// Per-lane level geometry: the level's size and its first texel in the storage.
template <class Arch>
struct LevelLanes {
  xsimd::batch<std::int32_t, Arch> width, height, start;
  xsimd::batch<float, Arch> widthf, heightf;
};

// table[index] per lane for an index below kLevelTableReadable: on AVX2 the table's 16 entries
// are permuted in registers, which is faster than a gather per table and level
// (docs/design/textures.md).
template <class Arch>
EDGEWISE_INLINE xsimd::batch<std::int32_t, Arch> lookup_small_table(
    const std::int32_t* table, xsimd::batch<std::int32_t, Arch> index) {
  static_assert(detail::kLevelTableReadable == kLookup16Entries);
  return lookup16_int32<Arch>(table, index);
}

template <class Arch>
EDGEWISE_INLINE xsimd::batch<std::int32_t, Arch> lookup_level(
    const std::int32_t* table, std::int32_t count, xsimd::batch<std::int32_t, Arch> index) {
  if (count <= detail::kLevelTableReadable) return lookup_small_table<Arch>(table, index);
  return gather_int32<Arch>(table, index);
}

template <class Arch>
EDGEWISE_INLINE LevelLanes<Arch> level_lanes(const detail::LevelTable& table,
                                             xsimd::batch<std::int32_t, Arch> level) {
  LevelLanes<Arch> lanes;
  lanes.width = lookup_level<Arch>(table.width, table.count, level);
  lanes.height = lookup_level<Arch>(table.height, table.count, level);
  lanes.start = lookup_level<Arch>(table.start, table.count, level);
  lanes.widthf = xsimd::to_float(lanes.width);
  lanes.heightf = xsimd::to_float(lanes.height);
  return lanes;
}

template <class Arch>
EDGEWISE_INLINE LevelLanes<Arch> level_lanes(const detail::LevelTable& table, std::int32_t level) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
  LevelLanes<Arch> lanes;
  lanes.width = Ints(table.width[level]);
  lanes.height = Ints(table.height[level]);
  lanes.start = Ints(table.start[level]);
  lanes.widthf = xsimd::to_float(lanes.width);
  lanes.heightf = xsimd::to_float(lanes.height);
  return lanes;
}

// A coordinate brought into one period of the wrap mode, exactly up to one rounding of
// s - floor(s) (below 2^-24 for s in [-2, 2]): repeat to [0, 1], mirror to [0, 2], clamp to
// [-1, 2] (beyond, every texel index clamps to the border anyway). Non-finite values become 0
// (callers zero those lanes' results), so that every index below stays in range.
template <class Arch>
EDGEWISE_INLINE xsimd::batch<float, Arch> reduce_coordinate(xsimd::batch<float, Arch> s,
                                                            WrapMode mode) {
  using Floats = xsimd::batch<float, Arch>;
  const auto finite = xsimd::abs(s) <= Floats(std::numeric_limits<float>::max());
  s = xsimd::select(finite, s, Floats(0.0f));
  switch (mode) {
    case WrapMode::repeat:
      return s - xsimd::floor(s);
    case WrapMode::mirror:
      return s - Floats(2.0f) * xsimd::floor(s * Floats(0.5f));
    case WrapMode::clamp_to_edge:
      break;
  }
  return xsimd::min(xsimd::max(s, Floats(-1.0f)), Floats(2.0f));
}

// Texel indices wrapped into [0, n). kRounds is how far outside one period the indices may lie:
// after reduce_coordinate(), a filter reaching one texel beyond its base texel (bilinear) gives
// indices in [-n, 2n) for repeat and [-2n, 4n) for mirror, one round; two texels (bicubic), two.
template <class Arch, int kRounds = 2>
EDGEWISE_INLINE xsimd::batch<std::int32_t, Arch> wrap_index(xsimd::batch<std::int32_t, Arch> i,
                                                            xsimd::batch<std::int32_t, Arch> n,
                                                            WrapMode mode) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
  const Ints zero(0);
  switch (mode) {
    case WrapMode::repeat:
      for (int k = 0; k < kRounds; ++k) {
        i = xsimd::select(i < zero, i + n, i);
        i = xsimd::select(i >= n, i - n, i);
      }
      return i;
    case WrapMode::mirror: {
      const Ints period = n + n;
      for (int k = 0; k < kRounds; ++k) {
        i = xsimd::select(i < zero, i + period, i);
        i = xsimd::select(i >= period, i - period, i);
      }
      return xsimd::select(i >= n, period - Ints(1) - i, i);
    }
    case WrapMode::clamp_to_edge:
      break;
  }
  return xsimd::min(xsimd::max(i, zero), n - Ints(1));
}

// The two texel indices of a bilinear tap row, x0 and x0 + 1, wrapped into [0, n), for x0 the
// floor of c n - 1/2 with c = reduce_coordinate(): as wrap_index<1>, with fewer operations
// where the reduction bounds x0. For repeat c is in [0, 1] (s - floor(s) rounds to 1 at most),
// so c n - 1/2 lies in [-1/2, n - 1/2] (c n is at most n after rounding, n being whole):
// x0 >= -1 needs only its lower wrap and x0 + 1 <= n only its upper one. Clamping is two
// comparisons per index whatever x0 is.
template <class Arch>
EDGEWISE_INLINE std::pair<xsimd::batch<std::int32_t, Arch>, xsimd::batch<std::int32_t, Arch>>
wrap_tap_pair(xsimd::batch<std::int32_t, Arch> x0, xsimd::batch<std::int32_t, Arch> n,
              WrapMode mode) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
  const Ints zero(0);
  const Ints x1 = x0 + Ints(1);
  switch (mode) {
    case WrapMode::repeat:
      return {xsimd::select(x0 < zero, x0 + n, x0), xsimd::select(x1 == n, zero, x1)};
    case WrapMode::clamp_to_edge: {
      const Ints last = n - Ints(1);
      return {xsimd::min(xsimd::max(x0, zero), last), xsimd::min(xsimd::max(x1, zero), last)};
    }
    case WrapMode::mirror:
      break;
  }
  return {wrap_index<Arch, 1>(x0, n, mode), wrap_index<Arch, 1>(x1, n, mode)};
}

// Any texel index below 2^24 in magnitude wrapped into [0, n): the quotient by one period comes
// from a float division (exact but for a rounding that can only land it one period off, which
// the two corrections undo).
template <class Arch>
EDGEWISE_INLINE xsimd::batch<std::int32_t, Arch> wrap_any_index(xsimd::batch<std::int32_t, Arch> i,
                                                                xsimd::batch<std::int32_t, Arch> n,
                                                                WrapMode mode) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
  if (mode == WrapMode::clamp_to_edge) return xsimd::min(xsimd::max(i, Ints(0)), n - Ints(1));
  const Ints period = mode == WrapMode::mirror ? n + n : n;
  const Ints quotient = xsimd::to_int(xsimd::floor(xsimd::to_float(i) / xsimd::to_float(period)));
  Ints r = i - quotient * period;
  r = xsimd::select(r < Ints(0), r + period, r);
  r = xsimd::select(r >= period, r - period, r);
  if (mode == WrapMode::repeat) return r;
  return xsimd::select(r >= n, period - Ints(1) - r, r);
}

// Channel k of 8-bit RGBA texels (one per lane), in the texture's stored units.
template <class Arch>
EDGEWISE_INLINE xsimd::batch<float, Arch> decode_channel(const detail::TextureDescription& texture,
                                                         xsimd::batch<std::int32_t, Arch> packed,
                                                         int k) {
  const xsimd::batch<std::int32_t, Arch> code = byte_of_lanes<Arch>(packed, k);
  if (k < 3 && texture.srgb_table != nullptr) return gather_float<Arch>(texture.srgb_table, code);
  return xsimd::to_float(code);
}

// RGBA of the texels at storage indices `index` (a level's start + y * width + x), in the
// texture's stored units: the linear value times 1 / channel_scale (8-bit codes stay 0 .. 255, so
// filters weight them as they are and one multiply per result, not per texel, brings them to
// linear; sRGB channels are decoded here).
template <class Arch>
EDGEWISE_INLINE Rgba<Arch> fetch_texels(const detail::TextureDescription& texture,
                                        xsimd::batch<std::int32_t, Arch> index) {
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  Rgba<Arch> out;
  if (texture.format == TexelFormat::rgba8) {
    const Ints packed =
        load_lanes_int32<Arch>(reinterpret_cast<const std::int32_t*>(texture.texels), index);
    for (int k = 0; k < 4; ++k)
      out.c[k] = decode_channel<Arch>(texture, packed, k);
    return out;
  }
  // Float texels: 16 bytes each, addressed in 64 bits (4 * index can pass 2^31).
  alignas(64) std::int32_t lanes[kLanes];
  index.store_aligned(lanes);
  alignas(64) float channels[4][kLanes];
  const float* texels = reinterpret_cast<const float*>(texture.texels);
  for (std::size_t l = 0; l < kLanes; ++l) {
    const float* texel = texels + 4 * static_cast<std::size_t>(lanes[l]);
    for (int k = 0; k < 4; ++k)
      channels[k][l] = texel[k];
  }
  for (int k = 0; k < 4; ++k)
    out.c[k] = Floats::load_aligned(channels[k]);
  return out;
}

template <class Arch>
EDGEWISE_INLINE Rgba<Arch> fetch(const detail::TextureDescription& texture,
                                 const LevelLanes<Arch>& level, xsimd::batch<std::int32_t, Arch> x,
                                 xsimd::batch<std::int32_t, Arch> y) {
  return fetch_texels<Arch>(texture, level.start + y * level.width + x);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
