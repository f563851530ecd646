// The tile walk: a triangle's clipped box in 8x8 tiles. Each tile row finds the tiles that no
// edge rejects and, among them, the run that every edge accepts; the accepted run is delivered
// whole and only the tiles at its two ends are evaluated per pixel. The partial-tile evaluator
// steps whole rows of edge values in xsimd batches (a row of 8 per step with 8 lanes, half rows
// with 4 lanes). A triangle whose box fits in 8x8 pixels is evaluated as one unaligned block.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "../simd/lane_arch-inl.hpp"
#include "../simd/simd_ops-inl.hpp"
#include "tile_masks-inl.hpp"
#include "triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// Hands a tile's mask to the visitor if any sample is covered. A visitor that declares
// kTakesEmptyMasks (one that only counts, to which an empty mask adds nothing) is handed every
// mask the walk makes, empty ones too (also of tiles just past the box), so that the walks
// have no branch per tile for it.
template <class Visitor>
[[gnu::always_inline]] inline void deliver_tile(Visitor& visitor, std::uint32_t tile_x,
                                                std::uint32_t tile_y, std::uint64_t mask) {
  if constexpr (requires { Visitor::kTakesEmptyMasks; }) {
    visitor.tile(tile_x, tile_y, mask);
  } else if (mask != 0) {
    visitor.tile(tile_x, tile_y, mask);
  }
}

// Coverage of partial tiles, with the per-triangle lane constants hoisted. A batch holds part of
// a tile row (4 lanes), one row (8) or several whole rows (16 lanes: rows r and r + 1).
template <class Arch>
class TileEvaluator {
 public:
  using Lanes = xsimd::batch<std::int32_t, Arch>;
  static constexpr std::size_t kLanes = Lanes::size;
  static constexpr std::size_t kStepsPerRow = kLanes < kTileSize ? kTileSize / kLanes : 1;
  static constexpr std::size_t kRowsPerStep = kLanes > kTileSize ? kLanes / kTileSize : 1;
  static_assert(kStepsPerRow * kLanes == kRowsPerStep * kTileSize,
                "a tile row is a whole number of batches, or a batch a whole number of rows");
  static_assert(kTileSize % kRowsPerStep == 0, "a tile is a whole number of batches");

  explicit TileEvaluator(const TriangleSetup& setup) {
    alignas(64) static constexpr std::int32_t kColumn[16] = {0, 1, 2, 3, 4, 5, 6, 7,
                                                             0, 1, 2, 3, 4, 5, 6, 7};
    alignas(64) static constexpr std::int32_t kRow[16] = {0, 0, 0, 0, 0, 0, 0, 0,
                                                          1, 1, 1, 1, 1, 1, 1, 1};
    static_assert(kStepsPerRow * kLanes <= 16, "the lane tables hold two rows");
    for (int e = 0; e < 3; ++e) {
      const Lanes a(setup.edge[e].a);
      for (std::size_t h = 0; h < kStepsPerRow; ++h) {
        column_offset_[e][h] = a * Lanes::load_aligned(kColumn + h * kLanes);
        if constexpr (kRowsPerStep > 1) {
          column_offset_[e][h] += Lanes(setup.edge[e].b) * Lanes::load_aligned(kRow + h * kLanes);
        }
      }
      row_step_[e] = Lanes(setup.edge[e].b * static_cast<std::int32_t>(kRowsPerStep));
    }
  }

  // Bit (y * 8 + x) set when the sample at (x, y) of the block is covered. `g` holds each
  // edge's G at the block's first sample, within +-2^30 (see the overflow analysis). All eight
  // rows are evaluated: a fixed trip count unrolls, and callers mask the rows they need.
  std::uint64_t coverage(const std::int32_t g[3]) const {
    const Lanes g0(g[0]), g1(g[1]), g2(g[2]);
    Lanes v0[kStepsPerRow], v1[kStepsPerRow], v2[kStepsPerRow];
    for (std::size_t h = 0; h < kStepsPerRow; ++h) {
      v0[h] = g0 + column_offset_[0][h];
      v1[h] = g1 + column_offset_[1][h];
      v2[h] = g2 + column_offset_[2][h];
    }
    constexpr std::size_t kSteps = kTileSize / kRowsPerStep;
    Lanes any_outside[kSteps * kStepsPerRow];  // negative where some edge excludes the sample
    for (std::size_t step = 0; step < kSteps; ++step) {
      for (std::size_t h = 0; h < kStepsPerRow; ++h) {
        any_outside[step * kStepsPerRow + h] = v0[h] | v1[h] | v2[h];
        v0[h] += row_step_[0];
        v1[h] += row_step_[1];
        v2[h] += row_step_[2];
      }
    }
    return ~sign_bits_8x8<Arch>(any_outside);
  }

  // coverage() of edge e alone, for a block that the other two edges hold whole.
  std::uint64_t coverage_of_edge(int e, std::int32_t g) const {
    const Lanes g0(g);
    Lanes v[kStepsPerRow];
    for (std::size_t h = 0; h < kStepsPerRow; ++h)
      v[h] = g0 + column_offset_[e][h];
    constexpr std::size_t kSteps = kTileSize / kRowsPerStep;
    Lanes outside[kSteps * kStepsPerRow];  // negative where the edge excludes the sample
    for (std::size_t step = 0; step < kSteps; ++step) {
      for (std::size_t h = 0; h < kStepsPerRow; ++h) {
        outside[step * kStepsPerRow + h] = v[h];
        v[h] += row_step_[e];
      }
    }
    return ~sign_bits_8x8<Arch>(outside);
  }

 private:
  Lanes column_offset_[3][kStepsPerRow];
  Lanes row_step_[3];
};

inline std::int32_t clamp_to_tile_range(std::int64_t g) {
  constexpr std::int64_t kLimit = std::int64_t{1} << 30;
  return static_cast<std::int32_t>(g < -kLimit ? -kLimit : (g > kLimit ? kLimit : g));
}
inline std::int32_t clamp_to_tile_range(std::int32_t g) {
  return g;
}  // narrow: exact already

// The smallest k >= lo with num <= den * k, or the largest k < hi with den * k <= num,
// clamped to [lo, hi]. Exact: num and den (|num| < 2^51, |den| <= 2^27) convert to double
// exactly; an integer quotient divides exactly, and any other lies at least 1/|den| >= 2^-27
// from an integer while the division errs by at most |q| 2^-53 <= 2^-40 for |q| <= 2^13;
// larger quotients lie beyond the clamp (at most 4096 tiles) either way.
inline std::int32_t first_at_least(std::int64_t num, std::int64_t den, std::int32_t lo,
                                   std::int32_t hi) {
  const double k = std::ceil(static_cast<double>(num) / static_cast<double>(den));
  return k <= lo ? lo : (k >= hi ? hi : static_cast<std::int32_t>(k));
}
inline std::int32_t end_at_most(std::int64_t num, std::int64_t den, std::int32_t lo,
                                std::int32_t hi) {
  const double k = std::floor(static_cast<double>(num) / static_cast<double>(den)) + 1.0;
  return k <= lo ? lo : (k >= hi ? hi : static_cast<std::int32_t>(k));
}

// Rows wider than this many tiles find their ranges by division rather than tile by tile.
inline constexpr std::int32_t kScanColumns = 4;

// The columns of one tile row the walk visits: no edge rejects the tiles in [begin, end), and
// every edge accepts those in [full_begin, full_end), a run inside [begin, end) (empty when
// full_begin == full_end).
struct TileColumns {
  std::int32_t begin, end, full_begin, full_end;
};

// walk_tiles() one tile row at a time. Holds what is fixed per triangle: the box's tile
// columns, each edge's steps between tiles and its extreme offsets within a tile. Every member
// is forced inline: the walk still compiles to one loop nest, the members to locals. Arrays are
// passed as references to arrays, not pointers, so that the compiler knows their extents and
// keeps them in registers.
template <class Arch, class Int, class Visitor>
class TileRowWalker {
 public:
  [[gnu::always_inline]] TileRowWalker(const TriangleSetup& setup, Visitor& visitor)
      : setup_(setup),
        box_(setup.box),
        visitor_(visitor),
        evaluator_(setup),
        columns_(((box_.x1 - 1 - setup.origin_x) >> 3) + 1),
        inner_begin_((box_.x0 - setup.origin_x + kTileSize - 1) >> 3),
        inner_end_((box_.x1 - setup.origin_x) >> 3),
        first_tile_x_(static_cast<std::uint32_t>(setup.origin_x / kTileSize)) {
    for (int e = 0; e < 3; ++e) {
      const Int a = setup.edge[e].a, b = setup.edge[e].b;
      step_x_[e] = a * kTileSize;
      step_y_[e] = b * kTileSize;
      // The tile's extreme samples for this edge: corners chosen by the signs of a and b.
      max_offset_[e] = (kTileSize - 1) * ((a > 0 ? a : 0) + (b > 0 ? b : 0));
      min_offset_[e] = (kTileSize - 1) * ((a < 0 ? a : 0) + (b < 0 ? b : 0));
    }
  }

  // Narrow boxes (the scan path) look their column masks up in `clip`.
  [[gnu::always_inline]] void clip_scan_columns(std::uint64_t (&clip)[kScanColumns]) const {
    for (std::int32_t column = 0; column < kScanColumns && column < columns_; ++column) {
      clip[column] = column_clip(column);
    }
  }

  // Visits the tiles of the tile row whose top pixel row is ty; `row_g` holds each edge's G at
  // the row's first tile, `scan_column_clip` what clip_scan_columns() stored.
  [[gnu::always_inline]] void walk_row(
      const Int (&row_g)[3], std::int32_t ty,
      const std::uint64_t (&scan_column_clip)[kScanColumns]) const {
    const int first_row = box_.y0 > ty ? box_.y0 - ty : 0;
    const int end_row = box_.y1 - ty < kTileSize ? box_.y1 - ty : kTileSize;
    const std::uint64_t rows = row_bits(first_row, end_row);
    const std::uint32_t tile_y = static_cast<std::uint32_t>(ty / kTileSize);
    Int g[3];
    for (int e = 0; e < 3; ++e)
      g[e] = row_g[e];
    if (columns_ <= kScanColumns) {
      scan_row(g, tile_y, rows, scan_column_clip);
    } else {
      walk_row_by_ranges(g, tile_y, rows);
    }
  }

  // Moves each edge's G from one tile row to the next.
  [[gnu::always_inline]] void step_down(Int (&g)[3]) const {
    for (int e = 0; e < 3; ++e)
      g[e] += step_y_[e];
  }

 private:
  // Pixels of tile column `column` inside the box horizontally.
  [[gnu::always_inline]] std::uint64_t column_clip(std::int32_t column) const {
    const std::int32_t tx = setup_.origin_x + column * kTileSize;
    return column_bits(box_.x0 > tx ? box_.x0 - tx : 0,
                       box_.x1 - tx < kTileSize ? box_.x1 - tx : kTileSize);
  }

  // Evaluates one tile per pixel and hands on its mask if any sample is covered.
  [[gnu::always_inline]] void evaluate(const Int (&g)[3], std::int32_t column, std::uint32_t tile_y,
                                       std::uint64_t clip) const {
    const std::int32_t tile_g[3] = {clamp_to_tile_range(g[0]), clamp_to_tile_range(g[1]),
                                    clamp_to_tile_range(g[2])};
    const std::uint64_t mask = evaluator_.coverage(tile_g) & clip;
    deliver_tile(visitor_, first_tile_x_ + static_cast<std::uint32_t>(column), tile_y, mask);
  }

  // Few tiles: reject tile by tile and evaluate the rest (evaluating a tile that every edge
  // accepts gives its mask all the same, and costs less than telling such tiles apart).
  [[gnu::always_inline]] void scan_row(
      Int (&g)[3], std::uint32_t tile_y, std::uint64_t rows,
      const std::uint64_t (&scan_column_clip)[kScanColumns]) const {
    for (std::int32_t column = 0; column < columns_; ++column) {
      const bool rejected =
          (g[0] + max_offset_[0] < 0) | (g[1] + max_offset_[1] < 0) | (g[2] + max_offset_[2] < 0);
      if constexpr (requires { Visitor::kTakesEmptyMasks; }) {
        // A rejected tile's mask is empty: evaluating it costs less than a mispredicted test.
        evaluate(g, column, tile_y, rejected ? 0 : rows & scan_column_clip[column]);
      } else if (!rejected) {
        evaluate(g, column, tile_y, rows & scan_column_clip[column]);
      }
      for (int e = 0; e < 3; ++e)
        g[e] += step_x_[e];
    }
  }

  // Many tiles: find the row's columns by division, evaluate the partial tiles at both ends of
  // the accepted run and deliver the run whole.
  [[gnu::always_inline]] void walk_row_by_ranges(const Int (&g)[3], std::uint32_t tile_y,
                                                 std::uint64_t rows) const {
    const TileColumns range = solve_columns(g);
    evaluate_columns(g, range.begin, range.full_begin, tile_y, rows);
    if (range.full_begin < range.full_end) {
      visitor_.full_tiles(
          static_cast<std::uint32_t>(setup_.origin_x / kTileSize + range.full_begin),
          static_cast<std::uint32_t>(setup_.origin_x / kTileSize + range.full_end), tile_y, rows);
    }
    evaluate_columns(g, range.full_end, range.end, tile_y, rows);
  }

  // Per edge, tile k's extreme sample is G + offset + step_x k: solve for the range of k.
  [[gnu::always_inline]] TileColumns solve_columns(const Int (&g)[3]) const {
    std::int32_t begin = 0, end = columns_, full_begin = inner_begin_, full_end = inner_end_;
    for (int e = 0; e < 3; ++e) {
      const std::int64_t top = std::int64_t{g[e]} + max_offset_[e];
      const std::int64_t bottom = std::int64_t{g[e]} + min_offset_[e];
      const std::int64_t step = step_x_[e];
      if (step > 0) {
        begin = first_at_least(-top, step, begin, end);
        full_begin = first_at_least(-bottom, step, full_begin, columns_);
      } else if (step < 0) {
        end = end_at_most(top, -step, begin, end);
        full_end = end_at_most(bottom, -step, 0, full_end);
      } else {
        if (top < 0) end = begin;
        if (bottom < 0) full_end = 0;
      }
    }
    if (full_begin >= full_end) full_begin = full_end = end;  // no accepted run
    return {begin, end, full_begin, full_end};
  }

  // Evaluates the tiles of columns [begin, end) of the row whose first tile has G `g`.
  [[gnu::always_inline]] void evaluate_columns(const Int (&g)[3], std::int32_t begin,
                                               std::int32_t end, std::uint32_t tile_y,
                                               std::uint64_t rows) const {
    Int tile_g[3];
    for (int e = 0; e < 3; ++e)
      tile_g[e] = g[e] + step_x_[e] * begin;
    for (std::int32_t column = begin; column < end; ++column) {
      evaluate(tile_g, column, tile_y, rows & column_clip(column));
      for (int e = 0; e < 3; ++e)
        tile_g[e] += step_x_[e];
    }
  }

  const TriangleSetup& setup_;
  const PixelRect& box_;
  Visitor& visitor_;
  const TileEvaluator<WideArch<Arch>> evaluator_;
  // Tile columns 0 .. columns-1 from origin_x; those in [inner_begin, inner_end) lie wholly
  // inside the box horizontally.
  const std::int32_t columns_, inner_begin_, inner_end_;
  const std::uint32_t first_tile_x_;  // the target's tile x of column 0
  Int step_x_[3], step_y_[3], max_offset_[3], min_offset_[3];
};

// Calls visitor.tile(tile_x, tile_y, mask) for every tile with covered samples, and
// visitor.full_tiles(tile_x_begin, tile_x_end, tile_y, mask) for runs of tiles that share one
// mask, in row order. Int is the type the walk steps G in: int32 when setup.narrow, else int64.
template <class Arch, class Int, class Visitor>
[[gnu::noinline]] void walk_tiles(const TriangleSetup& setup, Visitor& visitor) {
  const TileRowWalker<Arch, Int, Visitor> walker(setup, visitor);
  // Apart from the walker: an array indexed by column would keep the walker's members in memory.
  std::uint64_t scan_column_clip[kScanColumns];
  walker.clip_scan_columns(scan_column_clip);
  Int row_g[3];
  for (int e = 0; e < 3; ++e)
    row_g[e] = static_cast<Int>(setup.edge[e].g);
  for (std::int32_t ty = setup.origin_y; ty < setup.box.y1; ty += kTileSize) {
    walker.walk_row(row_g, ty, scan_column_clip);
    walker.step_down(row_g);
  }
}

// Hands the masks of an N x N grid of tiles from (tile_x, tile_y) to the visitor: whole, to a
// visitor with a small-triangle path (tile_grid), else tile by tile in row order.
template <std::size_t N, class Visitor>
[[gnu::always_inline]] inline void deliver_tile_grid(std::uint32_t tile_x, std::uint32_t tile_y,
                                                     const std::uint64_t (&masks)[N][N],
                                                     Visitor& visitor) {
  if constexpr (requires { visitor.tile_grid(tile_x, tile_y, masks); }) {
    visitor.tile_grid(tile_x, tile_y, masks);
  } else if constexpr (requires { Visitor::kTakesEmptyMasks; }) {
    for (std::uint32_t row = 0; row < N; ++row) {
      for (std::uint32_t column = 0; column < N; ++column) {
        deliver_tile(visitor, tile_x + column, tile_y + row, masks[row][column]);
      }
    }
  } else {
    // The covered tiles listed first, without a branch per tile: which of a small triangle's
    // tiles are empty follows no pattern a predictor could learn.
    std::uint64_t covered[N * N];
    std::uint32_t where[N * N];
    std::uint32_t count = 0;
    for (std::uint32_t row = 0; row < N; ++row) {
      for (std::uint32_t column = 0; column < N; ++column) {
        covered[count] = masks[row][column];
        where[count] = row * N + column;
        count += masks[row][column] != 0;
      }
    }
    for (std::uint32_t i = 0; i < count; ++i)
      visitor.tile(tile_x + where[i] % N, tile_y + where[i] / N, covered[i]);
  }
}

// A triangle whose box fits in 8x8 pixels: one block evaluated at the box's corner, then
// split among the (up to four) tiles it overlaps. Needs setup.narrow. Out of line, as every
// walk (triangle_batch-inl.hpp says why).
template <class Arch, class Visitor>
[[gnu::noinline]] void walk_block(const TriangleSetup& setup, Visitor& visitor) {
  const TileEvaluator<WideArch<Arch>> evaluator(setup);
  const PixelRect& box = setup.box;
  const std::int32_t dx = box.x0 - setup.origin_x, dy = box.y0 - setup.origin_y;  // 0 .. 7
  std::int32_t g[3];
  for (int e = 0; e < 3; ++e) {
    g[e] = static_cast<std::int32_t>(setup.edge[e].g) + setup.edge[e].a * dx + setup.edge[e].b * dy;
  }
  const std::uint64_t block =
      evaluator.coverage(g) & row_bits(0, box.y1 - box.y0) & column_bits(0, box.x1 - box.x0);
  // Block column c lands in column c + dx of the left tiles, c + dx - 8 of the right ones.
  const std::uint64_t left = (block & column_bits(0, kTileSize - dx)) << dx;
  const std::uint64_t right = dx == 0 ? 0 : (block >> (kTileSize - dx)) & column_bits(0, dx);
  const std::uint32_t tx = static_cast<std::uint32_t>(setup.origin_x / kTileSize);
  const std::uint32_t ty = static_cast<std::uint32_t>(setup.origin_y / kTileSize);
  const int shift_down = 8 * dy;
  const int shift_up = 8 * (kTileSize - dy);  // 8 .. 64: used only when dy != 0
  const std::uint64_t masks[2][2] = {
      {left << shift_down, right << shift_down},
      {dy == 0 ? 0 : left >> shift_up, dy == 0 ? 0 : right >> shift_up}};
  deliver_tile_grid(tx, ty, masks, visitor);
}

// A triangle whose box fits in 16x16 pixels: up to four 8x8 blocks evaluated from the box's
// corner, their samples gathered into the (up to) 3x3 tiles they overlap, and the tiles handed
// on in row order as walk_tiles() would. Needs setup.narrow: every sample lies within the reach
// of the overflow analysis (box corner + 15 < origin + 31). Out of line, as every walk.
template <class Arch, class Visitor>
[[gnu::noinline]] void walk_block_16(const TriangleSetup& setup, Visitor& visitor) {
  const TileEvaluator<WideArch<Arch>> evaluator(setup);
  const PixelRect& box = setup.box;
  const std::int32_t dx = box.x0 - setup.origin_x, dy = box.y0 - setup.origin_y;  // 0 .. 7
  const std::int32_t width = box.x1 - box.x0, height = box.y1 - box.y0;           // 1 .. 16
  std::uint64_t block[2][2] = {};
  for (std::int32_t by = 0; by < 2; ++by) {
    const std::int32_t rows =
        height - kTileSize * by < kTileSize ? height - kTileSize * by : kTileSize;
    if (rows <= 0) break;
    for (std::int32_t bx = 0; bx < 2; ++bx) {
      const std::int32_t columns =
          width - kTileSize * bx < kTileSize ? width - kTileSize * bx : kTileSize;
      if (columns <= 0) break;
      std::int32_t g[3];
      for (int e = 0; e < 3; ++e) {
        g[e] = static_cast<std::int32_t>(setup.edge[e].g) +
               setup.edge[e].a * (dx + kTileSize * bx) + setup.edge[e].b * (dy + kTileSize * by);
      }
      block[by][bx] = evaluator.coverage(g) & row_bits(0, rows) & column_bits(0, columns);
    }
  }
  // Block column c lands in column c + dx of its tile column, c + dx - 8 of the next; block row
  // r in row r + dy of its tile row, r + dy - 8 of the next. Each tile's mask is the OR of the
  // parts that land in it, formed in registers: read-modify-writes of an array of masks were
  // compiled to 16-byte loads over 8-byte stores, which stall store forwarding.
  const std::uint64_t keep_left = column_bits(0, kTileSize - dx);
  const auto left = [&](std::uint64_t b) { return (b & keep_left) << dx; };
  const auto right = [&](std::uint64_t b) {
    return dx == 0 ? 0 : (b >> (kTileSize - dx)) & column_bits(0, dx);
  };
  const auto top = [&](std::uint64_t m) { return m << (8 * dy); };
  const auto bottom = [&](std::uint64_t m) { return dy == 0 ? 0 : m >> (8 * (kTileSize - dy)); };
  const std::uint64_t l00 = left(block[0][0]), r00 = right(block[0][0]);
  const std::uint64_t l01 = left(block[0][1]), r01 = right(block[0][1]);
  const std::uint64_t l10 = left(block[1][0]), r10 = right(block[1][0]);
  const std::uint64_t l11 = left(block[1][1]), r11 = right(block[1][1]);
  const std::uint64_t tiles[3][3] = {
      {top(l00), top(r00) | top(l01), top(r01)},
      {bottom(l00) | top(l10), bottom(r00) | bottom(l01) | top(r10) | top(l11),
       bottom(r01) | top(r11)},
      {bottom(l10), bottom(r10) | bottom(l11), bottom(r11)}};
  const std::uint32_t tx = static_cast<std::uint32_t>(setup.origin_x / kTileSize);
  const std::uint32_t ty = static_cast<std::uint32_t>(setup.origin_y / kTileSize);
  deliver_tile_grid(tx, ty, tiles, visitor);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
