// Multiply-adds of 8-bit channel pairs by 16-bit weight pairs into 32-bit sums (pmaddwd on x86,
// vmlal on NEON), for fixed-point filtering (kernels/texture/fixed_taps-inl.hpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include <xsimd/xsimd.hpp>

#include "simd_ops-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

namespace byte_pairs_detail {

template <class F, std::size_t... J>
[[gnu::always_inline]] inline void for_each_query(const F& f, std::index_sequence<J...>) {
  (f(std::integral_constant<int, static_cast<int>(J)>{}), ...);
}

}  // namespace byte_pairs_detail

// For each query q (one per lane): pair(q) holds two texels' RGBA bytes (a's in the low four
// bytes, b's in the high four), and lane q of `packed` their weights (wa in the low 16 bits, wb
// in the high 16, each at most 32767). sums[q % 4] gets a_c wa + b_c wb added in its lane
// 4 (q / 4) + c for each channel c: query q's channels in the 128-bit block q / 4.
template <class Arch, class Pair>
[[gnu::always_inline]] inline void madd_byte_pairs(xsimd::batch<std::int32_t, Arch> (&sums)[4],
                                                   const Pair& pair,
                                                   xsimd::batch<std::int32_t, Arch> packed) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
  constexpr std::size_t kLanes = Ints::size;
  static_assert(kLanes == 4 || kLanes == 8, "madd_byte_pairs: 4 or 8 lanes");
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    const __m256i interleave =
        _mm256_setr_epi8(0, -1, 4, -1, 1, -1, 5, -1, 2, -1, 6, -1, 3, -1, 7, -1,  //
                         0, -1, 4, -1, 1, -1, 5, -1, 2, -1, 6, -1, 3, -1, 7, -1);
    const auto one = [&](auto j) EDGEWISE_INLINE_LAMBDA {
      constexpr int k = decltype(j)::value;
      const __m128i low = _mm_cvtsi64_si128(static_cast<long long>(pair(k)));
      const __m128i high = _mm_cvtsi64_si128(static_cast<long long>(pair(k + 4)));
      const __m256i texels = _mm256_shuffle_epi8(
          _mm256_inserti128_si256(_mm256_castsi128_si256(low), high, 1), interleave);
      const __m256i weights = _mm256_permutevar8x32_epi32(
          packed, _mm256_setr_epi32(k, k, k, k, k + 4, k + 4, k + 4, k + 4));
      sums[k] = _mm256_add_epi32(sums[k], _mm256_madd_epi16(texels, weights));
    };
    byte_pairs_detail::for_each_query(one, std::make_index_sequence<4>{});
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    const auto one = [&](auto j) EDGEWISE_INLINE_LAMBDA {
      constexpr int k = decltype(j)::value;
      const __m128i bytes = _mm_cvtsi64_si128(static_cast<long long>(pair(k)));
#if defined(__SSSE3__)
      const __m128i texels = _mm_shuffle_epi8(
          bytes, _mm_setr_epi8(0, -1, 4, -1, 1, -1, 5, -1, 2, -1, 6, -1, 3, -1, 7, -1));
#else
      const __m128i texels = _mm_unpacklo_epi8(_mm_unpacklo_epi8(bytes, _mm_srli_si128(bytes, 4)),
                                               _mm_setzero_si128());
#endif
      const __m128i weights = _mm_shuffle_epi32(packed, _MM_SHUFFLE(k, k, k, k));
      sums[k] = _mm_add_epi32(sums[k], _mm_madd_epi16(texels, weights));
    };
    byte_pairs_detail::for_each_query(one, std::make_index_sequence<4>{});
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    alignas(16) std::int32_t weights[4];
    packed.store_aligned(weights);
    for (int k = 0; k < 4; ++k) {
      const int16x8_t texels = vreinterpretq_s16_u16(vmovl_u8(vcreate_u8(pair(k))));
      const auto wa = static_cast<std::int16_t>(weights[k] & 0xFFFF);
      const auto wb = static_cast<std::int16_t>(weights[k] >> 16);
      int32x4_t sum = sums[k];
      sum = vmlal_n_s16(sum, vget_low_s16(texels), wa);
      sum = vmlal_n_s16(sum, vget_high_s16(texels), wb);
      sums[k] = sum;
    }
  } else
#endif
  {
    alignas(64) std::int32_t weights[kLanes];
    packed.store_aligned(weights);
    for (int k = 0; k < 4; ++k) {
      alignas(64) std::int32_t sum[kLanes];
      sums[k].store_aligned(sum);
      for (std::size_t part = 0; part < kLanes / 4; ++part) {
        const std::size_t query = k + 4 * part;
        const std::uint64_t bytes = pair(query);
        const std::int32_t wa = weights[query] & 0xFFFF, wb = weights[query] >> 16;
        for (int c = 0; c < 4; ++c) {
          const auto a = static_cast<std::int32_t>((bytes >> (8 * c)) & 0xFF);
          const auto b = static_cast<std::int32_t>((bytes >> (8 * c + 32)) & 0xFF);
          sum[4 * part + c] += a * wa + b * wb;
        }
      }
      sums[k] = Ints::load_aligned(sum);
    }
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
