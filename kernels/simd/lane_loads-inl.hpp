// Per-lane loads from an array, by lane index: one load per lane, the gather instruction, and
// a 16-entry table permuted in registers. xsimd 8.1 never emits a gather instruction and inserts
// gathered lanes one by one.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include <xsimd/xsimd.hpp>

#include "simd_ops-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// base[index] per lane by one load per lane: over scattered addresses (a texture's texels) the
// gather instruction is slower than separate loads, and faster only on small, hot tables, which
// take gather_*() (docs/design/textures.md has the figures). The lanes are built from their
// values at once (vmovd and vpinsrd on x86), not inserted one by one into the whole register as
// xsimd's gather does.
template <class Arch, class T, std::size_t... Lane>
EDGEWISE_INLINE xsimd::batch<T, Arch> load_lanes(const T* base, const std::int32_t* at,
                                                 std::index_sequence<Lane...>) {
  return xsimd::batch<T, Arch>{base[at[Lane]]...};
}

template <class Arch, class T>
EDGEWISE_INLINE xsimd::batch<T, Arch> load_lanes(const T* base,
                                                 xsimd::batch<std::int32_t, Arch> index) {
  constexpr std::size_t kLanes = xsimd::batch<std::int32_t, Arch>::size;
  alignas(64) std::int32_t at[kLanes];
  index.store_aligned(at);
  return load_lanes<Arch>(base, at, std::make_index_sequence<kLanes>{});
}

template <class Arch>
EDGEWISE_INLINE xsimd::batch<std::int32_t, Arch> load_lanes_int32(
    const std::int32_t* base, xsimd::batch<std::int32_t, Arch> index) {
  return load_lanes<Arch>(base, index);
}

template <class Arch>
EDGEWISE_INLINE xsimd::batch<float, Arch> load_lanes_float(const float* base,
                                                           xsimd::batch<std::int32_t, Arch> index) {
  return load_lanes<Arch>(base, index);
}

// base[index] per lane with the AVX2 gather instruction (xsimd 8.1 never emits it); a load
// per lane elsewhere.
template <class Arch>
EDGEWISE_INLINE xsimd::batch<std::int32_t, Arch> gather_int32(
    const std::int32_t* base, xsimd::batch<std::int32_t, Arch> index) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    return _mm256_i32gather_epi32(reinterpret_cast<const int*>(base), index, 4);
  } else
#endif
  {
    return load_lanes<Arch>(base, index);
  }
}

template <class Arch>
EDGEWISE_INLINE xsimd::batch<float, Arch> gather_float(const float* base,
                                                       xsimd::batch<std::int32_t, Arch> index) {
#if defined(__AVX512F__)
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    return _mm512_i32gather_ps(index, base, 4);
  } else
#endif
#if defined(__AVX2__)
      if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    return _mm256_i32gather_ps(base, index, 4);
  } else
#endif
  {
    return load_lanes<Arch>(base, index);
  }
}

// table[index] per lane for an index below kLookup16Entries: on AVX-512 the table's 16 entries
// are one register permuted, on AVX2 two (two permutes and a blend); a load per lane elsewhere.
inline constexpr int kLookup16Entries = 16;
template <class Arch>
EDGEWISE_INLINE xsimd::batch<std::int32_t, Arch> lookup16_int32(
    const std::int32_t* table, xsimd::batch<std::int32_t, Arch> index) {
#if defined(__AVX512F__)
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    return _mm512_permutexvar_epi32(index, _mm512_loadu_si512(table));
  } else
#endif
#if defined(__AVX2__)
      if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    const __m256i low = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(table));
    const __m256i high = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(table + 8));
    const __m256i in_high = _mm256_cmpgt_epi32(index, _mm256_set1_epi32(7));
    return _mm256_blendv_epi8(_mm256_permutevar8x32_epi32(low, index),
                              _mm256_permutevar8x32_epi32(high, index), in_high);
  } else
#endif
  {
    return load_lanes_int32<Arch>(table, index);
  }
}

// The x and y of the pairs `index` (each in range) of `xy` (x, y interleaved): on AVX2 each
// pair by one 64-bit element of a gather, half the elements of gathering x and y apart.
template <class Arch>
[[gnu::always_inline]] inline void gather_float_pairs(const float* xy,
                                                      xsimd::batch<std::int32_t, Arch> index,
                                                      xsimd::batch<float, Arch>& x,
                                                      xsimd::batch<float, Arch>& y) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch> && Ints::size == 8) {
    // Lanes 0, 1, 4, 5 in one gather and 2, 3, 6, 7 in the other: the in-lane shuffles that
    // split x from y then leave the lanes in order.
    const __m256i split =
        _mm256_permutevar8x32_epi32(index, _mm256_setr_epi32(0, 1, 4, 5, 2, 3, 6, 7));
    const auto* pairs = reinterpret_cast<const long long*>(xy);
    const __m256 low =
        _mm256_castsi256_ps(_mm256_i32gather_epi64(pairs, _mm256_castsi256_si128(split), 8));
    const __m256 high =
        _mm256_castsi256_ps(_mm256_i32gather_epi64(pairs, _mm256_extracti128_si256(split, 1), 8));
    x = _mm256_shuffle_ps(low, high, _MM_SHUFFLE(2, 0, 2, 0));
    y = _mm256_shuffle_ps(low, high, _MM_SHUFFLE(3, 1, 3, 1));
    return;
  }
#endif
  const Ints offset = index * Ints(2);
  x = gather_float<Arch>(xy, offset);
  y = gather_float<Arch>(xy + 1, offset);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
