// The tent and Mitchell resolves: a batch of consecutive output pixels per step, each lane
// summing the taps in the reference's order with the reference's float operations, so every
// lane's sum is the reference's bit for bit.
//
// Lane l of a batch at output column x reads source column (x + l) f + i for tap i: with the
// source's rows kept as float planes split by phase (plane p holds columns m f + p, m = x + q
// for i = q f + p), a tap is one unaligned load per channel. Each plane row is made once, from a
// source row clamped to the image, its columns clamped too (the reference clamps each
// coordinate), and kept in a ring of as many rows as the taps span.
#pragma once

#include <algorithm>
#include <climits>
#include <cstddef>
#include <cstdint>
#include <cstring>
#include <vector>

#include <xsimd/xsimd.hpp>

#include "resolve_call.hpp"
#include "../simd/lane_arch-inl.hpp"
#include "../simd/simd_ops-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

namespace resolve_detail {

inline std::int32_t floor_div(std::int32_t a, std::int32_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

inline std::int32_t floor_mod(std::int32_t a, std::int32_t b) {
  return a - floor_div(a, b) * b;
}

}  // namespace resolve_detail

// One call's resolve: its plane layout, the ring of plane rows and the output rows.
template <class Arch>
class TapResolve {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  using Words = xsimd::batch<std::uint32_t, Arch>;
  static constexpr std::int32_t kLanes = static_cast<std::int32_t>(Floats::size);
  static constexpr std::int32_t kTogether = 2;  // batches summed at once

  explicit TapResolve(const detail::ResolveCall& call) : call_(call), f_(call.factor) {
    using resolve_detail::floor_div;
    std::int32_t i_min = INT_MAX, i_max = INT_MIN, j_min = INT_MAX, j_max = INT_MIN;
    for (const detail::ResolveTap& tap : call.taps) {
      i_min = std::min(i_min, tap.i);
      i_max = std::max(i_max, tap.i);
      j_min = std::min(j_min, tap.j);
      j_max = std::max(j_max, tap.j);
    }
    q_min_ = floor_div(i_min, f_);
    const std::int32_t q_max = floor_div(i_max, f_);
    // Plane element m - q_min holds column m f + p; batches, kTogether at a time, read up to
    // kTogether batches past the last output column.
    batches_ = (call.width + kTogether * kLanes - 1) / (kTogether * kLanes) * kTogether;
    columns_ = static_cast<std::size_t>(batches_ * kLanes + q_max - q_min_);
    channel_stride_ = columns_ * static_cast<std::size_t>(f_);
    sample_stride_ = channel_stride_ * 4;
    row_stride_ = sample_stride_ * static_cast<std::size_t>(call.samples);
    ring_ = j_max - j_min + 1;
    planes_.resize(row_stride_ * static_cast<std::size_t>(ring_));
    ring_rows_.assign(static_cast<std::size_t>(ring_), INT_MIN);
    tap_planes_.resize(call.taps.size());
  }

  // Output rows [first_row, last_row).
  void rows(std::int32_t first_row, std::int32_t last_row) {
    for (std::int32_t y = first_row; y < last_row; ++y)
      row(y);
  }

 private:
  void row(std::int32_t y) {
    using resolve_detail::floor_div;
    for (std::size_t t = 0; t < call_.taps.size(); ++t) {
      const detail::ResolveTap& tap = call_.taps[t];
      const std::int32_t q = floor_div(tap.i, f_);
      tap_planes_[t] = plane_row(y * f_ + tap.j) +
                       static_cast<std::size_t>(tap.sample) * sample_stride_ +
                       static_cast<std::size_t>(tap.i - q * f_) * columns_ +
                       static_cast<std::size_t>(q - q_min_);
    }
    // kTogether batches at a time, so that more independent sums share each tap's weight; each
    // lane still adds its taps in order.
    for (std::int32_t batch = 0; batch < batches_; batch += kTogether) {
      const std::int32_t x = batch * kLanes;
      Floats sums[kTogether][4];
      for (auto& batch_sums : sums) {
        for (Floats& sum : batch_sums)
          sum = Floats(0.0f);
      }
      for (std::size_t t = 0; t < call_.taps.size(); ++t) {
        const float* at = tap_planes_[t] + x;
        const Floats weight(call_.taps[t].weight);
        for (std::size_t half = 0; half < kTogether; ++half) {
          for (std::size_t channel = 0; channel < 4; ++channel) {
            sums[half][channel] =
                sums[half][channel] +
                weight * Floats::load_unaligned(at + half * kLanes + channel * channel_stride_);
          }
        }
      }
      for (std::int32_t half = 0; half < kTogether; ++half)
        write_batch(sums[half], y, x + half * kLanes);
    }
  }

  // The planes of source row `source_row` (clamped to the image), made on first use.
  float* plane_row(std::int32_t source_row) {
    const auto slot = static_cast<std::size_t>(resolve_detail::floor_mod(source_row, ring_));
    float* row = planes_.data() + slot * row_stride_;
    if (ring_rows_[slot] == source_row) return row;
    ring_rows_[slot] = source_row;
    const std::int32_t y = std::clamp(source_row, 0, call_.source_height - 1);
    for (std::int32_t k = 0; k < call_.samples; ++k) {
      for (std::int32_t p = 0; p < f_; ++p) {
        fill_plane(row + static_cast<std::size_t>(k) * sample_stride_ +
                       static_cast<std::size_t>(p) * columns_,
                   y, k, p);
      }
    }
    return row;
  }

  // Element m of the plane of phase p, sample k, source row y: column (m + q_min) f + p clamped.
  void plane_column(float* out, std::int32_t y, std::int32_t k, std::int32_t p,
                    std::size_t m) const {
    const std::int32_t x =
        std::clamp((static_cast<std::int32_t>(m) + q_min_) * f_ + p, 0, call_.source_width - 1);
    const std::uint32_t c = call_.color(x, y, k);
    for (std::size_t channel = 0; channel < 4; ++channel)
      out[channel * channel_stride_ + m] = static_cast<float>((c >> (8 * channel)) & 0xFFu);
  }

  void fill_plane(float* out, std::int32_t y, std::int32_t k, std::int32_t p) const {
    if (f_ > 1) {
      for (std::size_t m = 0; m < columns_; ++m)
        plane_column(out, y, k, p, m);
      return;
    }
    // Factor 1: column m is source column m + q_min, a tile row's 8 pixels at once where they
    // all lie in the image and the plane; the clamped columns beyond, one at a time.
    const std::int32_t first = std::max(0, q_min_);
    const std::int32_t last =
        std::min(call_.source_width, static_cast<std::int32_t>(columns_) + q_min_);
    std::int32_t x = first;
    for (; x < last && x % 8 != 0; ++x)
      plane_column(out, y, k, p, static_cast<std::size_t>(x - q_min_));
    for (; x + 8 <= last; x += 8) {
      const std::uint32_t* pixels = call_.pixel(x, y, k);
      for (std::int32_t h = 0; h < 8; h += kLanes) {
        const Words c = Words::load_aligned(pixels + h);
        for (std::size_t channel = 0; channel < 4; ++channel) {
          const Words bytes = (c >> (8 * static_cast<std::int32_t>(channel))) & Words(0xFFu);
          xsimd::batch_cast<float>(xsimd::bitwise_cast<Ints>(bytes))
              .store_unaligned(out + channel * channel_stride_ +
                               static_cast<std::size_t>(x + h - q_min_));
        }
      }
    }
    for (std::size_t m = 0; m < columns_; ++m) {
      const std::int32_t at = static_cast<std::int32_t>(m) + q_min_;
      if (at < first || at >= x) plane_column(out, y, k, p, m);
    }
  }

  // The reference's encoding of lanes [x, x + kLanes) of row y, those within the image written:
  // v = sum / 255 (as a product), clamped, times 255, rounded to nearest (pack_rgba8_lanes()
  // clamps after the product, which gives the same codes), or sRGB-encoded.
  void write_batch(const Floats (&sums)[4], std::int32_t y, std::int32_t x) {
    const std::int32_t count = std::min(kLanes, call_.width - x);
    if (count <= 0) return;
    Floats values[4];
    for (std::size_t channel = 0; channel < 4; ++channel) {
      const Floats v = sums[channel] * Floats(1.0f / 255.0f);
      values[channel] = v * Floats(255.0f);
      if (call_.srgb && channel < 3) v.store_aligned(srgb_values_[channel]);
    }
    pack_rgba8_lanes<Arch>(values).store_aligned(packed_);
    if (call_.srgb) {
      for (std::int32_t l = 0; l < count; ++l) {
        std::uint32_t rgba = static_cast<std::uint32_t>(packed_[l]) & 0xFF000000u;
        for (std::size_t channel = 0; channel < 3; ++channel) {
          const float v = srgb_values_[channel][l];
          const float clamped = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // NaN: 0
          rgba |= std::uint32_t{call_.srgb_cells->code(clamped)} << (8 * channel);
        }
        packed_[l] = static_cast<std::int32_t>(rgba);
      }
    }
    std::memcpy(call_.rgba + (static_cast<std::size_t>(y) * call_.width + x) * 4, packed_,
                static_cast<std::size_t>(count) * 4);
  }

  const detail::ResolveCall& call_;
  const std::int32_t f_;
  std::int32_t q_min_ = 0;
  std::int32_t batches_ = 0;
  std::size_t columns_ = 0, channel_stride_ = 0, sample_stride_ = 0, row_stride_ = 0;
  std::int32_t ring_ = 0;
  std::vector<float> planes_;
  std::vector<std::int32_t> ring_rows_;
  std::vector<const float*> tap_planes_;
  alignas(64) std::int32_t packed_[kLanes];
  alignas(64) float srgb_values_[3][kLanes];
};

// Output rows [first_row, last_row).
template <class Arch>
void resolve_taps_rows(const detail::ResolveCall& call, std::int32_t first_row,
                       std::int32_t last_row) {
  TapResolve<Arch>(call).rows(first_row, last_row);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
