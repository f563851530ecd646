// The texturing part of shading: a textured tile's depth test comes first, so that only rows with
// pixels to write are textured; their texels are then filtered a tile at a time
// (texture_tile-inl.hpp), or given one colour or one texel where the error budget allows, and
// multiply the shaded colour.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "shade_batch.hpp"
#include "shading_budget.hpp"
#include "texture_planes.hpp"
#include "../../simd/simd_ops-inl.hpp"
#include "shade_budget-inl.hpp"
#include "shade_colour-inl.hpp"
#include "shade_depth-inl.hpp"
#include "texture_tile-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class TexturedShading {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Mask = xsimd::batch_bool<float, Arch>;
  static constexpr std::size_t kParts = kTileSize / Floats::size;
  using Columns = TileColumnTerms<Arch>;

  explicit TexturedShading(const detail::ShadeBatch& batch) : batch_(batch) {}

  // The triangle's texture planes from its vertices' positions, texture coordinates and w.
  void begin_triangle(const Vec2 (&p)[3], const Vec2 (&uv)[3], const double (&w)[3]) {
    planes_ = detail::make_texture_planes(p, uv, w, batch_.perspective);
    tile_.begin_triangle(planes_, batch_.derivatives);
  }

  const detail::TexturePlanes& planes() const { return planes_; }
  TextureTile<Arch>& tile() { return tile_; }

  // A textured tile's covered rows `rows` of `mask`: the depth test, then the texels of the rows
  // with pixels to write, then the colour.
  [[gnu::always_inline]] void shade_rows(DepthStage<Arch>& depth_stage,
                                         const ColourSource<Arch>& colour,
                                         ShadingBudget<Arch>& budget, std::uint64_t mask,
                                         std::uint32_t rows, float* depth, std::uint32_t* color,
                                         std::int32_t px, std::int32_t py, const Columns& columns,
                                         const float (*colour_row_bases)[kTileSize],
                                         Floats& stored_max) {
    Mask writes[kTileSize][kParts];
    const std::uint32_t written_rows =
        depth_test_rows(depth_stage, mask, rows, depth, py, columns, stored_max, writes);
    if (written_rows != 0 && budget.constant()) {
      return budget.write_constant_rows(written_rows, color, writes, budget.constant_colour());
    }
    if (written_rows != 0) {
      const int first_row = std::countr_zero(written_rows);
      const int last_row = 31 - std::countl_zero(written_rows);
      tile_.query_rows(px, py, first_row, last_row);
      detail::TileTexture choice;
      if (budget.tile_choices()) {
        choice = detail::measured_texture_tile(budget.interval(),
                                               tile_.measure(written_rows, writes), batch_);
      }
      if (choice.colour) {
        return budget.write_constant_rows(written_rows, color, writes, *choice.colour);
      }
      if (choice.one_texel) {
        tile_.fill_rows(choice.texel, first_row, last_row);
        one_texel_fragments_ += written_fragments(written_rows, writes);
      } else {
        tile_.filter_rows(batch_, first_row, last_row);
      }
    }
    write_rows(colour, written_rows, color, px, py, columns, colour_row_bases, writes);
  }

  void add_counts(detail::ShadeCounts& counts) const { counts.one_texel += one_texel_fragments_; }

 private:
  // The depth pass: `writes` gets the lanes to write of each covered row; returns the rows with
  // any such lane (bit `row` for row `row`).
  [[gnu::always_inline]] static std::uint32_t depth_test_rows(
      DepthStage<Arch>& depth_stage, std::uint64_t mask, std::uint32_t rows, float* depth,
      std::int32_t py, const Columns& columns, Floats& stored_max, Mask (*writes)[kParts]) {
    std::uint32_t written_rows = 0;
    for (; rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      const std::uint32_t row_mask = static_cast<std::uint32_t>(mask >> (8 * row)) & 0xFF;
      const Floats row_base(detail::depth_row_base(depth_stage.plane(), py + row));
      std::uint32_t any = 0;
      for (std::size_t h = 0; h < kParts; ++h) {
        writes[row][h] = depth_stage.step_any_test(depth, row, h, row_base, columns.depth[h],
                                                   row_mask, stored_max);
        any |= bits_of_lanes<Arch>(writes[row][h]);
      }
      if (any != 0) written_rows |= 1u << row;
    }
    return written_rows;
  }

  // The colour pass: shaded colour times the sampled texel, written under `writes` in the rows
  // of `written_rows`.
  [[gnu::always_inline]] void write_rows(const ColourSource<Arch>& colour,
                                         std::uint32_t written_rows, std::uint32_t* color,
                                         std::int32_t px, std::int32_t py, const Columns& columns,
                                         const float (*colour_row_bases)[kTileSize],
                                         const Mask (*writes)[kParts]) const {
    for (; written_rows != 0; written_rows &= written_rows - 1) {
      const int row = std::countr_zero(written_rows);
      for (std::size_t h = 0; h < kParts; ++h) {
        Floats channel[4];
        colour.channels(colour_row_bases, columns, px, py, row, h, channel);
        for (int k = 0; k < 4; ++k)
          channel[k] = channel[k] * tile_.texel(k, row, h);
        write_colour<Arch>(color, row, h, writes[row][h], pack_rgba8_lanes<Arch>(channel));
      }
    }
  }

  // The lanes of `writes` in the rows of `written_rows`.
  [[gnu::always_inline]] static std::uint64_t written_fragments(std::uint32_t written_rows,
                                                                const Mask (*writes)[kParts]) {
    std::uint64_t written = 0;
    for (; written_rows != 0; written_rows &= written_rows - 1) {
      const int row = std::countr_zero(written_rows);
      for (std::size_t h = 0; h < kParts; ++h)
        written += static_cast<std::uint64_t>(std::popcount(bits_of_lanes<Arch>(writes[row][h])));
    }
    return written;
  }

  const detail::ShadeBatch& batch_;
  TextureTile<Arch> tile_;
  detail::TexturePlanes planes_{};
  std::uint64_t one_texel_fragments_ = 0;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
