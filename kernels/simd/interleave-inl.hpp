// Batches to and from interleaved records: four channel batches stored as RGBA records (lane l's
// four values at out + 4 l), two as (x, y) pairs, records of three or six floats (and of three
// int32) loaded as one batch per field, and 4x4 transposes within 128-bit blocks; register
// shuffles per group of four lanes instead of a scalar move per lane and value.
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <xsimd/xsimd.hpp>

#include "lane_loads-inl.hpp"

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
#if defined(__AVX512F__)
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    const auto block = [&]<int kBlock>(std::integral_constant<int, kBlock>) {
      const auto lanes = [&](int k) { return _mm512_extractf32x4_ps(channels[k], kBlock); };
      store_interleaved4(lanes(0), lanes(1), lanes(2), lanes(3), out + 16 * kBlock);
    };
    block(std::integral_constant<int, 0>{});
    block(std::integral_constant<int, 1>{});
    block(std::integral_constant<int, 2>{});
    block(std::integral_constant<int, 3>{});
    return;
  } else
#endif
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

// Records of three floats, one per lane, loaded as three batches (field f of lane l from
// in[3 l + f]): in must hold 3 * lanes floats.
template <class Arch>
[[gnu::always_inline]] inline void load_interleaved3(const float* in,
                                                     xsimd::batch<float, Arch> (&fields)[3]) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    // Records 0..3 in the low halves, 4..7 in the high halves: the shuffles of the SSE branch
    // below, per half.
    const auto halves = [in](int low) {
      return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(in + low)),
                                  _mm_loadu_ps(in + low + 12), 1);
    };
    const __m256 a = halves(0), b = halves(4), c = halves(8);
    const __m256 xy = _mm256_shuffle_ps(b, c, _MM_SHUFFLE(2, 1, 3, 2));
    const __m256 yz = _mm256_shuffle_ps(a, b, _MM_SHUFFLE(1, 0, 2, 1));
    fields[0] = _mm256_shuffle_ps(a, xy, _MM_SHUFFLE(2, 0, 3, 0));
    fields[1] = _mm256_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0));
    fields[2] = _mm256_shuffle_ps(yz, c, _MM_SHUFFLE(3, 0, 3, 1));
    return;
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    const __m128 a = _mm_loadu_ps(in), b = _mm_loadu_ps(in + 4), c = _mm_loadu_ps(in + 8);
    // a = x0 y0 z0 x1, b = y1 z1 x2 y2, c = z2 x3 y3 z3
    const __m128 xy = _mm_shuffle_ps(b, c, _MM_SHUFFLE(2, 1, 3, 2));  // x2 y2 x3 y3
    const __m128 yz = _mm_shuffle_ps(a, b, _MM_SHUFFLE(1, 0, 2, 1));  // y0 z0 y1 z1
    fields[0] = _mm_shuffle_ps(a, xy, _MM_SHUFFLE(2, 0, 3, 0));
    fields[1] = _mm_shuffle_ps(yz, xy, _MM_SHUFFLE(3, 1, 2, 0));
    fields[2] = _mm_shuffle_ps(yz, c, _MM_SHUFFLE(3, 0, 3, 1));
    return;
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    const float32x4x3_t v = vld3q_f32(in);
    fields[0] = v.val[0];
    fields[1] = v.val[1];
    fields[2] = v.val[2];
    return;
  } else
#endif
  {
    static_assert(!sizeof(Arch), "load_interleaved3: no implementation for this architecture");
  }
}

// Two batches stored as (x, y) pairs, lane l's at out + 2 l: out must hold 2 * lanes floats.
template <class Arch>
[[gnu::always_inline]] inline void store_interleaved2(xsimd::batch<float, Arch> x,
                                                      xsimd::batch<float, Arch> y, float* out) {
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    const __m256 low = _mm256_unpacklo_ps(x, y);   // pairs 0, 1 | 4, 5
    const __m256 high = _mm256_unpackhi_ps(x, y);  // pairs 2, 3 | 6, 7
    _mm256_storeu_ps(out, _mm256_permute2f128_ps(low, high, 0x20));
    _mm256_storeu_ps(out + 8, _mm256_permute2f128_ps(low, high, 0x31));
    return;
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    _mm_storeu_ps(out, _mm_unpacklo_ps(x, y));
    _mm_storeu_ps(out + 4, _mm_unpackhi_ps(x, y));
    return;
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    vst2q_f32(out, (float32x4x2_t{{x, y}}));
    return;
  } else
#endif
  {
    static_assert(!sizeof(Arch), "store_interleaved2: no implementation for this architecture");
  }
}

// Four floats of record `record` (six floats each) from float `offset` on, per 4-lane block:
// block h holds record + 4 h.
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<float, Arch> record_row(const float* in, int record,
                                                                   int offset) {
  using Floats = xsimd::batch<float, Arch>;
  const float* first = in + 6 * record + offset;
#if defined(__AVX512F__)
  if constexpr (Floats::size == 16) {
    const __m512 blocks = _mm512_castps128_ps512(_mm_loadu_ps(first));
    const __m512 two = _mm512_insertf32x4(blocks, _mm_loadu_ps(first + 6 * 4), 1);
    const __m512 three = _mm512_insertf32x4(two, _mm_loadu_ps(first + 6 * 8), 2);
    return _mm512_insertf32x4(three, _mm_loadu_ps(first + 6 * 12), 3);
  } else
#endif
#if defined(__AVX2__)
      if constexpr (Floats::size == 8) {
    return _mm256_insertf128_ps(_mm256_castps128_ps256(_mm_loadu_ps(first)),
                                _mm_loadu_ps(first + 6 * 4), 1);
  } else
#endif
  {
    static_assert(Floats::size == 4, "record_row: 4, 8 or 16 lanes");
    return Floats::load_unaligned(first);
  }
}

// Records of six floats, one per lane, loaded as six batches (field f of lane l from
// in[6 l + f]): in must hold 6 * lanes floats. Within each 4-lane block, pairs of lanes are
// interleaved as floats, then pairs of pairs as doubles (the same unpacks on every ISA).
template <class Arch>
[[gnu::always_inline]] inline void load_records6(const float* in,
                                                 xsimd::batch<float, Arch> (&fields)[6]) {
  using Floats = xsimd::batch<float, Arch>;
  using Doubles = xsimd::batch<double, Arch>;
  const auto pairs_low = [](Floats a, Floats b) {
    return xsimd::bitwise_cast<Floats>(
        xsimd::zip_lo(xsimd::bitwise_cast<Doubles>(a), xsimd::bitwise_cast<Doubles>(b)));
  };
  const auto pairs_high = [](Floats a, Floats b) {
    return xsimd::bitwise_cast<Floats>(
        xsimd::zip_hi(xsimd::bitwise_cast<Doubles>(a), xsimd::bitwise_cast<Doubles>(b)));
  };
  Floats front[4], back[4];  // fields 0..3 and 2..5 of records 0..3 (and 4..7)
  for (int i = 0; i < 4; ++i) {
    front[i] = record_row<Arch>(in, i, 0);
    back[i] = record_row<Arch>(in, i, 2);
  }
  const Floats f01_a = xsimd::zip_lo(front[0], front[1]);  // s0 s1 t0 t1
  const Floats f01_b = xsimd::zip_lo(front[2], front[3]);  // s2 s3 t2 t3
  const Floats f23_a = xsimd::zip_hi(front[0], front[1]);  // fields 2, 3 of records 0, 1
  const Floats f23_b = xsimd::zip_hi(front[2], front[3]);
  const Floats f45_a = xsimd::zip_hi(back[0], back[1]);  // fields 4, 5 of records 0, 1
  const Floats f45_b = xsimd::zip_hi(back[2], back[3]);
  fields[0] = pairs_low(f01_a, f01_b);
  fields[1] = pairs_high(f01_a, f01_b);
  fields[2] = pairs_low(f23_a, f23_b);
  fields[3] = pairs_high(f23_a, f23_b);
  fields[4] = pairs_low(f45_a, f45_b);
  fields[5] = pairs_high(f45_a, f45_b);
}

// A 4x4 transpose in each 128-bit block: in[j] holds item j's four values in its first block
// (and item j + 4's in its second, with 8 lanes); out[c] value c of every item, in item order.
template <class Arch>
[[gnu::always_inline]] inline void transpose_blocks4(const xsimd::batch<float, Arch> (&in)[4],
                                                     xsimd::batch<float, Arch> (&out)[4]) {
  using Floats = xsimd::batch<float, Arch>;
  constexpr std::size_t kLanes = Floats::size;
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    const __m256 t0 = _mm256_unpacklo_ps(in[0], in[1]), t1 = _mm256_unpackhi_ps(in[0], in[1]);
    const __m256 t2 = _mm256_unpacklo_ps(in[2], in[3]), t3 = _mm256_unpackhi_ps(in[2], in[3]);
    out[0] = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(1, 0, 1, 0));
    out[1] = _mm256_shuffle_ps(t0, t2, _MM_SHUFFLE(3, 2, 3, 2));
    out[2] = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(1, 0, 1, 0));
    out[3] = _mm256_shuffle_ps(t1, t3, _MM_SHUFFLE(3, 2, 3, 2));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    const __m128 t0 = _mm_unpacklo_ps(in[0], in[1]), t1 = _mm_unpackhi_ps(in[0], in[1]);
    const __m128 t2 = _mm_unpacklo_ps(in[2], in[3]), t3 = _mm_unpackhi_ps(in[2], in[3]);
    out[0] = _mm_movelh_ps(t0, t2);
    out[1] = _mm_movehl_ps(t2, t0);
    out[2] = _mm_movelh_ps(t1, t3);
    out[3] = _mm_movehl_ps(t3, t1);
  } else
#endif
  {
    alignas(64) float lanes[4][kLanes], channels[4][kLanes];
    for (int j = 0; j < 4; ++j)
      in[j].store_aligned(lanes[j]);
    for (std::size_t item = 0; item < kLanes; ++item) {
      for (int c = 0; c < 4; ++c)
        channels[c][item] = lanes[item % 4][4 * (item / 4) + c];
    }
    for (int c = 0; c < 4; ++c)
      out[c] = Floats::load_aligned(channels[c]);
  }
}

// Records of three int32 (a triangle's corner indices), one per lane, from `records`: field i
// of every record in v[i]. With 8 lanes on AVX2 three loads, deinterleaved in registers (gathers
// cost several times as much); elsewhere a load per lane.
template <class Arch>
[[gnu::always_inline]] inline void load_records3_int32(const std::int32_t* records,
                                                       xsimd::batch<std::int32_t, Arch> (&v)[3]) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
#if defined(__AVX2__)
  if constexpr (std::is_base_of_v<xsimd::avx2, Arch> && Ints::size == 8) {
    const __m256i a = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(records));
    const __m256i b = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(records + 8));
    const __m256i c = _mm256_loadu_si256(reinterpret_cast<const __m256i*>(records + 16));
    // Field i of record t is element 3 t + i: lane (3 t + i) mod 8 of the load (3 t + i) / 8.
    // A blend per field takes each lane from its load, a permute puts the records in order.
    const __m256i c0 = _mm256_blend_epi32(_mm256_blend_epi32(a, b, 0b10010010), c, 0b00100100);
    const __m256i c1 = _mm256_blend_epi32(_mm256_blend_epi32(a, b, 0b00100100), c, 0b01001001);
    const __m256i c2 = _mm256_blend_epi32(_mm256_blend_epi32(a, b, 0b01001001), c, 0b10010010);
    v[0] = _mm256_permutevar8x32_epi32(c0, _mm256_setr_epi32(0, 3, 6, 1, 4, 7, 2, 5));
    v[1] = _mm256_permutevar8x32_epi32(c1, _mm256_setr_epi32(1, 4, 7, 2, 5, 0, 3, 6));
    v[2] = _mm256_permutevar8x32_epi32(c2, _mm256_setr_epi32(2, 5, 0, 3, 6, 1, 4, 7));
    return;
  }
#endif
  static constexpr std::int32_t kLaneIndex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  const Ints at = Ints::load_unaligned(kLaneIndex) * Ints(3);
  for (int i = 0; i < 3; ++i)
    v[i] = gather_int32<Arch>(records + i, at);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
