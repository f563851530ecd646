// The tile walk: a triangle's clipped box in 8x8 tiles, each tile rejected, accepted or
// evaluated per pixel. The partial-tile evaluator steps whole rows of edge values in xsimd
// batches (one row of 8 per step with 8 lanes, half rows with 4 lanes).
#pragma once

#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "simd_ops-inl.hpp"
#include "triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

static_assert(kTileSize == 8, "tile masks are 64-bit: 8 x 8 pixels");

// Coverage of partial tiles, with the per-triangle lane constants hoisted.
template <class Arch>
class TileEvaluator {
 public:
  using Lanes = xsimd::batch<std::int32_t, Arch>;
  static constexpr std::size_t kLanes = Lanes::size;
  static constexpr std::size_t kStepsPerRow = kTileSize / kLanes;
  static_assert(kTileSize % kLanes == 0, "a tile row is a whole number of batches");

  explicit TileEvaluator(const TriangleSetup& setup) {
    alignas(64) static constexpr std::int32_t kColumn[kTileSize] = {0, 1, 2, 3, 4, 5, 6, 7};
    for (int e = 0; e < 3; ++e) {
      const Lanes a(setup.edge[e].a);
      for (std::size_t h = 0; h < kStepsPerRow; ++h) {
        column_offset_[e][h] = a * Lanes::load_aligned(kColumn + h * kLanes);
      }
      row_step_[e] = Lanes(setup.edge[e].b);
    }
  }

  // Bit (y * 8 + x) set when the sample at (x, y) of the tile is covered; `g` holds each
  // edge's G at the tile's first sample, already within +-2^29 (see the overflow analysis).
  std::uint64_t coverage(const std::int32_t g[3]) const {
    Lanes v0[kStepsPerRow], v1[kStepsPerRow], v2[kStepsPerRow];
    for (std::size_t h = 0; h < kStepsPerRow; ++h) {
      v0[h] = Lanes(g[0]) + column_offset_[0][h];
      v1[h] = Lanes(g[1]) + column_offset_[1][h];
      v2[h] = Lanes(g[2]) + column_offset_[2][h];
    }
    std::uint64_t outside = 0;  // sign bit of any edge: the sample is outside
    for (int row = 0; row < kTileSize; ++row) {
      for (std::size_t h = 0; h < kStepsPerRow; ++h) {
        const std::uint64_t bits = sign_bits<Arch>(v0[h] | v1[h] | v2[h]);
        outside |= bits << (row * kTileSize + h * kLanes);
        v0[h] += row_step_[0];
        v1[h] += row_step_[1];
        v2[h] += row_step_[2];
      }
    }
    return ~outside;
  }

 private:
  Lanes column_offset_[3][kStepsPerRow];
  Lanes row_step_[3];
};

inline std::int32_t clamp_to_tile_range(std::int64_t g) {
  constexpr std::int64_t kLimit = std::int64_t{1} << 29;
  return static_cast<std::int32_t>(g < -kLimit ? -kLimit : (g > kLimit ? kLimit : g));
}
inline std::int32_t clamp_to_tile_range(std::int32_t g) {
  return g;
}  // narrow: exact already

// Pixels of one tile row/column inside [lo, hi) of the clip box, as mask bits.
inline std::uint64_t clip_rows(std::int32_t tile_origin, std::int32_t lo, std::int32_t hi) {
  const std::int32_t first = lo > tile_origin ? lo - tile_origin : 0;
  const std::int32_t end = hi - tile_origin < kTileSize ? hi - tile_origin : kTileSize;
  return (~std::uint64_t{0} << (8 * first)) & (~std::uint64_t{0} >> (8 * (kTileSize - end)));
}
inline std::uint64_t clip_columns(std::int32_t tile_origin, std::int32_t lo, std::int32_t hi) {
  const std::int32_t first = lo > tile_origin ? lo - tile_origin : 0;
  const std::int32_t end = hi - tile_origin < kTileSize ? hi - tile_origin : kTileSize;
  const std::uint64_t byte = (0xFFu << first) & (0xFFu >> (kTileSize - end));
  return byte * 0x0101010101010101ull;
}

// Calls visitor.tile(tile_x, tile_y, mask) for every tile with covered samples, row by row.
// Int is the type the walk steps G in: int32 when setup.narrow, int64 otherwise.
template <class Arch, class Int, class Visitor>
void walk_tiles(const TriangleSetup& setup, Visitor& visitor) {
  const TileEvaluator<Arch> evaluator(setup);
  const PixelRect& box = setup.box;
  Int row_g[3], step_x[3], step_y[3], max_offset[3], min_offset[3];
  for (int e = 0; e < 3; ++e) {
    const Int a = setup.edge[e].a, b = setup.edge[e].b;
    row_g[e] = static_cast<Int>(setup.edge[e].g);
    step_x[e] = a * kTileSize;
    step_y[e] = b * kTileSize;
    // The tile's extreme samples for this edge: corners chosen by the signs of a and b.
    max_offset[e] = (kTileSize - 1) * ((a > 0 ? a : 0) + (b > 0 ? b : 0));
    min_offset[e] = (kTileSize - 1) * ((a < 0 ? a : 0) + (b < 0 ? b : 0));
  }
  const std::int32_t last_x = box.x1 - 1, last_y = box.y1 - 1;
  for (std::int32_t ty = setup.origin_y; ty <= last_y; ty += kTileSize) {
    const std::uint64_t rows = clip_rows(ty, box.y0, box.y1);
    Int g[3] = {row_g[0], row_g[1], row_g[2]};
    for (std::int32_t tx = setup.origin_x; tx <= last_x; tx += kTileSize) {
      const bool rejected =
          (g[0] + max_offset[0] < 0) | (g[1] + max_offset[1] < 0) | (g[2] + max_offset[2] < 0);
      if (!rejected) {
        std::uint64_t mask = rows & clip_columns(tx, box.x0, box.x1);
        const bool accepted =
            (g[0] + min_offset[0] >= 0) & (g[1] + min_offset[1] >= 0) & (g[2] + min_offset[2] >= 0);
        if (!accepted) {
          const std::int32_t tile_g[3] = {clamp_to_tile_range(g[0]), clamp_to_tile_range(g[1]),
                                          clamp_to_tile_range(g[2])};
          mask &= evaluator.coverage(tile_g);
        }
        if (mask != 0) {
          visitor.tile(static_cast<std::uint32_t>(tx / kTileSize),
                       static_cast<std::uint32_t>(ty / kTileSize), mask);
        }
      }
      for (int e = 0; e < 3; ++e)
        g[e] += step_x[e];
    }
    for (int e = 0; e < 3; ++e)
      row_g[e] += step_y[e];
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
