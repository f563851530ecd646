// Occluders drawn into depth kept as planes (plane_tiles.hpp): depth test less with writes, no
// colour. A tile the triangle lies wholly in front of, over the pixels it covers, takes the
// triangle's plane for those pixels (masks and one plane written, no depth computed); one it lies
// wholly behind is left; any other is worked out to 64 values and tested per pixel as draw()
// tests it. Either way every pixel ends with the depth draw() would leave there. On a reduced
// buffer (docs/design/occlusion.md, "Reduced resolution") the pixels are blocks of the view's
// samples, each drawn with its largest depth (block_depth_plane()), and blocks covered in part
// may be merged into a layer per block (partial_block()).
//
// "Wholly in front" is decided from bounds on the depths the triangle's covered pixels compute,
// from its vertex depths: every covered sample lies in the closed triangle, where the plane
// through the vertices lies between their least and largest depth. The computed depth differs
// from that plane by (a) the slopes' rounding to float, at most u (|dzdx| |dx| + |dzdy| |dy|)
// plus the double set-up's 2^-52 relative (u = 2^-24), and (b) the formula's three roundings,
// at most 3 u M (shade_depth-inl.hpp's hidden()), M = |z0| + |dzdy| max|dy| + |dzdx| max|dx|,
// where max|dx|, max|dy| over the triangle are the vertices' largest offsets from vertex 0. So
// every covered pixel's computed depth lies within 4.01 u M of [least, largest]; the bounds below
// widen by 8 u M, which also covers M's computation in double, and are rounded to float away
// from the range. Clamping to [0, 1] keeps the order.
#pragma once

#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "plane_setup-inl.hpp"
#include "plane_tile_depths-inl.hpp"
#include "shade_batch.hpp"
#include "../../coverage/block_setup-inl.hpp"
#include "../../coverage/tile_masks-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class OccluderVisitor {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using Mask = xsimd::batch_bool<float, Arch>;
  static constexpr std::size_t kLanes = Floats::size;
  static constexpr std::size_t kParts = kTileSize / kLanes;
  static constexpr std::size_t kGroupLanes = kSetupLanes<Arch>;

  explicit OccluderVisitor(const detail::ShadeBatch& batch)
      : batch_(batch),
        tiles_(batch.plane_tiles.tiles),
        slots_(batch.plane_tiles.slots),
        planes_(batch.plane_tiles.planes),
        first_plane_(batch.plane_tiles.first_plane),
        reduction_(batch.plane_tiles.reduction),
        layers_(batch.plane_tiles.layers),
        all_samples_((1u << (reduction_ * reduction_)) - 1u) {
    for (std::int32_t sample = 0; sample < kMaxReduction * kMaxReduction; ++sample) {
      sample_column_[sample] = static_cast<float>(sample % reduction_);
      sample_row_[sample] = static_cast<float>(sample / reduction_);
    }
  }

  // On a reduced buffer the walk hands on blocks, each covered when all its samples are
  // (triangle_batch-inl.hpp), and each takes the largest depth of its samples.
  std::int32_t reduction() const { return reduction_; }
  bool merges_partial_blocks() const { return layers_ != nullptr; }

  // The depth planes of a group of triangles (plane_setup-inl.hpp) and their depth bounds.
  void begin_group(const GroupCorners<Arch>& corners, const TriangleGroup<Arch>& positions) {
    PlaneGroupInput<Arch> in;
    for (std::size_t l = 0; l < kGroupLanes; ++l) {
      const bool valid = corners.valid[l];  // a bad index reads nothing; the lane is not drawn
      for (int i = 0; i < 3; ++i) {
        in.x[i][l] = positions.x[i][l];
        in.y[i][l] = positions.y[i][l];
        in.z[i][l] = valid ? batch_.depth[corners.vertex[l][i]] : 0.0f;
      }
    }
    set_up_plane_group(in, /*colour_planes=*/false, /*normal_planes=*/false,
                       /*perspective_correct=*/false, group_);
    for (std::size_t l = 0; l < kGroupLanes; ++l) {
      const double reach_x =
          larger(std::fabs(in.x[1][l] - in.x[0][l]), std::fabs(in.x[2][l] - in.x[0][l]));
      const double reach_y =
          larger(std::fabs(in.y[1][l] - in.y[0][l]), std::fabs(in.y[2][l] - in.y[0][l]));
      const double margin = 8.0 * 0x1p-24 *
                            (std::fabs(group_.z0[l]) + std::fabs(group_.dzdy[l]) * reach_y +
                             std::fabs(group_.dzdx[l]) * reach_x);
      const double least = smaller(smaller(in.z[0][l], in.z[1][l]), in.z[2][l]);
      // NaN margins (infinite slopes) give NaN bounds, which decide nothing: every tile is then
      // tested per pixel.
      lowest_[l] = float_below(clamp_unit(least - margin));
      highest_[l] = float_above(clamp_unit(group_.max_depth[l] + margin));
    }
  }

  // Starts fetching what run_batch() and begin_group() will read of the vertices `corners`.
  [[gnu::always_inline]] void prefetch_vertices(const std::uint32_t* corners,
                                                std::size_t count) const {
    const std::size_t vertices = batch_.coverage.vertex_count;
    if (vertices == 0) return;
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t v = corners[i] < vertices ? corners[i] : vertices - 1;
      __builtin_prefetch(batch_.coverage.vertices + v);
      __builtin_prefetch(batch_.depth + v);
    }
  }

  // Starts fetching the tiles under the vertices `corners`, whose positions the prefetch above
  // has brought in: small triangles land anywhere, and their tiles' cache misses would otherwise
  // be most of their cost.
  [[gnu::always_inline]] void prefetch_targets(const std::uint32_t* corners,
                                               std::size_t count) const {
    const std::size_t vertices = batch_.coverage.vertex_count;
    if (vertices == 0) return;
    const PixelRect& clip = batch_.coverage.clip;
    // Inside the clip rectangle (NaN compares false: its first column or row).
    const auto inside = [](float v, std::int32_t lo, std::int32_t hi) {
      return v >= static_cast<float>(lo)
                 ? (v < static_cast<float>(hi) ? static_cast<std::int32_t>(v) : hi - 1)
                 : lo;
    };
    // A tile is 8 pixels, 8 k samples of the view: a shift, where a division by the run-time
    // side cost six integer divisions a triangle (coordinates in the clip rectangle are >= 0).
    const int tile_shift = std::countr_zero(static_cast<std::uint32_t>(kTileSize * reduction_));
    for (std::size_t i = 0; i < count; ++i) {
      const std::size_t v = corners[i] < vertices ? corners[i] : vertices - 1;
      const Vec2 p = batch_.coverage.vertices[v];
      const std::size_t index =
          static_cast<std::size_t>(inside(p.y, clip.y0, clip.y1) >> tile_shift) *
              static_cast<std::size_t>(batch_.tiles_x) +
          static_cast<std::size_t>(inside(p.x, clip.x0, clip.x1) >> tile_shift);
      __builtin_prefetch(tiles_ + index, 1);
      const float* depth = batch_.depth_tiles + index * 64;
      for (int line = 0; line < 4; ++line)
        __builtin_prefetch(depth + line * 16, 1);
    }
  }

  // Triangle t, lane l of the last begin_group(): its plane stored as plane first_plane + t.
  void begin_triangle(std::uint32_t t, std::size_t l) {
    plane_ = {group_.z0[l], group_.dzdx[l], group_.dzdy[l], group_.x0[l], group_.y0[l]};
    lowest_depth_ = lowest_[l];
    highest_depth_ = highest_[l];
    if (reduction_ > 1) {
      view_plane_ = plane_;
      view_lowest_ = lowest_depth_;
      // A block's depth is one of its samples' (covered, so within the bounds), or 1.
      plane_ = detail::block_depth_plane(plane_, reduction_, /*farthest=*/true);
      if (plane_.dzdx == 0.0f && plane_.dzdy == 0.0f && plane_.z0 == 1.0f)
        lowest_depth_ = highest_depth_ = 1.0f;
    }
    plane_index_ = first_plane_ + t;
    planes_[plane_index_] = plane_;
    whole_tile_.plane = plane_index_;
    whole_tile_.lowest = lowest_depth_;
    whole_tile_.highest = highest_depth_;
    whole_tile_.kind = detail::TileKind::plane;
    whole_tile_.unresolved = true;
  }

  void tile(std::uint32_t tile_x, std::uint32_t tile_y, std::uint64_t mask) {
    fragments_ += static_cast<std::uint64_t>(std::popcount(mask));
    update(tile_x, tile_y, mask);
  }

  // A run of tiles under one mask: most often whole, each taking the triangle's plane in one
  // store of the tile made in begin_triangle(), the counts kept in registers.
  void full_tiles(std::uint32_t begin, std::uint32_t end, std::uint32_t tile_y,
                  std::uint64_t mask) {
    fragments_ += static_cast<std::uint64_t>(std::popcount(mask)) * (end - begin);
    if (mask != kAll) {
      for (std::uint32_t tile_x = begin; tile_x < end; ++tile_x)
        update(tile_x, tile_y, mask);
      return;
    }
    detail::PlaneTile* row = tiles_ + static_cast<std::size_t>(tile_y) * batch_.tiles_x;
    const float highest = highest_depth_;
    std::uint64_t taken = 0;
    for (std::uint32_t tile_x = begin; tile_x < end; ++tile_x) {
      if (highest < row[tile_x].lowest) {
        row[tile_x] = whole_tile_;
        taken += 64;
      } else {
        update(tile_x, tile_y, kAll);
      }
    }
    passed_ += taken;
  }

  // A block of a reduced buffer that the triangle covers in part (`samples`, some of the block's):
  // merged into the block's layer at the largest depth draw() gives those samples, the block
  // falling to the layer's depth once the layer holds all its samples (block_layer_merge()).
  void partial_block(std::int32_t x, std::int32_t y, std::uint32_t samples) {
    const std::size_t index =
        static_cast<std::size_t>(y / kTileSize) * static_cast<std::size_t>(batch_.tiles_x) +
        static_cast<std::size_t>(x / kTileSize);
    detail::PlaneTile& tile = tiles_[index];
    // Behind every value of the tile: nothing to merge (block_layer_merge() would return first).
    if (view_lowest_ >= tile.highest) return;
    const int pixel = (y % kTileSize) * kTileSize + x % kTileSize;
    const float value =
        block_value(tile, slots_[index], batch_.depth_tiles + index * 64, pixel, x, y);
    const float lowered = detail::block_layer_merge(
        layers_[index * 64 + pixel], samples, farthest_sample(samples, x, y), value, all_samples_);
    if (!(lowered < value)) return;
    float* depth = batch_.depth_tiles + index * 64;
    if (tile.kind != detail::TileKind::values) {
      write_plane_tile<Arch>(tile, slots_[index], planes_, x - x % kTileSize, y - y % kTileSize,
                             depth);
      tile.kind = detail::TileKind::values;
      tile.unresolved = false;
    }
    depth[pixel] = lowered;
    if (!(lowered >= tile.lowest)) tile.lowest = lowered;
  }

  void add_counts(detail::ShadeCounts& counts) const {
    counts.fragments += fragments_;
    counts.passed += passed_;
  }

 private:
  static constexpr std::uint64_t kAll = ~std::uint64_t{0};

  // The triangle's samples `mask` (not empty) of the tile drawn.
  void update(std::uint32_t tile_x, std::uint32_t tile_y, std::uint64_t mask) {
    const std::size_t index =
        static_cast<std::size_t>(tile_y) * static_cast<std::size_t>(batch_.tiles_x) + tile_x;
    detail::PlaneTile& tile = tiles_[index];
    if (highest_depth_ < tile.lowest) {
      if (mask == kAll) {
        tile = whole_tile_;
        passed_ += 64;
        return;
      }
      if (tile.kind != detail::TileKind::values && take_pixels(tile, slots_[index], mask)) {
        passed_ += static_cast<std::uint64_t>(std::popcount(mask));
        return;
      }
    } else if (lowest_depth_ >= tile.highest) {
      return;  // behind every depth of the tile
    }
    float* depth = batch_.depth_tiles + index * 64;
    const std::int32_t px = static_cast<std::int32_t>(tile_x) * kTileSize;
    const std::int32_t py = static_cast<std::int32_t>(tile_y) * kTileSize;
    if (tile.kind != detail::TileKind::values) {
      write_plane_tile<Arch>(tile, slots_[index], planes_, px, py, depth);
      tile.kind = detail::TileKind::values;
      tile.unresolved = false;
    }
    test_pixels(tile, mask, depth, px, py);
  }

  // The largest depth draw() gives the view's samples `samples` of block (x, y), in lanes: the
  // lanes' dx, (px + 0.5) - x0 with px = k x + i, is depth_at()'s (the integers' sum is exact),
  // and so is every other operation.
  float farthest_sample(std::uint32_t samples, std::int32_t x, std::int32_t y) const {
    const Floats x0(static_cast<float>(reduction_ * x)), y0(static_cast<float>(reduction_ * y));
    Floats farthest(0.0f);
    for (std::size_t h = 0; h * kLanes < static_cast<std::size_t>(reduction_ * reduction_); ++h) {
      const std::uint32_t lanes = samples >> (h * kLanes);
      const Floats dx = ((x0 + Floats::load_aligned(sample_column_ + h * kLanes)) + Floats(0.5f)) -
                        Floats(view_plane_.x0);
      const Floats dy = ((y0 + Floats::load_aligned(sample_row_ + h * kLanes)) + Floats(0.5f)) -
                        Floats(view_plane_.y0);
      const Floats z = clamp01((Floats(view_plane_.z0) + Floats(view_plane_.dzdy) * dy) +
                               Floats(view_plane_.dzdx) * dx);
      farthest = xsimd::max(farthest, xsimd::select(lanes_of_bits<Arch>(lanes), z, Floats(0.0f)));
    }
    return lane_max<Arch>(farthest);
  }

  // The depth that `tile` (its slots, its values `depth`) holds at `pixel`, pixel (x, y) of the
  // target: the value resolve_plane_tiles would write.
  float block_value(const detail::PlaneTile& tile, const detail::PlaneSlots& slots,
                    const float* depth, int pixel, std::int32_t x, std::int32_t y) const {
    if (tile.kind == detail::TileKind::values) return depth[pixel];
    std::uint32_t plane = tile.plane;
    if (tile.kind == detail::TileKind::slots) {
      for (int s = 0; s < detail::kPlaneTileSlots; ++s) {
        if ((slots.mask[s] >> pixel) & 1u) plane = slots.plane[s];
      }
    }
    return detail::depth_at(planes_[plane], x, y);
  }

  // Clamped to [0, 1]; NaN stays NaN.
  static double clamp_unit(double z) {
    return z > 0.0 ? (z < 1.0 ? z : 1.0) : (z <= 0.0 ? 0.0 : z);
  }
  // A float at most z, or at least z, for z in [0, 1] (NaN passes): the nearest, moved to its
  // neighbour when it lies on the wrong side (then it is above 0, or below 1).
  static float float_below(double z) {
    const float f = static_cast<float>(z);
    return f > z ? std::bit_cast<float>(std::bit_cast<std::uint32_t>(f) - 1u) : f;
  }
  static float float_above(double z) {
    const float f = static_cast<float>(z);
    return f < z ? std::bit_cast<float>(std::bit_cast<std::uint32_t>(f) + 1u) : f;
  }
  // Plain comparisons: std::fmax and std::fmin compile to library calls (a NaN lane gives NaN
  // bounds either way, which decide nothing).
  static double larger(double a, double b) { return a > b ? a : b; }
  static double smaller(double a, double b) { return a < b ? a : b; }

  // The triangle's plane takes the pixels of `mask` (some, not all) from the planes that held
  // them, in a free slot; false when no slot is free (the tile is then tested per pixel).
  bool take_pixels(detail::PlaneTile& tile, detail::PlaneSlots& slots, std::uint64_t mask) const {
    if (tile.kind == detail::TileKind::plane) {
      slots.mask[0] = ~mask;
      slots.plane[0] = tile.plane;
      slots.mask[1] = mask;
      slots.plane[1] = plane_index_;
      for (int free = 2; free < detail::kPlaneTileSlots; ++free)
        slots.mask[free] = 0;
      tile.kind = detail::TileKind::slots;
    } else {
      std::uint64_t left[detail::kPlaneTileSlots];
      int free = detail::kPlaneTileSlots;
      for (int s = detail::kPlaneTileSlots - 1; s >= 0; --s) {
        left[s] = slots.mask[s] & ~mask;
        free = left[s] == 0 ? s : free;
      }
      if (free == detail::kPlaneTileSlots) return false;
      for (int s = 0; s < detail::kPlaneTileSlots; ++s)
        slots.mask[s] = left[s];
      slots.mask[free] = mask;
      slots.plane[free] = plane_index_;
    }
    // The triangle's depths lie below the tile's lowest; the highest still bounds the rest.
    tile.lowest = lowest_depth_;
    tile.unresolved = true;
    return true;
  }

  // draw()'s depth test less with writes, per pixel, on a tile of values.
  void test_pixels(detail::PlaneTile& tile, std::uint64_t mask, float* depth, std::int32_t px,
                   std::int32_t py) {
    const TilePlaneTerms<Arch> terms(plane_, px, py);
    std::uint64_t passed = 0;
    for (std::uint32_t rows = covered_rows(mask); rows != 0; rows &= rows - 1) {
      const int row = std::countr_zero(rows);
      const std::uint32_t row_bits = static_cast<std::uint32_t>(mask >> (row * 8)) & 0xFFu;
      for (std::size_t h = 0; h < kParts; ++h) {
        float* at = depth + row * kTileSize + h * kLanes;
        const Floats z = terms.depth(row, h);
        const Floats stored = Floats::load_aligned(at);
        const Mask write = lanes_of_bits<Arch>(row_bits >> (h * kLanes)) && z < stored;
        xsimd::select(write, z, stored).store_aligned(at);
        passed += static_cast<std::uint64_t>(std::popcount(bits_of_lanes<Arch>(write)));
      }
    }
    passed_ += passed;
    // Values only fall: the highest still bounds them, and the new ones lie at or above
    // lowest_depth_ (a NaN bound says nothing: the written ones lie in [0, 1]).
    if (!(lowest_depth_ >= tile.lowest)) {
      tile.lowest = lowest_depth_ == lowest_depth_ ? lowest_depth_ : std::fmin(tile.lowest, 0.0f);
    }
  }

  const detail::ShadeBatch& batch_;
  detail::PlaneTile* const tiles_;
  detail::PlaneSlots* const slots_;
  detail::DepthPlane* const planes_;
  const std::uint32_t first_plane_;
  const std::int32_t reduction_;
  detail::BlockLayer* const layers_;
  const std::uint32_t all_samples_;  // a block's samples, as BlockLayer::samples names them
  // Sample s of a block at (s % k, s / k) from its first.
  alignas(64) float sample_column_[kMaxReduction * kMaxReduction];
  alignas(64) float sample_row_[kMaxReduction * kMaxReduction];
  PlaneGroup<Arch> group_;
  float lowest_[kGroupLanes], highest_[kGroupLanes];
  detail::DepthPlane plane_{};
  // On a reduced buffer, the triangle's plane and lower bound in the view.
  detail::DepthPlane view_plane_{};
  float view_lowest_ = 0.0f;
  std::uint32_t plane_index_ = 0;
  float lowest_depth_ = 0.0f, highest_depth_ = 1.0f;
  detail::PlaneTile whole_tile_{};  // a tile the triangle covers whole, in front of it
  std::uint64_t fragments_ = 0, passed_ = 0;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
