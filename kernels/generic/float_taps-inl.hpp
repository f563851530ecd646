// Bilinear taps in float (FilterPrecision::float32, sample.hpp), for 8-bit textures: each tap
// row's two texels decoded to float channels (sRGB through its table) and weighted in the pair
// layout of texel_pairs-inl.hpp, the sums kept per channel in that layout until total().
#pragma once

#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "../src/sample_kernels.hpp"
#include "../simd/simd_ops-inl.hpp"
#include "texel_fetch-inl.hpp"
#include "../simd/texel_pairs-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class FloatTapSums {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;

  explicit FloatTapSums(const detail::TextureDescription& texture) : texture_(texture) {
    const Floats zero(0.0f);
    for (auto& channel : sums_)
      channel = {zero, zero};
  }

  // Per lane, weight_a times the texel at storage index index_a plus weight_b times the one at
  // index_b, added to the sums. `adjacent`: index_b = index_a + 1 on every lane, so one 64-bit
  // load per lane fetches both (else a load per texel; the same sums either way).
  [[gnu::always_inline]] void add(Ints index_a, Ints index_b, bool adjacent, Floats weight_a,
                                  Floats weight_b) {
    const auto* texels = reinterpret_cast<const std::int32_t*>(texture_.texels);
    const Pairs<std::int32_t, Arch> texel =
        adjacent ? load_texel_pairs<Arch>(texture_.texels, index_a)
                 : make_pairs<std::int32_t, Arch>(load_lanes_int32<Arch>(texels, index_a),
                                                  load_lanes_int32<Arch>(texels, index_b));
    const Pairs<float, Arch> w = make_pairs<float, Arch>(weight_a, weight_b);
    for (int k = 0; k < 4; ++k) {
      Pairs<float, Arch>& sum = sums_[k];
      sum.low =
          fused_multiply_add<Arch>(decode_channel<Arch>(texture_, texel.low, k), w.low, sum.low);
      sum.high =
          fused_multiply_add<Arch>(decode_channel<Arch>(texture_, texel.high, k), w.high, sum.high);
    }
  }

  // The sums in the texture's stored units, one batch per channel.
  [[gnu::always_inline]] Rgba<Arch> total() const {
    Rgba<Arch> out;
    for (int k = 0; k < 4; ++k)
      out.c[k] = sum_pairs<Arch>(sums_[k]);
    return out;
  }

 private:
  const detail::TextureDescription& texture_;
  Pairs<float, Arch> sums_[4];
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
