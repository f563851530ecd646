// Double-precision batches: lanes rounded to float and stored, the positive lanes as bits, and
// the lanes one place back (for running sums along a row), per architecture.
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

// The lanes of `v` rounded to float and stored at out[0 .. lanes).
template <class Arch>
inline void store_as_floats(xsimd::batch<double, Arch> v, float* out) {
#if defined(__AVX512F__)
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    _mm256_storeu_ps(out, _mm512_cvtpd_ps(v));
  } else
#endif
#if defined(__AVX2__)
      if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    _mm_storeu_ps(out, _mm256_cvtpd_ps(v));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    _mm_storel_pi(reinterpret_cast<__m64*>(out), _mm_cvtpd_ps(v));
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    vst1_f32(out, vcvt_f32_f64(v));
  } else
#endif
  {
    static_assert(!sizeof(Arch), "store_as_floats: no implementation for this architecture");
  }
}

// Bit l set where lane l of `v` is positive.
template <class Arch>
inline std::uint32_t positive_lanes(xsimd::batch<double, Arch> v) {
#if defined(__AVX512F__)
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    return _mm512_cmp_pd_mask(v, _mm512_setzero_pd(), _CMP_GT_OQ);
  } else
#endif
#if defined(__AVX2__)
      if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    return static_cast<std::uint32_t>(
        _mm256_movemask_pd(_mm256_cmp_pd(v, _mm256_setzero_pd(), _CMP_GT_OQ)));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    return static_cast<std::uint32_t>(_mm_movemask_pd(_mm_cmpgt_pd(v, _mm_setzero_pd())));
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    const uint64x2_t positive = vcgtzq_f64(v);
    return static_cast<std::uint32_t>((vgetq_lane_u64(positive, 0) & 1) |
                                      (vgetq_lane_u64(positive, 1) & 2));
  } else
#endif
  {
    static_assert(!sizeof(Arch), "positive_lanes: no implementation for this architecture");
  }
}

// The last lane of `before` followed by lanes 0 .. n - 2 of `v`: the values one lane back.
template <class Arch>
inline xsimd::batch<double, Arch> previous_lanes(xsimd::batch<double, Arch> before,
                                                 xsimd::batch<double, Arch> v) {
#if defined(__AVX512F__)
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    return _mm512_castsi512_pd(
        _mm512_alignr_epi64(_mm512_castpd_si512(v), _mm512_castpd_si512(before), 7));
  } else
#endif
#if defined(__AVX2__)
      if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    // (before2, before3, v0, v1), then its odd lanes with v's even ones.
    return _mm256_shuffle_pd(_mm256_permute2f128_pd(before, v, 0x21), v, 0x5);
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    return _mm_shuffle_pd(before, v, 1);
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    return vextq_f64(before, v, 1);
  } else
#endif
  {
    static_assert(!sizeof(Arch), "previous_lanes: no implementation for this architecture");
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
