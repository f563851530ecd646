// The multisample part of shading: the walks deliver every sample's masks of a tile
// (walk_multisample_tiles), and sample k of the tile is the 64 values from (tile * samples + k) *
// 64 (framebuffer.hpp). Each covered sample's depth is tested, and written, at its own position;
// each pixel with a covered sample is shaded once, at its centre, and that colour written to the
// samples that passed.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>

#include <xsimd/xsimd.hpp>

#include "depth_plane.hpp"
#include "../../simd/simd_ops-inl.hpp"
#include "shade-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class MultisampleShadingVisitor : public ShadingVisitor<Arch> {
  using Base = ShadingVisitor<Arch>;
  using typename Base::Floats;
  using typename Base::Ints;
  using typename Base::Mask;
  using Columns = TileColumnTerms<Arch>;
  static constexpr std::size_t kLanes = Floats::size;
  static constexpr std::size_t kParts = kTileSize / kLanes;

 public:
  static constexpr bool kMultisample = true;

  explicit MultisampleShadingVisitor(const detail::ShadeBatch& batch) : Base(batch) {
    const std::span<const SampleOffset> pattern = batch.coverage.samples;
    for (std::size_t k = 0; k < pattern.size() && k < kMaxSamples; ++k) {
      sample_dx_[k] = detail::sixteenths(pattern[k].x);
      sample_dy_[k] = detail::sixteenths(pattern[k].y);
    }
  }

  void begin_triangle(std::uint32_t t, std::size_t l) {
    Base::begin_triangle(t, l);
    sample_rows_tile_y_ = kNoTileRow;
  }

  void multisample_tile(std::uint32_t tile_x, std::uint32_t tile_y,
                        std::span<const std::uint64_t> masks) {
    const std::size_t samples = masks.size();
    const std::size_t tile_index =
        static_cast<std::size_t>(tile_y) * static_cast<std::size_t>(this->batch_.tiles_x) + tile_x;
    float* depth = this->batch_.depth_tiles + tile_index * samples * 64;
    std::uint32_t* color = this->batch_.color_tiles + tile_index * samples * 64;
    const std::int32_t px = static_cast<std::int32_t>(tile_x) * kTileSize;
    const std::int32_t py = static_cast<std::int32_t>(tile_y) * kTileSize;
    std::uint64_t covered = 0, fragments = 0;
    for (std::uint64_t mask : masks) {
      fragments += static_cast<std::uint64_t>(std::popcount(mask));
      covered |= mask;
    }
    this->fragments_ += fragments;
    if (this->depth_.skips_hidden_tile(tile_index, px, py)) return;
    Columns columns;
    this->set_up_tile_columns(px, columns);
    if (this->colour_.planar()) this->colour_.set_up_tile_row(this->depth_.plane().y0, py, tile_y);
    const float(*row_bases)[kTileSize] = this->colour_.row_bases();
    SampleDepthTerms terms;
    set_up_sample_depth(px, samples, terms);
    if (tile_y != sample_rows_tile_y_) {
      set_up_sample_rows(py, samples);
      sample_rows_tile_y_ = tile_y;
    }
    std::uint64_t tile_passed = 0;
    if (this->textured_) {
      tile_passed = shade_textured_samples(masks, depth, color, px, py, columns, row_bases, terms);
    } else {
      // Inlined: as a call, its captures go through memory for every tile.
      this->depth_.with_test([&](auto test) EDGEWISE_INLINE_LAMBDA {
        constexpr DepthTest kTest = decltype(test)::value;
        tile_passed = this->batch_.depth_write
                          ? shade_samples<kTest, true>(masks, covered, depth, color, px, py,
                                                       columns, row_bases, terms)
                          : shade_samples<kTest, false>(masks, covered, depth, color, px, py,
                                                        columns, row_bases, terms);
      });
    }
    this->depth_.add_passed(tile_passed);
    keep_sample_bound(tile_index, samples, depth, tile_passed);
  }

 private:
  // Each sample's dx terms of the depth formula over a tile column, per batch of lanes (its row
  // terms are sample_row_base_): depth_at() with the sample's offset, the same float operations.
  struct SampleDepthTerms {
    Floats column[kMaxSamples][kParts];
  };

  [[gnu::always_inline]] void set_up_sample_depth(std::int32_t px, std::size_t samples,
                                                  SampleDepthTerms& terms) const {
    const detail::DepthPlane& plane = this->depth_.plane();
    for (std::size_t h = 0; h < kParts; ++h) {
      const Floats centre_x =
          interpolation_detail::lane_centers<Arch>(px + static_cast<std::int32_t>(h * kLanes));
      for (std::size_t k = 0; k < samples; ++k)
        terms.column[k][h] =
            Floats(plane.dzdx) * ((centre_x + Floats(sample_dx_[k])) - Floats(plane.x0));
    }
  }

  // Each sample's row terms of the depth formula for the tile row from pixel row py.
  [[gnu::always_inline]] void set_up_sample_rows(std::int32_t py, std::size_t samples) {
    const detail::DepthPlane& plane = this->depth_.plane();
    for (std::size_t h = 0; h < kParts; ++h) {
      const auto first = static_cast<std::int32_t>(h * kLanes);
      const Floats centre_y = interpolation_detail::lane_centers<Arch>(py + first);
      for (std::size_t k = 0; k < samples; ++k) {
        const Floats dy = (centre_y + Floats(sample_dy_[k])) - Floats(plane.y0);
        (Floats(plane.z0) + Floats(plane.dzdy) * dy).store_aligned(sample_row_base_[k] + first);
      }
    }
  }

  // The tile's bound anew from every sample's depth where the writes may have raised it (tests
  // other than less and less_equal), or where they replaced every sample (a tile the triangle
  // covers whole): then the lower bound lets hierarchical depth skip the tile for the triangles
  // behind. Elsewhere the old bound stays an upper bound, looser (as the 1x path leaves it for
  // small triangles): the recount would cost more than the depth test itself.
  void keep_sample_bound(std::size_t tile_index, std::size_t samples, const float* depth,
                         std::uint64_t tile_passed) const {
    const DepthTest test = this->batch_.depth_test;
    const bool may_raise = test != DepthTest::less && test != DepthTest::less_equal;
    if (!this->depth_.keeps_bounds() || tile_passed == 0 ||
        !(may_raise || tile_passed == 64 * samples)) {
      return;
    }
    Floats stored_max(-std::numeric_limits<float>::infinity());
    for (std::size_t k = 0; k < samples; ++k) {
      for (int row = 0; row < kTileSize; ++row)
        DepthStage<Arch>::keep_row_bound(depth + k * 64, row, stored_max);
    }
    this->depth_.set_bound(tile_index, stored_max);
  }

  // Untextured multisampled tiles in one pass over the covered rows: per batch of lanes, the
  // colour at the pixel centres, then per sample with covered lanes the depth test and the
  // writes. Returns the samples that passed.
  template <DepthTest Test, bool WriteDepth>
  [[gnu::always_inline]] std::uint64_t shade_samples(std::span<const std::uint64_t> masks,
                                                     std::uint64_t covered, float* depth,
                                                     std::uint32_t* color, std::int32_t px,
                                                     std::int32_t py, const Columns& columns,
                                                     const float (*row_bases)[kTileSize],
                                                     const SampleDepthTerms& terms) {
    const std::size_t samples = masks.size();
    constexpr std::uint32_t kLaneBits = (1u << kLanes) - 1;
    Floats passed(0.0f);  // per lane, the samples that passed (exact: at most 128 per tile)
    for (std::uint32_t rows = covered_rows(covered); rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      for (std::size_t h = 0; h < kParts; ++h) {
        const std::size_t at = static_cast<std::size_t>(row) * kTileSize + h * kLanes;
        Floats channel[4];
        this->colour_.channels(row_bases, columns, px, py, row, h, channel);
        const Ints packed = pack_rgba8_lanes<Arch>(channel);
        for (std::size_t k = 0; k < samples; ++k) {
          const std::uint32_t lanes = static_cast<std::uint32_t>(masks[k] >> at) & kLaneBits;
          if (lanes == 0) continue;
          float* sample_depth = depth + k * 64;
          const Floats z = clamp01(Floats(sample_row_base_[k][row]) + terms.column[k][h]);
          const Floats stored = Floats::load_aligned(sample_depth + at);
          const Mask write = lanes_of_bits<Arch>(lanes) && passes<Test>(z, stored);
          if constexpr (WriteDepth)
            xsimd::select(write, z, stored).store_aligned(sample_depth + at);
          write_colour<Arch>(color + k * 64, row, h, write, packed);
          passed += xsimd::select(write, Floats(1.0f), Floats(0.0f));
        }
      }
    }
    return static_cast<std::uint64_t>(xsimd::hadd(passed));  // exact: at most 1024
  }

  // Textured multisampled tiles: every sample's depth test first, then the texels of the rows
  // with a sample that passed, and the colour written to those samples. Returns the samples
  // that passed.
  std::uint64_t shade_textured_samples(std::span<const std::uint64_t> masks, float* depth,
                                       std::uint32_t* color, std::int32_t px, std::int32_t py,
                                       const Columns& columns, const float (*row_bases)[kTileSize],
                                       const SampleDepthTerms& terms) {
    const std::size_t samples = masks.size();
    // Per sample, the rows with a sample that passed (bit `row`) and each row's lanes to write.
    std::uint32_t passed_rows[kMaxSamples];
    Mask writes[kMaxSamples][kTileSize][kParts];
    std::uint32_t written_rows = 0;
    std::uint64_t tile_passed = 0;
    this->depth_.with_test([&](auto test) {
      for (std::size_t k = 0; k < samples; ++k) {
        const std::uint64_t passed = sample_depth_test<decltype(test)::value>(
            masks[k], depth + k * 64, terms, k, writes[k], passed_rows[k]);
        tile_passed += static_cast<std::uint64_t>(std::popcount(passed));
        written_rows |= passed_rows[k];
      }
    });
    if (written_rows == 0) return 0;
    TextureTile<Arch>& texture = this->texture_.tile();
    texture.sample_rows(this->batch_, px, py, std::countr_zero(written_rows),
                        31 - std::countl_zero(written_rows));
    for (std::uint32_t rows = written_rows; rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      for (std::size_t h = 0; h < kParts; ++h) {
        Floats channel[4];
        this->colour_.channels(row_bases, columns, px, py, row, h, channel);
        for (int k = 0; k < 4; ++k)
          channel[k] = channel[k] * texture.texel(k, row, h);
        const Ints packed = pack_rgba8_lanes<Arch>(channel);
        for (std::size_t k = 0; k < samples; ++k) {
          if ((passed_rows[k] >> row) & 1u)
            write_colour<Arch>(color + k * 64, row, h, writes[k][row][h], packed);
        }
      }
    }
    return tile_passed;
  }

  // One sample's depth test over a tile (`depth` its plane of the tile), the depth written where
  // it passes. Fills `writes` for the rows of `passed_rows` (the rows where some lane passed) and
  // returns the samples that passed (bit y * 8 + x).
  template <DepthTest Test>
  [[gnu::always_inline]] std::uint64_t sample_depth_test(std::uint64_t mask, float* depth,
                                                         const SampleDepthTerms& terms,
                                                         std::size_t k, Mask (*writes)[kParts],
                                                         std::uint32_t& passed_rows) {
    std::uint64_t passed = 0;
    for (std::uint32_t rows = covered_rows(mask); rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      const std::uint32_t row_mask = static_cast<std::uint32_t>(mask >> (8 * row)) & 0xFF;
      const Floats base(sample_row_base_[k][row]);
      for (std::size_t h = 0; h < kParts; ++h) {
        const std::size_t at = static_cast<std::size_t>(row) * kTileSize + h * kLanes;
        const Floats z = clamp01(base + terms.column[k][h]);
        const Floats stored = Floats::load_aligned(depth + at);
        const Mask write = lanes_of_bits<Arch>(row_mask >> (h * kLanes)) && passes<Test>(z, stored);
        if (this->batch_.depth_write) xsimd::select(write, z, stored).store_aligned(depth + at);
        writes[row][h] = write;
        passed |= std::uint64_t{bits_of_lanes<Arch>(write)} << at;
      }
    }
    passed_rows = covered_rows(passed);
    return passed;
  }

  static constexpr std::uint32_t kNoTileRow = UINT32_MAX;
  float sample_dx_[kMaxSamples]{}, sample_dy_[kMaxSamples]{};  // the pattern's offsets in pixels
  // Each sample's depth row terms for the tile row sample_rows_tile_y_ (set_up_sample_rows()).
  std::uint32_t sample_rows_tile_y_ = kNoTileRow;
  alignas(64) float sample_row_base_[kMaxSamples][kTileSize];
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
