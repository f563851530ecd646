// The few operations xsimd 8.1 lacks, per architecture: collecting lane sign bits.
#pragma once

#include <cstdint>
#include <type_traits>

#include <xsimd/xsimd.hpp>

#if defined(__SSE2__)
#include <immintrin.h>
#endif
#if defined(__ARM_NEON)
#include <arm_neon.h>
#endif

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// Bit i set when lane i is negative.
template <class Arch>
inline std::uint32_t sign_bits(xsimd::batch<std::int32_t, Arch> v) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    return static_cast<std::uint32_t>(_mm256_movemask_ps(_mm256_castsi256_ps(v)));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    return static_cast<std::uint32_t>(_mm_movemask_ps(_mm_castsi128_ps(v)));
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    const uint32x4_t all_ones_if_negative = vreinterpretq_u32_s32(vshrq_n_s32(v, 31));
    const uint32x4_t weight = {1, 2, 4, 8};
    return vaddvq_u32(vandq_u32(all_ones_if_negative, weight));
  } else
#endif
  {
    static_assert(!sizeof(Arch), "sign_bits: no implementation for this architecture");
  }
}

// Sign bits of an 8x8 block of int32 values held as rows[row * steps + step], where each row is
// 8 / lanes batches: bit (row * 8 + column) set when that value is negative. On x86 saturating
// packs keep each value's sign while narrowing to bytes, so one movemask serves several rows.
template <class Arch>
inline std::uint64_t sign_bits_8x8(const xsimd::batch<std::int32_t, Arch>* rows) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    // Packs work within 128-bit halves; the permute restores row order before the movemask.
    const __m256i order = _mm256_setr_epi32(0, 4, 1, 5, 2, 6, 3, 7);
    std::uint64_t bits = 0;
    for (int quad = 0; quad < 2; ++quad) {
      const xsimd::batch<std::int32_t, Arch>* r = rows + 4 * quad;
      const __m256i rows01 = _mm256_packs_epi32(r[0], r[1]);
      const __m256i rows23 = _mm256_packs_epi32(r[2], r[3]);
      const __m256i bytes = _mm256_permutevar8x32_epi32(_mm256_packs_epi16(rows01, rows23), order);
      bits |= std::uint64_t{static_cast<std::uint32_t>(_mm256_movemask_epi8(bytes))} << (32 * quad);
    }
    return bits;
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    std::uint64_t bits = 0;
    for (int pair = 0; pair < 4; ++pair) {
      const xsimd::batch<std::int32_t, Arch>* r = rows + 4 * pair;  // two rows of two halves
      const __m128i upper = _mm_packs_epi32(r[0], r[1]);
      const __m128i lower = _mm_packs_epi32(r[2], r[3]);
      const int pair_bits = _mm_movemask_epi8(_mm_packs_epi16(upper, lower));
      bits |= std::uint64_t{static_cast<std::uint16_t>(pair_bits)} << (16 * pair);
    }
    return bits;
  } else
#endif
  {
    constexpr std::size_t kLanes = xsimd::batch<std::int32_t, Arch>::size;
    constexpr std::size_t kSteps = 8 / kLanes;
    std::uint64_t bits = 0;
    for (std::size_t i = 0; i < 8 * kSteps; ++i) {
      bits |= std::uint64_t{sign_bits<Arch>(rows[i])} << (i * kLanes);
    }
    return bits;
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
