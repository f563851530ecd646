// The few operations xsimd 8.1 lacks, per architecture: collecting lane sign bits, lane masks
// from and to bits, a float comparison's lanes as integers, a correctly rounded division on
// AArch64 and a fused multiply-add on AVX-512; and the inlining attributes the kernels force
// where GCC would call instead.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <xsimd/xsimd.hpp>

#if defined(__SSE2__)
#include <immintrin.h>
#endif
#if defined(__ARM_NEON)
#include <arm_neon.h>
#endif

#define EDGEWISE_INLINE [[gnu::always_inline]] inline
// For lambdas in loops: inlined (GCC otherwise calls each once per batch, passing the queries
// and results through memory).
#define EDGEWISE_INLINE_LAMBDA __attribute__((always_inline))

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// x y + z rounded once where the ISA fuses (xsimd::fma), also on AVX-512, where xsimd 8.1 falls
// back to a multiply and an add: 16-lane kernels then round as their 8-lane forms on AVX2 do.
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<float, Arch> fused_multiply_add(
    xsimd::batch<float, Arch> x, xsimd::batch<float, Arch> y, xsimd::batch<float, Arch> z) {
#if defined(__AVX512F__)
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    return _mm512_fmadd_ps(x, y, z);
  } else
#endif
  {
    return xsimd::fma(x, y, z);
  }
}

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

// The eight lanes of every 8-bit set, all ones where the bit is set: one load makes the mask
// that a broadcast, an and and a compare would (8 KiB, of which a triangle's rows touch few).
struct EightLaneMasks {
  alignas(32) std::int32_t lanes[256][8];
};
inline constexpr EightLaneMasks kEightLaneMasks = [] {
  EightLaneMasks table{};
  for (int bits = 0; bits < 256; ++bits) {
    for (int lane = 0; lane < 8; ++lane)
      table.lanes[bits][lane] = (bits >> lane) & 1 ? -1 : 0;
  }
  return table;
}();

// Lane i true where bit i of `bits` is set (the bits of kLanes lanes; higher bits ignored).
template <class Arch>
inline xsimd::batch_bool<float, Arch> lanes_of_bits(std::uint32_t bits) {
  using Bools = xsimd::batch_bool<float, Arch>;
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    return Bools(
        _mm256_load_ps(reinterpret_cast<const float*>(kEightLaneMasks.lanes[bits & 0xFFu])));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    const __m128i bit = _mm_setr_epi32(1, 2, 4, 8);
    const __m128i set = _mm_and_si128(_mm_set1_epi32(static_cast<int>(bits)), bit);
    return Bools(_mm_castsi128_ps(_mm_cmpeq_epi32(set, bit)));
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    const uint32x4_t bit = {1, 2, 4, 8};
    return Bools(vceqq_u32(vandq_u32(vdupq_n_u32(bits), bit), bit));
  } else
#endif
  {
    static_assert(!sizeof(Arch), "lanes_of_bits: no implementation for this architecture");
  }
}

// Bit i set where lane i is true: the inverse of lanes_of_bits().
template <class Arch>
inline std::uint32_t bits_of_lanes(xsimd::batch_bool<float, Arch> lanes) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    return static_cast<std::uint32_t>(_mm256_movemask_ps(lanes));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    return static_cast<std::uint32_t>(_mm_movemask_ps(lanes));
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    const uint32x4_t weight = {1, 2, 4, 8};
    return vaddvq_u32(vandq_u32(lanes, weight));
  } else
#endif
  {
    static_assert(!sizeof(Arch), "bits_of_lanes: no implementation for this architecture");
  }
}

// The largest lane (for NaN-free lanes; with NaN, some lane's value or NaN), by halving.
template <class Arch>
inline float lane_max(xsimd::batch<float, Arch> v) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    __m128 m = _mm_max_ps(_mm256_castps256_ps128(v), _mm256_extractf128_ps(v, 1));
    m = _mm_max_ps(m, _mm_movehl_ps(m, m));
    return _mm_cvtss_f32(_mm_max_ss(m, _mm_shuffle_ps(m, m, 1)));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    const __m128 m = _mm_max_ps(v, _mm_movehl_ps(v, v));
    return _mm_cvtss_f32(_mm_max_ss(m, _mm_shuffle_ps(m, m, 1)));
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    return vmaxvq_f32(v);
  } else
#endif
  {
    static_assert(!sizeof(Arch), "lane_max: no implementation for this architecture");
  }
}

// The lanes of a float comparison as int32 lanes, all ones where it holds: the register itself.
// (Selecting a constant by the mask with xsimd::select() can cost one more compare.)
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<std::int32_t, Arch> mask_lanes(
    xsimd::batch_bool<float, Arch> mask) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    return _mm256_castps_si256(mask);
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    return _mm_castps_si128(mask);
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    return vreinterpretq_s32_u32(mask);
  } else
#endif
  {
    static_assert(!sizeof(Arch), "mask_lanes: no implementation for this architecture");
  }
}

// The lanes of an int32 comparison as int32 lanes, all ones where it holds.
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<std::int32_t, Arch> mask_lanes(
    xsimd::batch_bool<std::int32_t, Arch> mask) {
#if defined(__aarch64__)
  if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    return vreinterpretq_s32_u32(mask);
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch> || std::is_base_of_v<xsimd::avx, Arch>) {
    return typename xsimd::batch<std::int32_t, Arch>::register_type(mask);  // the same register
  } else
#endif
  {
    static_assert(!sizeof(Arch), "mask_lanes: no implementation for this architecture");
  }
}

// a / b, correctly rounded as the scalar division is. (xsimd 8.1 divides float batches on
// AArch64 by a reciprocal estimate refined by Newton steps, which can differ in the last bit.)
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<float, Arch> divide_exactly(
    xsimd::batch<float, Arch> a, xsimd::batch<float, Arch> b) {
#if defined(__aarch64__)
  if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    return vdivq_f32(a, b);
  } else
#endif
  {
    return a / b;  // divps on x86
  }
}

// Sign bits of an 8x8 block of int32 values held in batches in row order (a row is 8 / lanes
// batches, or a batch 16 lanes / 8 rows): bit (row * 8 + column) set when that value is
// negative. On x86 saturating packs keep each value's sign while narrowing to bytes, so one
// movemask serves several rows; AVX-512 compares two rows into one mask register.
template <class Arch>
inline std::uint64_t sign_bits_8x8(const xsimd::batch<std::int32_t, Arch>* rows) {
#if defined(__AVX512F__)
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    std::uint64_t bits = 0;
    for (int pair = 0; pair < 4; ++pair) {
      const __mmask16 negative = _mm512_cmplt_epi32_mask(rows[pair], _mm512_setzero_si512());
      bits |= std::uint64_t{negative} << (16 * pair);
    }
    return bits;
  } else
#endif
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

// Eight values held as double batches, converted (exact integers in int32 range) to int32
// batches: rows[8 / double lanes] -> out[8 / int32 lanes].
template <class Arch>
inline void to_int32_rows(const xsimd::batch<double, Arch>* rows,
                          xsimd::batch<std::int32_t, Arch>* out) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    out[0] = _mm256_set_m128i(_mm256_cvttpd_epi32(rows[1]), _mm256_cvttpd_epi32(rows[0]));
    return;
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    out[0] = _mm_unpacklo_epi64(_mm_cvttpd_epi32(rows[0]), _mm_cvttpd_epi32(rows[1]));
    out[1] = _mm_unpacklo_epi64(_mm_cvttpd_epi32(rows[2]), _mm_cvttpd_epi32(rows[3]));
    return;
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    for (int i = 0; i < 2; ++i) {
      out[i] = vcombine_s32(vmovn_s64(vcvtq_s64_f64(rows[2 * i])),
                            vmovn_s64(vcvtq_s64_f64(rows[2 * i + 1])));
    }
    return;
  } else
#endif
  {
    static_assert(!sizeof(Arch), "to_int32_rows: no implementation for this architecture");
  }
}

// The smallest and the largest of the lanes of an int32 batch, by halving.
// a * b modulo 2^32 in every lane. The product is taken in unsigned lanes: where an ISA has no
// 32-bit vector multiply (SSE2), xsimd multiplies lane by lane in scalar code, where a signed
// overflow would be undefined behaviour.
template <class Arch>
inline xsimd::batch<std::int32_t, Arch> wrapping_multiply(xsimd::batch<std::int32_t, Arch> a,
                                                          xsimd::batch<std::int32_t, Arch> b) {
  using Signed = xsimd::batch<std::int32_t, Arch>;
  using Unsigned = xsimd::batch<std::uint32_t, Arch>;
  return xsimd::bitwise_cast<Signed>(xsimd::bitwise_cast<Unsigned>(a) *
                                     xsimd::bitwise_cast<Unsigned>(b));
}

template <class Arch>
inline std::int32_t lane_min(xsimd::batch<std::int32_t, Arch> v) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    __m128i m = _mm_min_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
    m = _mm_min_epi32(m, _mm_shuffle_epi32(m, 0x4E));
    return _mm_cvtsi128_si32(_mm_min_epi32(m, _mm_shuffle_epi32(m, 0xB1)));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    using Ints = xsimd::batch<std::int32_t, Arch>;
    const Ints m = xsimd::min(v, Ints(_mm_shuffle_epi32(v, 0x4E)));
    return _mm_cvtsi128_si32(xsimd::min(m, Ints(_mm_shuffle_epi32(m, 0xB1))));
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    return vminvq_s32(v);
  } else
#endif
  {
    static_assert(!sizeof(Arch), "lane_min: no implementation for this architecture");
  }
}

template <class Arch>
inline std::int32_t lane_max(xsimd::batch<std::int32_t, Arch> v) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    __m128i m = _mm_max_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
    m = _mm_max_epi32(m, _mm_shuffle_epi32(m, 0x4E));
    return _mm_cvtsi128_si32(_mm_max_epi32(m, _mm_shuffle_epi32(m, 0xB1)));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    using Ints = xsimd::batch<std::int32_t, Arch>;
    const Ints m = xsimd::max(v, Ints(_mm_shuffle_epi32(v, 0x4E)));
    return _mm_cvtsi128_si32(xsimd::max(m, Ints(_mm_shuffle_epi32(m, 0xB1))));
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    return vmaxvq_s32(v);
  } else
#endif
  {
    static_assert(!sizeof(Arch), "lane_max: no implementation for this architecture");
  }
}

// The low byte of each of eight int32 values (each in 0 .. 255), as bytes 0 .. 7 of a word.
template <class Arch>
inline std::uint64_t low_bytes(const xsimd::batch<std::int32_t, Arch>* rows) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    const __m256i v = rows[0];
    const __m128i words =
        _mm_packs_epi32(_mm256_castsi256_si128(v), _mm256_extracti128_si256(v, 1));
    return static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_packus_epi16(words, words)));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    const __m128i words = _mm_packs_epi32(rows[0], rows[1]);
    return static_cast<std::uint64_t>(_mm_cvtsi128_si64(_mm_packus_epi16(words, words)));
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    const int16x8_t words = vcombine_s16(vmovn_s32(rows[0]), vmovn_s32(rows[1]));
    return vget_lane_u64(vreinterpret_u64_u8(vqmovun_s16(words)), 0);
  } else
#endif
  {
    static_assert(!sizeof(Arch), "low_bytes: no implementation for this architecture");
  }
}

// The horizontal minimum of each of four batches: out[i] = min over the lanes of v[i]. Two
// rounds of interleaving leave, in every group of four lanes, lane i holding a partial minimum
// of v[i] (zip_lo/zip_hi interleave within 128-bit halves on AVX2, which keeps that pattern).
template <class Arch>
inline void horizontal_min4(const xsimd::batch<std::int32_t, Arch>* v, std::int32_t* out) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
  using Pairs = xsimd::batch<std::int64_t, Arch>;
  const Ints v01 = xsimd::min(xsimd::zip_lo(v[0], v[1]), xsimd::zip_hi(v[0], v[1]));
  const Ints v23 = xsimd::min(xsimd::zip_lo(v[2], v[3]), xsimd::zip_hi(v[2], v[3]));
  const Pairs p01 = xsimd::bitwise_cast<Pairs>(v01), p23 = xsimd::bitwise_cast<Pairs>(v23);
  const Ints partial = xsimd::min(xsimd::bitwise_cast<Ints>(xsimd::zip_lo(p01, p23)),
                                  xsimd::bitwise_cast<Ints>(xsimd::zip_hi(p01, p23)));
  alignas(64) std::int32_t lanes[Ints::size];
  partial.store_aligned(lanes);
  for (std::size_t i = 0; i < 4; ++i) {
    std::int32_t m = lanes[i];
    for (std::size_t j = i + 4; j < Ints::size; j += 4)
      m = m < lanes[j] ? m : lanes[j];
    out[i] = m;
  }
}

// Four channels of colour values in 0 .. 255 (any float; out-of-range values saturate, NaN gives
// 0) rounded to nearest (ties to even) and packed R | G << 8 | B << 16 | A << 24 per lane.
// On x86 the saturating packs do the clamping and one byte shuffle interleaves the channels.
template <class Arch>
inline xsimd::batch<std::int32_t, Arch> pack_rgba8_lanes(
    const xsimd::batch<float, Arch>* channels) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
#if defined(__AVX512BW__)
  if constexpr (std::is_base_of_v<xsimd::avx512bw, Arch>) {
    // As the AVX2 code below, on four 128-bit lanes of four pixels each.
    __m512i c[4];
    for (int k = 0; k < 4; ++k)
      c[k] = _mm512_cvtps_epi32(_mm512_min_ps(_mm512_set1_ps(255.0f), channels[k]));
    const __m512i planar =
        _mm512_packus_epi16(_mm512_packs_epi32(c[0], c[1]), _mm512_packs_epi32(c[2], c[3]));
    const __m512i order =
        _mm512_broadcast_i32x4(_mm_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15));
    return Ints(_mm512_shuffle_epi8(planar, order));
  } else
#endif
#if defined(__AVX2__)
      if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    // Values past 2^31 would convert to INT32_MIN: cap them first (min returns its second
    // operand, NaN, when one is NaN, and NaN converts to INT32_MIN, which saturates to 0).
    __m256i c[4];
    for (int k = 0; k < 4; ++k)
      c[k] = _mm256_cvtps_epi32(_mm256_min_ps(_mm256_set1_ps(255.0f), channels[k]));
    // Within each 128-bit half: bytes r0..r3 g0..g3 b0..b3 a0..a3, then interleaved.
    const __m256i planar =
        _mm256_packus_epi16(_mm256_packs_epi32(c[0], c[1]), _mm256_packs_epi32(c[2], c[3]));
    const __m256i order = _mm256_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15, 0,
                                           4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15);
    return Ints(_mm256_shuffle_epi8(planar, order));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    __m128i c[4];  // capped as above
    for (int k = 0; k < 4; ++k)
      c[k] = _mm_cvtps_epi32(_mm_min_ps(_mm_set1_ps(255.0f), channels[k]));
    const __m128i planar =
        _mm_packus_epi16(_mm_packs_epi32(c[0], c[1]), _mm_packs_epi32(c[2], c[3]));
#if defined(__SSSE3__)
    const __m128i order = _mm_setr_epi8(0, 4, 8, 12, 1, 5, 9, 13, 2, 6, 10, 14, 3, 7, 11, 15);
    return Ints(_mm_shuffle_epi8(planar, order));
#else
    const __m128i red_green = _mm_unpacklo_epi8(planar, _mm_srli_si128(planar, 4));
    const __m128i blue_alpha =
        _mm_unpacklo_epi8(_mm_srli_si128(planar, 8), _mm_srli_si128(planar, 12));
    return Ints(_mm_unpacklo_epi16(red_green, blue_alpha));
#endif
  } else
#endif
  {
    Ints packed(0);
    for (int k = 0; k < 4; ++k) {
      const Ints value = xsimd::nearbyint_as_int(channels[k]);
      const Ints clamped = xsimd::min(xsimd::max(value, Ints(0)), Ints(255));
      packed = packed | (clamped << (8 * k));
    }
    return packed;
  }
}

// 2^n for lanes n in 0 .. 8, without variable shifts (SSE has none): the float whose
// exponent field is n + 127 is exactly 2^n.
template <class Arch>
inline xsimd::batch<std::int32_t, Arch> power_of_two(xsimd::batch<std::int32_t, Arch> n) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
  using Floats = xsimd::batch<float, Arch>;
  const Ints exponent_bits = (n + Ints(127)) << 23;
  return xsimd::batch_cast<std::int32_t>(xsimd::bitwise_cast<Floats>(exponent_bits));
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
