// The depth part of shading: the depth plane's value per batch of lanes (the shared formula of
// kernels/draw/shading/depth_plane.hpp, the same float operations as the reference, so outcomes
// match it exactly), the depth test and its writes, and each tile's depth bound, by which
// hierarchical depth skips a tile whole.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <span>
#include <type_traits>

#include <xsimd/xsimd.hpp>

#include "depth_plane.hpp"
#include "shade_batch.hpp"
#include "../../simd/simd_ops-inl.hpp"
#include "../../interpolation/interpolation-inl.hpp"
#include "../../coverage/multisample_walk-inl.hpp"
#include "../../coverage/tile_masks-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// f(std::integral_constant<DepthTest, test>) for `test`: the one place a test chosen at run time
// becomes a template argument.
template <class F>
[[gnu::always_inline]] inline decltype(auto) with_depth_test(DepthTest test, F&& f) {
  switch (test) {
    case DepthTest::less:
      return f(std::integral_constant<DepthTest, DepthTest::less>{});
    case DepthTest::less_equal:
      return f(std::integral_constant<DepthTest, DepthTest::less_equal>{});
    case DepthTest::greater:
      return f(std::integral_constant<DepthTest, DepthTest::greater>{});
    case DepthTest::always:
      return f(std::integral_constant<DepthTest, DepthTest::always>{});
    case DepthTest::never:
      break;
  }
  return f(std::integral_constant<DepthTest, DepthTest::never>{});
}

template <class F>
[[gnu::always_inline]] inline F clamp01(F z) {
  return xsimd::min(xsimd::max(z, F(0.0f)), F(1.0f));
}

// The lanes where a fragment at depth z passes the test against the stored depth.
template <DepthTest Test, class F>
[[gnu::always_inline]] inline typename F::batch_bool_type passes(F z, F stored) {
  using Bools = typename F::batch_bool_type;
  if constexpr (Test == DepthTest::less) return z < stored;
  if constexpr (Test == DepthTest::less_equal) return z <= stored;
  if constexpr (Test == DepthTest::greater) return z > stored;
  if constexpr (Test == DepthTest::always) return Bools(true);
  return Bools(false);
}

// One triangle's depth at a time: its plane, its test and writes, and the tiles' bounds.
template <class Arch>
class DepthStage {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Mask = xsimd::batch_bool<float, Arch>;
  static constexpr std::size_t kLanes = Floats::size;
  static constexpr std::size_t kParts = kTileSize / kLanes;

  explicit DepthStage(const detail::ShadeBatch& batch)
      : batch_(batch),
        keep_bounds_(batch.tile_max_depth != nullptr && batch.depth_write),
        reject_hidden_(
            batch.tile_max_depth != nullptr && batch.hierarchical_depth &&
            (batch.depth_test == DepthTest::less || batch.depth_test == DepthTest::less_equal)),
        sample_reach_(sample_reach(batch.coverage.samples)) {}

  void begin_triangle(const detail::DepthPlane& plane, float max_vertex_depth) {
    plane_ = plane;
    max_vertex_depth_ = max_vertex_depth;
  }

  const detail::DepthPlane& plane() const { return plane_; }
  bool keeps_bounds() const { return keep_bounds_; }

  // f(std::integral_constant<DepthTest, test>) for the batch's test.
  template <class F>
  [[gnu::always_inline]] decltype(auto) with_test(F&& f) const {
    return with_depth_test(batch_.depth_test, static_cast<F&&>(f));
  }

  // The dx terms of the depth formula for the tile columns from pixel column px, per batch of
  // lanes, and the exact dx they take (which the colour planes share).
  [[gnu::always_inline]] Floats column_dx(std::int32_t px, std::size_t h) const {
    return interpolation_detail::lane_centers<Arch>(px + static_cast<std::int32_t>(h * kLanes)) -
           Floats(plane_.x0);
  }

  // Whether hierarchical depth rejects the tile at (px, py) whole, counted when it does. A tile
  // whose bound lies above every vertex depth holds a stored depth the triangle beats (hidden()
  // could only succeed within its rounding margin of the vertices' largest depth, and not
  // skipping a tile is always correct): the cheap comparison spares most tiles the test.
  [[gnu::always_inline]] bool skips_hidden_tile(std::size_t tile_index, std::int32_t px,
                                                std::int32_t py) {
    if (reject_hidden_ && !(batch_.tile_max_depth[tile_index] > max_vertex_depth_) &&
        hidden(batch_.tile_max_depth[tile_index], px, py)) {
      ++tiles_skipped_;
      return true;
    }
    return false;
  }

  // The depth test of lanes h of `row`, the depth written where it passes; returns the lanes
  // to write.
  template <DepthTest Test>
  [[gnu::always_inline]] Mask step(float* depth, int row, std::size_t h, Floats row_base,
                                   Floats depth_column, std::uint32_t row_mask,
                                   Floats& stored_max) {
    const std::size_t offset = static_cast<std::size_t>(row) * kTileSize + h * kLanes;
    const Floats z = clamp01(row_base + depth_column);
    const Floats stored = Floats::load_aligned(depth + offset);
    const Mask write = lanes_of_bits<Arch>(row_mask >> (h * kLanes)) && passes<Test>(z, stored);
    if (batch_.depth_write) {
      const Floats updated = xsimd::select(write, z, stored);
      updated.store_aligned(depth + offset);
      stored_max = xsimd::max(stored_max, updated);
    }
    passed_ += static_cast<std::uint64_t>(std::popcount(bits_of_lanes<Arch>(write)));
    return write;
  }

  // step() with the test chosen per call.
  [[gnu::always_inline]] Mask step_any_test(float* depth, int row, std::size_t h, Floats row_base,
                                            Floats depth_column, std::uint32_t row_mask,
                                            Floats& stored_max) {
    return with_test([&](auto test) {
      return step<decltype(test)::value>(depth, row, h, row_base, depth_column, row_mask,
                                         stored_max);
    });
  }

  // A row without covered samples: its stored depths still count towards the tile's bound.
  [[gnu::always_inline]] static void keep_row_bound(const float* depth, int row,
                                                    Floats& stored_max) {
    for (std::size_t h = 0; h < kParts; ++h) {
      stored_max = xsimd::max(
          stored_max,
          Floats::load_aligned(depth + static_cast<std::size_t>(row) * kTileSize + h * kLanes));
    }
  }

  // The tile's largest depth, over all 64 values after the writes, as its new bound:
  // `stored_max` holds the largest of the covered rows `rows`; the others kept their depths.
  [[gnu::always_inline]] void tighten_bound(std::size_t tile_index, const float* depth,
                                            std::uint32_t rows, Floats stored_max) const {
    for (std::uint32_t other = ~rows & 0xFFu; other != 0; other &= other - 1)
      keep_row_bound(depth, std::countr_zero(other), stored_max);
    set_bound(tile_index, stored_max);
  }

  // The tile's bound: the largest lane of `stored_max`.
  void set_bound(std::size_t tile_index, Floats stored_max) const {
    batch_.tile_max_depth[tile_index] = lane_max<Arch>(stored_max);
  }

  // Samples that passed, counted by the loops that keep their own count.
  void add_passed(std::uint64_t passed) { passed_ += passed; }

  void add_counts(detail::ShadeCounts& counts) const {
    counts.tiles_skipped += tiles_skipped_;
    counts.passed += passed_;
  }

 private:
  // Whether the depth test fails at every sample of the tile at (px, py). The samples lie in the
  // rectangle from the first pixel centre moved by the pattern's least offsets to the last one
  // moved by its largest (the centres alone with one sample), and the plane's exact value over
  // it is smallest at the corner its slopes point away from. Each computed depth
  // (depth_plane.hpp: three roundings) lies within 3 u M of the exact plane, u = 2^-24,
  // M = |z0| + |dzdy| max|dy| + |dzdx| max|dx| over the rectangle; `corner` (the computed row base
  // plus the rounded dx term, summed exactly) is within u M of the computed corner depth. So
  // every computed depth in the tile is at least corner - 7 u M; clamping to [0, 1] keeps the
  // order. The margin below is 8 u M: M is itself computed from float differences (the reaches,
  // each within a factor 1 +- u of the exact one), so the computed 7 u M could fall short of the
  // exact one by about 7 u^2 M; the extra u M covers that many times over. A NaN bound compares
  // false: such a tile is never skipped.
  bool hidden(float bound, std::int32_t px, std::int32_t py) const {
    const SampleReach& r = sample_reach_;
    // The pattern's reach in sixteenths of a pixel, as the depth formula takes offsets (16
    // fixed-point units each), and in pixels.
    const auto sixteenths = [](std::int32_t fixed) { return fixed / 16; };
    const auto px_of = [&](std::int32_t fixed) { return detail::sixteenths(sixteenths(fixed)); };
    const bool low_x = plane_.dzdx >= 0.0f, low_y = plane_.dzdy >= 0.0f;
    const std::int32_t cx = low_x ? px : px + kTileSize - 1;
    const std::int32_t cy = low_y ? py : py + kTileSize - 1;
    const float corner_dx =
        ((static_cast<float>(cx) + 0.5f) + px_of(low_x ? r.x_min : r.x_max)) - plane_.x0;
    const double corner = static_cast<double>(detail::depth_row_base(
                              plane_, cy, sixteenths(low_y ? r.y_min : r.y_max))) +
                          plane_.dzdx * corner_dx;
    // Plain comparisons rather than std::fmax/fmin, which compile to library calls; they give
    // the same values here (the reaches are finite, and a NaN corner becomes 0 either way).
    const double reach_x =
        larger(std::fabs(((static_cast<float>(px) + 0.5f) + px_of(r.x_min)) - plane_.x0),
               std::fabs(((static_cast<float>(px) + 7.5f) + px_of(r.x_max)) - plane_.x0));
    const double reach_y =
        larger(std::fabs(((static_cast<float>(py) + 0.5f) + px_of(r.y_min)) - plane_.y0),
               std::fabs(((static_cast<float>(py) + 7.5f) + px_of(r.y_max)) - plane_.y0));
    const double margin = 8.0 * 0x1p-24 *
                          (std::fabs(plane_.z0) + std::fabs(plane_.dzdy) * reach_y +
                           std::fabs(plane_.dzdx) * reach_x);
    const double above_zero = corner - margin > 0.0 ? corner - margin : 0.0;
    const double lowest = above_zero < 1.0 ? above_zero : 1.0;
    return batch_.depth_test == DepthTest::less ? lowest >= bound : lowest > bound;
  }

  static double larger(double a, double b) { return a > b ? a : b; }

  const detail::ShadeBatch& batch_;
  const bool keep_bounds_, reject_hidden_;
  // The target's sample pattern's reach (multisample_walk-inl.hpp): hidden() looks at every sample.
  const SampleReach sample_reach_;
  detail::DepthPlane plane_{};
  float max_vertex_depth_ = 0.0f;
  std::uint64_t tiles_skipped_ = 0;
  std::uint64_t passed_ = 0;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
