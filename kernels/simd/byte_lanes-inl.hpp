// Byte k of each 32-bit lane (packed 8-bit channels) as the lane's value, 0 .. 255: one byte
// shuffle on x86 (pshufb), shifts and a mask elsewhere.
#pragma once

#include <cstdint>
#include <type_traits>

#include <xsimd/xsimd.hpp>

#include "simd_ops-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// Lane j of the byte shuffle (pshufb) that moves byte k of each 32-bit lane of a 128-bit block to
// the lane's lowest byte and zeroes the others (index bit 7 set).
constexpr std::int32_t byte_k_selector(int k, int j) {
  return static_cast<std::int32_t>(0x80808000u + 4 * j + k);
}

#if defined(__SSSE3__)
EDGEWISE_INLINE __m128i byte_k_of_lanes(int k) {
  return _mm_setr_epi32(byte_k_selector(k, 0), byte_k_selector(k, 1), byte_k_selector(k, 2),
                        byte_k_selector(k, 3));
}
#endif

template <class Arch>
EDGEWISE_INLINE xsimd::batch<std::int32_t, Arch> byte_of_lanes(
    xsimd::batch<std::int32_t, Arch> packed, int k) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
#if defined(__AVX512BW__)
  if constexpr (std::is_base_of_v<xsimd::avx512bw, Arch>) {
    const auto lane = [k](int j) { return byte_k_selector(k, j); };
    return _mm512_shuffle_epi8(
        packed,
        _mm512_setr_epi32(lane(0), lane(1), lane(2), lane(3), lane(0), lane(1), lane(2), lane(3),
                          lane(0), lane(1), lane(2), lane(3), lane(0), lane(1), lane(2), lane(3)));
  } else
#endif
#if defined(__AVX2__)
      if constexpr (std::is_base_of_v<xsimd::avx2, Arch> && Ints::size == 8) {
    // A 256-bit constant, not a broadcast 128-bit one: the compiler then reads it as the
    // shuffle's memory operand instead of building it in a register (and spilling it).
    const auto lane = [k](int j) { return byte_k_selector(k, j); };
    return _mm256_shuffle_epi8(packed, _mm256_setr_epi32(lane(0), lane(1), lane(2), lane(3),
                                                         lane(0), lane(1), lane(2), lane(3)));
  } else
#endif
#if defined(__SSSE3__)
      if constexpr (std::is_base_of_v<xsimd::ssse3, Arch> && Ints::size == 4) {
    return _mm_shuffle_epi8(packed, byte_k_of_lanes(k));
  } else
#endif
  {
    // Logical shift (as unsigned), masked below the top byte.
    using Uints = xsimd::batch<std::uint32_t, Arch>;
    const Uints bits = xsimd::bitwise_cast<Uints>(packed);
    return xsimd::bitwise_cast<Ints>(k == 3 ? bits >> 24 : (bits >> (8 * k)) & Uints(0xFF));
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
