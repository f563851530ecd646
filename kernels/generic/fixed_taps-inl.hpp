// Bilinear taps in fixed point (FilterPrecision::fixed16, sample.hpp), for linear 8-bit
// textures: each tap row's two texels are widened to 16-bit channels, interleaved as
// (a.r, b.r, a.g, b.g, ...), and multiplied by their two weights, rounded to integers in units
// of 2^-15, by one multiply-add of 16-bit pairs into 32-bit sums (pmaddwd, NEON's vmlal), as
// GPUs filter. The sums are exact: a result is sum(round(w_i 2^15) c_i) 2^-15 for texel codes c_i,
// so it differs from the float32 path only by the weights' rounding, at most 2^-16 times the
// largest code per tap (2^-15 for a weight of 1, which becomes 32767).
//
// Layout: accumulator j holds the four channels of query j in its first four 32-bit lanes and,
// with 8 lanes, those of query j + 4 in its last four (one 128-bit block per query), so that
// total() needs only a 4x4 transpose per 128-bit block.
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

#include <xsimd/xsimd.hpp>

#include "../src/sample_kernels.hpp"
#include "simd_ops-inl.hpp"
#include "texel_fetch-inl.hpp"

#if defined(__SSE2__)
#include <immintrin.h>
#endif
#if defined(__ARM_NEON)
#include <arm_neon.h>
#endif

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// A weight in [0, 1] as an integer in units of 2^-15, at most 32767 (a signed 16-bit value).
inline constexpr float kFixedWeightOne = 32768.0f;
inline constexpr std::int32_t kFixedWeightMost = 32767;

template <class Arch>
class FixedTapSums {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  static constexpr std::size_t kLanes = Floats::size;
  static_assert(kLanes == 4 || kLanes == 8, "FixedTapSums: 4 or 8 lanes");

  // For a linear 8-bit texture.
  explicit FixedTapSums(const detail::TextureDescription& texture) : texels_(texture.texels) {
    for (Ints& sum : sums_)
      sum = Ints(0);
  }

  // Per lane, weight_a times the texel at storage index index_a plus weight_b times the one at
  // index_b, added to the sums. `adjacent`: index_b = index_a + 1 on every lane, so one 64-bit
  // load fetches both. Weights must lie in [0, 1] (a NaN weight gives garbage sums, which the
  // callers' defined results replace).
  [[gnu::always_inline]] void add(Ints index_a, Ints index_b, bool adjacent, Floats weight_a,
                                  Floats weight_b) {
    const std::byte* texels = texels_;
    const Ints packed = fixed_weight(weight_a) | (fixed_weight(weight_b) << 16);
    alignas(64) std::int32_t at_a[kLanes], at_b[kLanes];
    index_a.store_aligned(at_a);
    // The two texels of lane l as 8 bytes, a's RGBA then b's: one load, or one per texel.
    if (adjacent) {
      accumulate(
          [&](std::size_t l) EDGEWISE_INLINE_LAMBDA {
            std::uint64_t bytes;
            std::memcpy(&bytes, texels + 4 * static_cast<std::ptrdiff_t>(at_a[l]), sizeof bytes);
            return bytes;
          },
          packed);
      return;
    }
    index_b.store_aligned(at_b);
    accumulate(
        [&](std::size_t l) EDGEWISE_INLINE_LAMBDA {
          std::uint32_t first, second;
          std::memcpy(&first, texels + 4 * static_cast<std::ptrdiff_t>(at_a[l]), sizeof first);
          std::memcpy(&second, texels + 4 * static_cast<std::ptrdiff_t>(at_b[l]), sizeof second);
          return first | (std::uint64_t{second} << 32);
        },
        packed);
  }

  // The sums in the texture's stored units (8-bit codes), one batch per channel. A bilinear or
  // trilinear sum is an integer below 2^24 (255 codes times weights adding up to about 2^15), so
  // exact in float; the anisotropic probes' sum (up to kMaxAnisotropyLimit of them, below 2^31)
  // rounds once here, by 2^-24 relative, within the bound's rounding of the probes' mean.
  [[gnu::always_inline]] Rgba<Arch> total() const {
    Floats f[4];
    for (int j = 0; j < 4; ++j)
      f[j] = xsimd::to_float(sums_[j]);
    Rgba<Arch> out;
    transpose(f, out.c);
    const Floats unit(1.0f / kFixedWeightOne);
    for (int k = 0; k < 4; ++k)
      out.c[k] = out.c[k] * unit;
    return out;
  }

 private:
  [[gnu::always_inline]] static Ints fixed_weight(Floats w) {
    return xsimd::min(xsimd::to_int(w * Floats(kFixedWeightOne) + Floats(0.5f)),
                      Ints(kFixedWeightMost));
  }

  // sums_[j] += the multiply-add of query j's (and j + 4's) interleaved texels and weights.
  template <class Pair>
  [[gnu::always_inline]] void accumulate(const Pair& pair, Ints packed) {
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
        sums_[k] = _mm256_add_epi32(sums_[k], _mm256_madd_epi16(texels, weights));
      };
      for_each_query(one, std::make_index_sequence<4>{});
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
        sums_[k] = _mm_add_epi32(sums_[k], _mm_madd_epi16(texels, weights));
      };
      for_each_query(one, std::make_index_sequence<4>{});
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
        int32x4_t sum = sums_[k];
        sum = vmlal_n_s16(sum, vget_low_s16(texels), wa);
        sum = vmlal_n_s16(sum, vget_high_s16(texels), wb);
        sums_[k] = sum;
      }
    } else
#endif
    {
      alignas(64) std::int32_t weights[kLanes];
      packed.store_aligned(weights);
      for (int k = 0; k < 4; ++k) {
        alignas(64) std::int32_t sum[kLanes];
        sums_[k].store_aligned(sum);
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
        sums_[k] = Ints::load_aligned(sum);
      }
    }
  }

  template <class F, std::size_t... J>
  [[gnu::always_inline]] static void for_each_query(const F& f, std::index_sequence<J...>) {
    (f(std::integral_constant<int, static_cast<int>(J)>{}), ...);
  }

  // in[j] holds query j's channels (and query j + 4's); out[c] channel c of every query.
  [[gnu::always_inline]] static void transpose(const Floats (&in)[4], Floats (&out)[4]) {
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
      for (std::size_t query = 0; query < kLanes; ++query) {
        for (int c = 0; c < 4; ++c)
          channels[c][query] = lanes[query % 4][4 * (query / 4) + c];
      }
      for (int c = 0; c < 4; ++c)
        out[c] = Floats::load_aligned(channels[c]);
    }
  }

  const std::byte* texels_;
  Ints sums_[4];
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
