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

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
