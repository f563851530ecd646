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

#include "sample_kernels.hpp"
#include "../simd/byte_pairs-inl.hpp"
#include "../simd/interleave-inl.hpp"
#include "../simd/simd_ops-inl.hpp"
#include "texel_fetch-inl.hpp"

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
      madd_byte_pairs<Arch>(
          sums_,
          [&](std::size_t l) EDGEWISE_INLINE_LAMBDA {
            std::uint64_t bytes;
            std::memcpy(&bytes, texels + 4 * static_cast<std::ptrdiff_t>(at_a[l]), sizeof bytes);
            return bytes;
          },
          packed);
      return;
    }
    index_b.store_aligned(at_b);
    madd_byte_pairs<Arch>(
        sums_,
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
    transpose_blocks4<Arch>(f, out.c);
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

  const std::byte* texels_;
  Ints sums_[4];
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
