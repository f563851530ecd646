// The texture queries of one 8x8 tile and their filtered texels, for the shading kernels: the
// shared formula of kernels/draw/shading/texture_planes.hpp evaluated a batch of lanes at a time
// (the same float operations in the same order, so every query equals the scalar reference's bit
// for bit), then the ISA's sampling kernel over the tile's rows at once.
//
// Quad differences read each lane's left and right neighbours with unaligned loads one float
// off, and keep the one inside the lane's quad (select by lane parity, no shuffle): the
// coordinate arrays carry padding on both sides so these loads stay in bounds, and what they
// read outside the quad is discarded.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <xsimd/xsimd.hpp>

#include "../../core/isa_kernels.hpp"
#include "shade_batch.hpp"
#include "texture_planes.hpp"
#include "../../interpolation/interpolation-inl.hpp"
#include "../../simd/lane_arch-inl.hpp"
#include "../../simd/simd_ops-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class TextureTile {
 public:
  using Floats = xsimd::batch<float, Arch>;
  static constexpr std::size_t kLanes = Floats::size;
  static constexpr std::size_t kParts = kTileSize / kLanes;
  static constexpr std::size_t kPixels = kTileSize * kTileSize;
  // Rows per batch of the sampler's widest kernels (sample_batch-inl.hpp): the rows queried and
  // filtered are whole batches of them, so that no batch is partial. A row sampled but not
  // written costs its lanes only.
  static constexpr int kSampledRows =
      static_cast<int>((xsimd::batch<float, WideArch<Arch>>::size + kTileSize - 1) / kTileSize);

  TextureTile() {
    for (float* field : {s_, t_})
      for (std::size_t i = 0; i < kPixels + 2 * kPad; ++i)
        field[i] = 0.0f;
  }

  void begin_triangle(const detail::TexturePlanes& planes, TextureDerivatives derivatives) {
    planes_ = planes;
    derivatives_ = derivatives;
  }

  // Queries for rows first_row .. last_row of the tile whose top-left pixel is (px, py), and
  // the texels the batch's sampler filters there.
  void sample_rows(const detail::ShadeBatch& batch, std::int32_t px, std::int32_t py, int first_row,
                   int last_row) {
    query_rows(px, py, first_row, last_row);
    filter_rows(batch, first_row, last_row);
  }

  // The queries of rows first_row .. last_row, for measure() and filter_rows().
  void query_rows(std::int32_t px, std::int32_t py, int first_row, int last_row) {
    first_row = sampled_first(first_row);
    last_row = sampled_last(last_row);
    const bool quad = derivatives_ == TextureDerivatives::quad;
    // Quad differences need the other row of each quad too.
    const int first = quad ? first_row & ~1 : first_row;
    const int last = quad ? last_row | 1 : last_row;
    Floats columns[3][kParts];  // the dx terms of s, t and q
    for (std::size_t h = 0; h < kParts; ++h) {
      const Floats dx =
          interpolation_detail::lane_centers<Arch>(px + static_cast<std::int32_t>(h * kLanes)) -
          Floats(planes_.x0);
      columns[0][h] = Floats(planes_.s.dx) * dx;
      columns[1][h] = Floats(planes_.t.dx) * dx;
      columns[2][h] = Floats(planes_.q.dx) * dx;
    }
    for (int row = first; row <= last; ++row) {
      const float dy = detail::offset_y(planes_, py + row);
      const Floats s_base(planes_.s.at_vertex + planes_.s.dy * dy);
      const Floats t_base(planes_.t.at_vertex + planes_.t.dy * dy);
      const Floats q_base(planes_.q.at_vertex + planes_.q.dy * dy);
      for (std::size_t h = 0; h < kParts; ++h) {
        const std::size_t at = static_cast<std::size_t>(row) * kTileSize + h * kLanes;
        Floats s = s_base + columns[0][h];
        Floats t = t_base + columns[1][h];
        if (planes_.divides) {
          const Floats r = Floats(1.0f) / (q_base + columns[2][h]);
          s = s * r;
          t = t * r;
          r.store_aligned(r_ + at);
        }
        s.store_aligned(s_ + kPad + at);
        t.store_aligned(t_ + kPad + at);
      }
    }
    for (int row = first_row; row <= last_row; ++row) {
      for (std::size_t h = 0; h < kParts; ++h)
        derivatives_at(row, h);
    }
  }

  // The sampler's texels at the queries of rows first_row .. last_row.
  void filter_rows(const detail::ShadeBatch& batch, int first_row, int last_row) {
    first_row = sampled_first(first_row);
    last_row = sampled_last(last_row);
    const std::size_t begin = static_cast<std::size_t>(first_row) * kTileSize;
    const std::size_t count = static_cast<std::size_t>(last_row - first_row + 1) * kTileSize;
    const detail::QueryFields fields{s_ + kPad + begin, t_ + kPad + begin, dsdx_ + begin,
                                     dtdx_ + begin,     dsdy_ + begin,     dtdy_ + begin};
    const detail::ResultChannels results{
        {texels_[0] + begin, texels_[1] + begin, texels_[2] + begin, texels_[3] + begin}};
    sample_fields(*batch.texture_description, batch.sampler, fields, count, results);
  }

  // The least and greatest of each query field over the lanes `lanes[row][h]` of the rows in
  // `rows` (bit r for row r), after query_rows(): exact, as only minima and maxima of the values
  // the sampler receives, so the reference finds the same.
  template <class Mask>
  detail::TileQueries measure(std::uint32_t rows, const Mask (*lanes)[kParts]) const {
    const float* fields[6] = {s_ + kPad, t_ + kPad, dsdx_, dtdx_, dsdy_, dtdy_};
    const Floats infinity(std::numeric_limits<float>::infinity());
    Floats low[6], high[6];
    for (int f = 0; f < 6; ++f) {
      low[f] = infinity;
      high[f] = -infinity;
    }
    Mask finite(true);
    for (; rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      for (std::size_t h = 0; h < kParts; ++h) {
        const Mask in = lanes[row][h];
        const std::size_t at = static_cast<std::size_t>(row) * kTileSize + h * kLanes;
        for (int f = 0; f < 6; ++f) {
          const Floats v = Floats::load_aligned(fields[f] + at);
          finite = finite & ((xsimd::abs(v) <= Floats(std::numeric_limits<float>::max())) | !in);
          low[f] = xsimd::select(in, xsimd::min(low[f], v), low[f]);
          high[f] = xsimd::select(in, xsimd::max(high[f], v), high[f]);
        }
      }
    }
    detail::TileQueries queries;
    queries.finite = xsimd::all(finite);
    for (int f = 0; f < 6; ++f) {
      queries.low[f] = -lane_max<Arch>(-low[f]);
      queries.high[f] = lane_max<Arch>(high[f]);
    }
    return queries;
  }

  // Every texel of rows first_row .. last_row set to `texel` (the budget's one texel value).
  void fill_rows(const float (&texel)[4], int first_row, int last_row) {
    for (int k = 0; k < 4; ++k) {
      const Floats value(texel[k]);
      for (int row = first_row; row <= last_row; ++row) {
        for (std::size_t h = 0; h < kParts; ++h)
          value.store_aligned(texels_[k] + static_cast<std::size_t>(row) * kTileSize + h * kLanes);
      }
    }
  }

  // Channel k (linear) of the texels at lanes h of `row`, after sample_rows().
  [[gnu::always_inline]] Floats texel(int k, int row, std::size_t h) const {
    return Floats::load_aligned(texels_[k] + static_cast<std::size_t>(row) * kTileSize +
                                h * kLanes);
  }

 private:
  static constexpr std::size_t kPad = 16;  // a whole cache line, so rows stay aligned

  static int sampled_first(int row) { return row - row % kSampledRows; }
  static int sampled_last(int row) { return row - row % kSampledRows + kSampledRows - 1; }

  void derivatives_at(int row, std::size_t h) {
    const std::size_t at = static_cast<std::size_t>(row) * kTileSize + h * kLanes;
    Floats out[4];
    if (derivatives_ == TextureDerivatives::quad) {
      const std::size_t top = static_cast<std::size_t>(row & ~1) * kTileSize + h * kLanes;
      const std::size_t bottom = top + kTileSize;
      const float* fields[2] = {s_ + kPad, t_ + kPad};
      for (int f = 0; f < 2; ++f) {
        const Floats here = Floats::load_aligned(fields[f] + at);
        const Floats right = Floats::load_unaligned(fields[f] + at + 1);
        const Floats left = Floats::load_unaligned(fields[f] + at - 1);
        out[f] = xsimd::select(even_lanes(), right - here, here - left);
        out[2 + f] =
            Floats::load_aligned(fields[f] + bottom) - Floats::load_aligned(fields[f] + top);
      }
    } else if (!planes_.divides) {
      out[0] = Floats(planes_.s.dx);
      out[1] = Floats(planes_.t.dx);
      out[2] = Floats(planes_.s.dy);
      out[3] = Floats(planes_.t.dy);
    } else {
      const Floats s = Floats::load_aligned(s_ + kPad + at);
      const Floats t = Floats::load_aligned(t_ + kPad + at);
      const Floats r = Floats::load_aligned(r_ + at);
      out[0] = (Floats(planes_.s.dx) - s * Floats(planes_.q.dx)) * r;
      out[1] = (Floats(planes_.t.dx) - t * Floats(planes_.q.dx)) * r;
      out[2] = (Floats(planes_.s.dy) - s * Floats(planes_.q.dy)) * r;
      out[3] = (Floats(planes_.t.dy) - t * Floats(planes_.q.dy)) * r;
    }
    out[0].store_aligned(dsdx_ + at);
    out[1].store_aligned(dtdx_ + at);
    out[2].store_aligned(dsdy_ + at);
    out[3].store_aligned(dtdy_ + at);
  }

  // Lanes at even columns (kLanes is even, so a batch starts at an even column).
  static xsimd::batch_bool<float, Arch> even_lanes() {
    alignas(64) static constexpr float kParity[8] = {0, 1, 0, 1, 0, 1, 0, 1};
    return Floats::load_aligned(kParity) == Floats(0.0f);
  }

  detail::TexturePlanes planes_{};
  TextureDerivatives derivatives_ = TextureDerivatives::quad;
  alignas(64) float s_[kPixels + 2 * kPad];
  alignas(64) float t_[kPixels + 2 * kPad];
  alignas(64) float r_[kPixels];
  alignas(64) float dsdx_[kPixels], dtdx_[kPixels], dsdy_[kPixels], dtdy_[kPixels];
  alignas(64) float texels_[4][kPixels];
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
