// Bilinear taps two texels at a time: the two texels of a tap row are neighbours in memory
// whenever the row does not wrap, so one 64-bit load per lane fetches both, half the loads (and
// half the index extractions) of one load per texel.
//
// The pair layout: a batch of N lanes with a first and a second value per lane (a and b) is held
// as two batches, `low` and `high`. Within each group of four lanes (one 128-bit block), `low`
// holds lanes 0 and 1 of the group as (a0, b0, a1, b1) and `high` lanes 2 and 3 as
// (a2, b2, a3, b3): what x86's unpack instructions and NEON's zips build from a and b, and what a
// 64-bit load per lane gives directly for texel pairs. Weights take the same layout, the
// weighted sums are accumulated in it, and sum_pairs() turns them back into one batch per
// channel (a_l + b_l, the same result on every ISA).
#pragma once

#include <cstddef>
#include <cstdint>
#include <cstring>
#include <type_traits>
#include <utility>

#include <xsimd/xsimd.hpp>

#if defined(__SSE2__)
#include <immintrin.h>
#endif
#if defined(__ARM_NEON)
#include <arm_neon.h>
#endif

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class T, class Arch>
struct Pairs {
  xsimd::batch<T, Arch> low, high;
};

namespace texel_pairs_detail {

// The natural lane that element e of a 64-bit batch holds in `low` (kHigh false) or `high`.
template <bool kHigh>
constexpr std::size_t lane_of(std::size_t e) {
  return 4 * (e / 2) + (kHigh ? 2 : 0) + e % 2;
}

// Portable form of the layout, for architectures without a branch below.
template <bool kHigh, class T, class Arch>
xsimd::batch<T, Arch> interleave(xsimd::batch<T, Arch> a, xsimd::batch<T, Arch> b) {
  constexpr std::size_t kLanes = xsimd::batch<T, Arch>::size;
  alignas(64) T in[2][kLanes], out[kLanes];
  a.store_aligned(in[0]);
  b.store_aligned(in[1]);
  for (std::size_t i = 0; i < kLanes; ++i)
    out[i] = in[i % 2][lane_of<kHigh>(i / 2)];
  return xsimd::batch<T, Arch>::load_aligned(out);
}

template <class Arch, std::size_t... E>
[[gnu::always_inline]] inline xsimd::batch<std::uint64_t, Arch> load_pairs(
    const std::byte* texels, const std::int32_t* at, std::index_sequence<E...>, auto lane) {
  const auto pair = [&](std::size_t l) {
    std::uint64_t v;
    std::memcpy(&v, texels + 4 * static_cast<std::ptrdiff_t>(at[l]), sizeof v);
    return v;
  };
  return xsimd::batch<std::uint64_t, Arch>{pair(lane(E))...};
}

}  // namespace texel_pairs_detail

// (a, b) in the pair layout, for float or int32 batches.
template <class T, class Arch>
[[gnu::always_inline]] inline Pairs<T, Arch> make_pairs(xsimd::batch<T, Arch> a,
                                                        xsimd::batch<T, Arch> b) {
  static_assert(sizeof(T) == 4 && xsimd::batch<T, Arch>::size % 4 == 0);
#if defined(__AVX512F__)
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    if constexpr (std::is_same_v<T, float>) {
      return {_mm512_unpacklo_ps(a, b), _mm512_unpackhi_ps(a, b)};
    } else {
      return {_mm512_unpacklo_epi32(a, b), _mm512_unpackhi_epi32(a, b)};
    }
  } else
#endif
#if defined(__AVX2__)
      if constexpr (std::is_base_of_v<xsimd::avx2, Arch> && xsimd::batch<T, Arch>::size == 8) {
    if constexpr (std::is_same_v<T, float>) {
      return {_mm256_unpacklo_ps(a, b), _mm256_unpackhi_ps(a, b)};
    } else {
      return {_mm256_unpacklo_epi32(a, b), _mm256_unpackhi_epi32(a, b)};
    }
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch> && xsimd::batch<T, Arch>::size == 4) {
    if constexpr (std::is_same_v<T, float>) {
      return {_mm_unpacklo_ps(a, b), _mm_unpackhi_ps(a, b)};
    } else {
      return {_mm_unpacklo_epi32(a, b), _mm_unpackhi_epi32(a, b)};
    }
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    if constexpr (std::is_same_v<T, float>) {
      return {vzip1q_f32(a, b), vzip2q_f32(a, b)};
    } else {
      return {vzip1q_s32(a, b), vzip2q_s32(a, b)};
    }
  } else
#endif
  {
    return {texel_pairs_detail::interleave<false>(a, b),
            texel_pairs_detail::interleave<true>(a, b)};
  }
}

// a_l + b_l per lane, in natural order, from the pair layout.
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<float, Arch> sum_pairs(const Pairs<float, Arch>& pairs) {
  using Floats = xsimd::batch<float, Arch>;
#if defined(__AVX512F__)
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    // No horizontal add of 512 bits: the a and b of each 128-bit block apart, then added.
    const __m512 a = _mm512_shuffle_ps(pairs.low, pairs.high, _MM_SHUFFLE(2, 0, 2, 0));
    const __m512 b = _mm512_shuffle_ps(pairs.low, pairs.high, _MM_SHUFFLE(3, 1, 3, 1));
    return _mm512_add_ps(a, b);
  } else
#endif
#if defined(__AVX2__)
      if constexpr (std::is_base_of_v<xsimd::avx2, Arch> && Floats::size == 8) {
    return _mm256_hadd_ps(pairs.low, pairs.high);
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch> && Floats::size == 4) {
    const __m128 a = _mm_shuffle_ps(pairs.low, pairs.high, _MM_SHUFFLE(2, 0, 2, 0));
    const __m128 b = _mm_shuffle_ps(pairs.low, pairs.high, _MM_SHUFFLE(3, 1, 3, 1));
    return _mm_add_ps(a, b);
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    return vpaddq_f32(pairs.low, pairs.high);
  } else
#endif
  {
    constexpr std::size_t kLanes = Floats::size;
    alignas(64) float in[2][kLanes], out[kLanes];
    pairs.low.store_aligned(in[0]);
    pairs.high.store_aligned(in[1]);
    for (std::size_t l = 0; l < kLanes; ++l) {
      const bool high = l % 4 >= 2;
      const std::size_t e = 2 * (2 * (l / 4) + l % 2);  // a's element in its batch
      out[l] = in[high][e] + in[high][e + 1];
    }
    return Floats::load_aligned(out);
  }
}

// The 4-byte texels at `index` and index + 1 of each lane, in the pair layout (a the texel at
// `index`), by one 64-bit load per lane. Both texels must be in the storage.
template <class Arch>
[[gnu::always_inline]] inline Pairs<std::int32_t, Arch> load_texel_pairs(
    const std::byte* texels, xsimd::batch<std::int32_t, Arch> index) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
  constexpr std::size_t kPairs = Ints::size / 2;
  alignas(64) std::int32_t at[Ints::size];
  index.store_aligned(at);
  const auto low = texel_pairs_detail::load_pairs<Arch>(
      texels, at, std::make_index_sequence<kPairs>{},
      [](std::size_t e) { return texel_pairs_detail::lane_of<false>(e); });
  const auto high = texel_pairs_detail::load_pairs<Arch>(
      texels, at, std::make_index_sequence<kPairs>{},
      [](std::size_t e) { return texel_pairs_detail::lane_of<true>(e); });
  return {xsimd::bitwise_cast<Ints>(low), xsimd::bitwise_cast<Ints>(high)};
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
