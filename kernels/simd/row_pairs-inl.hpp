// Two 8-lane rows in one 512-bit batch, for kernels that step two tile rows at a time on
// AVX-512: a row's values in both halves, a lane mask from and to 16 bits, a masked store of
// 32-bit lanes and the larger of the two halves.
#pragma once

#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "lane_arch-inl.hpp"

#if defined(EDGEWISE_HAS_AVX512_256)
#include <immintrin.h>

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

using PairFloats = xsimd::batch<float, xsimd::avx512bw>;
using PairInts = xsimd::batch<std::int32_t, xsimd::avx512bw>;
using PairMask = xsimd::batch_bool<float, xsimd::avx512bw>;
using RowFloats = xsimd::batch<float, avx512_256>;

// An 8-lane row's values in both halves.
[[gnu::always_inline]] inline PairFloats both_halves(RowFloats row) {
  const __m256 half = row;
  return PairFloats(_mm512_insertf32x8(_mm512_castps256_ps512(half), half, 1));
}

// Lane l set where bit l of `bits` is (bits 0 .. 15).
[[gnu::always_inline]] inline PairMask pair_mask_of_bits(std::uint64_t bits) {
  return PairMask(static_cast<__mmask16>(bits));
}

// Bit l set where lane l is.
[[gnu::always_inline]] inline std::uint32_t bits_of_pair_mask(PairMask mask) {
  const __mmask16 bits = mask;
  return static_cast<std::uint32_t>(bits);
}

// The lanes of `values` where `mask` is set, stored at out[0 .. 16) (64-byte aligned).
[[gnu::always_inline]] inline void store_masked(std::uint32_t* out, PairMask mask,
                                                PairInts values) {
  const __mmask16 bits = mask;
  _mm512_mask_store_epi32(out, bits, values);
}

// The larger of each lane of the two halves.
[[gnu::always_inline]] inline RowFloats max_of_halves(PairFloats pair) {
  const __m512 wide = pair;
  return RowFloats(_mm256_max_ps(_mm512_castps512_ps256(wide), _mm512_extractf32x8_ps(wide, 1)));
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE

#endif
