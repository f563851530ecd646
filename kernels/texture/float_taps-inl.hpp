// Bilinear taps in float (FilterPrecision::float32, sample.hpp), for 8-bit textures: each tap
// row's two texels decoded to float channels (sRGB through its table) and weighted in the pair
// layout of texel_pairs-inl.hpp, the sums kept per channel in that layout until total().
#pragma once

#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "sample_kernels.hpp"
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
    Pending& p = pending_[count_++];
    p.index_a = index_a;
    p.index_b = index_b;
    p.adjacent = adjacent;
    p.weight_a = weight_a;
    p.weight_b = weight_b;
    if (count_ == kPending) flush();
  }

  // The sums in the texture's stored units, one batch per channel.
  [[gnu::always_inline]] Rgba<Arch> total() {
    flush();
    Rgba<Arch> out;
    for (int k = 0; k < 4; ++k)
      out.c[k] = sum_pairs<Arch>(sums_[k]);
    return out;
  }

 private:
  // Taps wait until four are known (a trilinear query's tap rows), then their texels are loaded
  // together before any is weighed: their cache misses overlap instead of each waiting behind
  // the previous tap's sums. The sums take the taps in the order added, as one at a time would.
  static constexpr int kPending = 4;
  struct Pending {
    Ints index_a, index_b;
    bool adjacent;
    Floats weight_a, weight_b;
  };

  [[gnu::always_inline]] void flush() {
    const auto* texels = reinterpret_cast<const std::int32_t*>(texture_.texels);
    Pairs<std::int32_t, Arch> texel[kPending];
    for (int i = 0; i < count_; ++i) {
      const Pending& p = pending_[i];
      texel[i] = p.adjacent
                     ? load_texel_pairs<Arch>(texture_.texels, p.index_a)
                     : make_pairs<std::int32_t, Arch>(load_lanes_int32<Arch>(texels, p.index_a),
                                                      load_lanes_int32<Arch>(texels, p.index_b));
    }
    for (int i = 0; i < count_; ++i) {
      const Pending& p = pending_[i];
      const Pairs<float, Arch> w = make_pairs<float, Arch>(p.weight_a, p.weight_b);
      for (int k = 0; k < 4; ++k) {
        Pairs<float, Arch>& sum = sums_[k];
        sum.low = fused_multiply_add<Arch>(decode_channel<Arch>(texture_, texel[i].low, k), w.low,
                                           sum.low);
        sum.high = fused_multiply_add<Arch>(decode_channel<Arch>(texture_, texel[i].high, k),
                                            w.high, sum.high);
      }
    }
    count_ = 0;
  }

  const detail::TextureDescription& texture_;
  Pairs<float, Arch> sums_[4];
  Pending pending_[kPending];
  int count_ = 0;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
