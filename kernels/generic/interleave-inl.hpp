// Four channel batches stored as interleaved RGBA records (lane l's four values at out + 4 l):
// a 4 x 4 transpose per group of four lanes instead of sixteen scalar moves per lane group.
#pragma once

#include <cstddef>
#include <type_traits>

#include <xsimd/xsimd.hpp>

#if defined(__SSE2__)
#include <immintrin.h>
#endif
#if defined(__ARM_NEON)
#include <arm_neon.h>
#endif

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

#if defined(__SSE2__)
// The transpose of four 4-lane registers (rows r, g, b, a) into four RGBA records.
inline void store_interleaved4(__m128 r, __m128 g, __m128 b, __m128 a, float* out) {
  const __m128 rg_low = _mm_unpacklo_ps(r, g), rg_high = _mm_unpackhi_ps(r, g);
  const __m128 ba_low = _mm_unpacklo_ps(b, a), ba_high = _mm_unpackhi_ps(b, a);
  _mm_storeu_ps(out + 0, _mm_movelh_ps(rg_low, ba_low));
  _mm_storeu_ps(out + 4, _mm_movehl_ps(ba_low, rg_low));
  _mm_storeu_ps(out + 8, _mm_movelh_ps(rg_high, ba_high));
  _mm_storeu_ps(out + 12, _mm_movehl_ps(ba_high, rg_high));
}
#endif

// Stores all lanes: out must hold 4 * lanes floats.
template <class Arch>
inline void store_interleaved(const xsimd::batch<float, Arch> (&channels)[4], float* out) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    for (int half = 0; half < 2; ++half) {
      const auto lanes = [&](int k) {
        return half == 0 ? _mm256_castps256_ps128(channels[k])
                         : _mm256_extractf128_ps(channels[k], 1);
      };
      store_interleaved4(lanes(0), lanes(1), lanes(2), lanes(3), out + 16 * half);
    }
    return;
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    store_interleaved4(channels[0], channels[1], channels[2], channels[3], out);
    return;
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    vst4q_f32(out, (float32x4x4_t{{channels[0], channels[1], channels[2], channels[3]}}));
    return;
  } else
#endif
  {
    static_assert(!sizeof(Arch), "store_interleaved: no implementation for this architecture");
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
