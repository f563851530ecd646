// The error budget's part of shading (DrawOptions::error_budget,
// kernels/draw/shading/shading_budget.hpp): per triangle, whether one colour is within the budget
// everywhere on it, and for a textured triangle whether each tile is to be decided by its measured
// texture queries.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <optional>

#include <xsimd/xsimd.hpp>

#include "shade_batch.hpp"
#include "shading_budget.hpp"
#include "texture_planes.hpp"
#include "../../simd/simd_ops-inl.hpp"
#include "budget_prefilter-inl.hpp"
#include "plane_setup-inl.hpp"
#include "shade_colour-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class ShadingBudget {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  using Mask = xsimd::batch_bool<float, Arch>;
  static constexpr std::size_t kParts = kTileSize / Floats::size;

  explicit ShadingBudget(const detail::ShadeBatch& batch)
      : batch_(batch), active_(detail::budget_shades(batch)) {}

  // The budget bounds this batch's shading.
  bool active() const { return active_; }
  // The triangle is drawn in one colour, constant_colour().
  bool constant() const { return constant_; }
  std::uint32_t constant_colour() const { return constant_colour_; }
  // Textured: each tile is decided by its measured queries (measured_texture_tile()).
  bool tile_choices() const { return tile_choices_; }
  const detail::ShadeInterval& interval() const { return shade_interval_; }

  // An untextured group's lanes whose vertices already rule one colour out (`in`: the group's
  // planes' inputs, colours included).
  void mark_group(const PlaneGroupInput<Arch>& in, bool diffuse) {
    mark_beyond_budget(in, diffuse, batch_.light, batch_.ambient,
                       detail::untextured_width_limit(batch_.budget_codes), beyond_budget_);
  }
  // Whether lane l of the group is to be looked at closer (choose() from its vertices).
  bool looks_at(std::size_t l) const { return active_ && !beyond_budget_[l]; }

  void begin_triangle() { constant_ = tile_choices_ = false; }

  // The choice for a triangle from its vertices: its shade interval, and one colour for it when
  // untextured and within the budget (`planes`: its texture's, when textured).
  void choose(const Vec2 (&p)[3], const ScreenTriangle& screen, const Vec4* colours,
              const Vec3* normals, const detail::TexturePlanes* planes) {
    detail::BudgetTriangle triangle;
    for (int i = 0; i < 3; ++i) {
      triangle.position[i] = p[i];
      triangle.w[i] = screen.w[i];
      triangle.colour[i] = colours[i];
      triangle.normal[i] = normals[i];
    }
    shade_interval_ = detail::shade_interval(triangle, batch_);
    std::optional<std::uint32_t> colour;
    tile_choices_ = false;
    if (planes == nullptr) {
      colour = detail::constant_colour(shade_interval_, batch_.budget_codes);
    } else {
      const detail::TexturePlan plan = detail::texture_plan(shade_interval_, *planes, batch_, p);
      colour = plan.colour;
      tile_choices_ = plan.tiles;
    }
    constant_ = colour.has_value();
    constant_colour_ = colour.value_or(0u);
  }

  // A tile (or a tile's lanes) the budget gives one colour: `constant` written under `writes` in
  // the rows of `written_rows`.
  [[gnu::always_inline]] void write_constant_rows(std::uint32_t written_rows, std::uint32_t* color,
                                                  const Mask (*writes)[kParts],
                                                  std::uint32_t constant) {
    const Ints packed(static_cast<std::int32_t>(constant));
    std::uint64_t written = 0;
    for (; written_rows != 0; written_rows &= written_rows - 1) {
      const int row = std::countr_zero(written_rows);
      for (std::size_t h = 0; h < kParts; ++h) {
        write_colour<Arch>(color, row, h, writes[row][h], packed);
        written += static_cast<std::uint64_t>(std::popcount(bits_of_lanes<Arch>(writes[row][h])));
      }
    }
    constant_fragments_ += written;
  }

  // Lanes h of `row` written in the triangle's constant colour.
  [[gnu::always_inline]] void write_constant(std::uint32_t* color, int row, std::size_t h,
                                             Mask write) {
    write_colour<Arch>(color, row, h, write, Ints(static_cast<std::int32_t>(constant_colour_)));
    constant_fragments_ += static_cast<std::uint64_t>(std::popcount(bits_of_lanes<Arch>(write)));
  }

  void add_counts(detail::ShadeCounts& counts) const { counts.constant += constant_fragments_; }

 private:
  const detail::ShadeBatch& batch_;
  const bool active_;
  detail::ShadeInterval shade_interval_{};
  bool constant_ = false;
  bool tile_choices_ = false;
  std::uint32_t constant_colour_ = 0;
  bool beyond_budget_[kSetupLanes<Arch>]{};  // of the current group (mark_beyond_budget())
  std::uint64_t constant_fragments_ = 0;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
