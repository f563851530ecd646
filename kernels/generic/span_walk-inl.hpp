// The span walk: a triangle's clipped box in strips of 8 pixel rows (one tile row). For each
// row of a strip the three edge functions give the exact span of covered columns [L, R):
// G + a x >= 0 holds from x = ceil(t) on for a left edge (a > 0) and up to x < ceil(t) for a
// right edge (a < 0), where t = -(G0 + 1/2) / a and G0 is the edge's G at the box's first tile
// column. A tile's mask is then read off the eight spans, whatever edges cross it; tiles
// between the strip's spans are delivered whole.
//
// Exactness: G0 is an integer below 2^42 and a a nonzero integer below 2^25, both exact in
// double. The half in the numerator keeps t off the integers: its distance to the nearest one
// is at least 1 / (2 |a|) > 2^-26, so any approximation of t closer than that has the same
// ceil(). No division is needed: with m = fl(-1/a) and the row slope s = fl(b m), a strip's
// row k gets t_k = fl(fl((G0 + 1/2) m) + fl(k s)), whose error is at most
// 2^-53 (2 |t_0| + 3 |k s| + |t_k|). The walk is used only where |b| < 2^20 |a|
// (span_walk_is_exact), so |k s| < 2^23 for k <= 7; for |t_k| <= 2^17 then |t_0| < 2^24 and the
// error is below 2^-53 * 2^26 = 2^-27. A larger |t_k| lies beyond every column of the guard
// band (columns are below 2^16 from the first tile column) and is clamped to the box either way.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "simd_ops-inl.hpp"
#include "tile_masks-inl.hpp"
#include "tile_walk-inl.hpp"
#include "triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// The edges of one triangle as the span walk steps them, ordered left edges (a > 0) first, then
// right edges (a < 0), then the horizontal edge if any. A triangle has one of three such edge
// sets (its a's sum to zero): two left and one right, one left and two right, or one of each
// kind. The set is a template argument, so the strip loop tests no edge's sign.
template <class Arch, int kLefts, int kRights>
class StripSpans {
 public:
  using Doubles = xsimd::batch<double, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  static constexpr std::size_t kDoubleParts = kTileSize / Doubles::size;
  static constexpr std::size_t kIntParts = kTileSize / Ints::size;
  static constexpr bool kHorizontal = kLefts + kRights < 3;
  static constexpr std::int32_t kBlockTiles = 3;  // tiles whose masks are made at once

  // `order` lists the setup's edges in the order above.
  StripSpans(const TriangleSetup& setup, const int (&order)[3]) {
    alignas(64) static constexpr double kRow[kTileSize] = {0, 1, 2, 3, 4, 5, 6, 7};
    for (int i = 0; i < 3; ++i) {
      const EdgeSetup& edge = setup.edge[order[i]];
      // Horizontal edges step G itself (exact); the others step t (see above).
      scale_[i] = edge.a != 0 ? -1.0 / edge.a : 1.0;
      offset_[i] = edge.a != 0 ? 0.5 : 0.0;
      const Doubles step(edge.a != 0 ? edge.b * scale_[i] : static_cast<double>(edge.b));
      for (std::size_t h = 0; h < kDoubleParts; ++h) {
        row_term_[i][h] = step * Doubles::load_aligned(kRow + h * Doubles::size);
        row_term_[i][h].store_aligned(scalar_row_term_[i] + h * Doubles::size);
      }
    }
  }

  // t at a strip's first row for each edge, from its G there (g0, in the edges' order).
  void starts(const double (&g0)[3], double (&start)[3]) const {
    for (int i = 0; i < 3; ++i)
      start[i] = (g0[i] + offset_[i]) * scale_[i];
  }

  // Spans of the 8 rows from a strip's first row, in columns from the box's first tile:
  // begin[] and end[] (begin >= end when a row is empty); [lo, hi) are the box's columns.
  void compute(const double (&start)[3], double lo, double hi, Ints* begin, Ints* end) const {
    Doubles first[kDoubleParts], last[kDoubleParts];  // last is exclusive
    for (std::size_t h = 0; h < kDoubleParts; ++h) {
      first[h] = Doubles(lo);
      last[h] = Doubles(hi);
    }
    for (int i = 0; i < 3; ++i) {
      const Doubles at(start[i]);
      for (std::size_t h = 0; h < kDoubleParts; ++h) {
        const Doubles t = at + row_term_[i][h];
        if (i < kLefts) {
          first[h] = xsimd::max(first[h], xsimd::ceil(t));
        } else if (i < kLefts + kRights) {
          last[h] = xsimd::min(last[h], xsimd::ceil(t));
        } else {  // horizontal: t is G, and the whole row is in or out
          last[h] = xsimd::select(t < Doubles(0.0), Doubles(lo), last[h]);
        }
      }
    }
    for (std::size_t h = 0; h < kDoubleParts; ++h) {
      first[h] = xsimd::min(first[h], Doubles(hi));  // keep both within the int32 range
      last[h] = xsimd::max(last[h], Doubles(lo));
    }
    to_int32_rows<Arch>(first, begin);
    to_int32_rows<Arch>(last, end);
  }

  // The strip's tile columns from its rows first_row .. last_row alone, in scalar arithmetic
  // apart from compute(), so that the walk's loop bounds do not wait for the vector spans.
  // t is computed as compute() computes it, and it is monotonic in the row (a sum and a
  // product, each rounded monotonically), so each edge's extreme t over the rows lies at
  // first_row or last_row. Hence:
  //  - no covered column lies outside [max over left edges of the smaller ceil(t),
  //    min over right edges of the larger ceil(t)): the tiles that can have covered samples;
  //  - every row covers [max over left edges of the larger ceil(t), min over right edges of
  //    the smaller ceil(t)) when a horizontal edge excludes neither end row: the tiles inside
  //    it are full (a row's span is exactly the intersection of its edges' half-planes).
  TileColumns columns(const double (&start)[3], int first_row, int last_row, double lo,
                      double hi) const {
    double outer_begin = lo, outer_end = hi, inner_begin = lo, inner_end = hi;
    for (int i = 0; i < 3; ++i) {
      const double t0 = start[i] + scalar_row_term_[i][first_row];
      const double t1 = start[i] + scalar_row_term_[i][last_row];
      const double low = t0 < t1 ? t0 : t1, high = t0 < t1 ? t1 : t0;
      if (i < kLefts) {
        outer_begin = std::max(outer_begin, std::ceil(low));
        inner_begin = std::max(inner_begin, std::ceil(high));
      } else if (i < kLefts + kRights) {
        outer_end = std::min(outer_end, std::ceil(high));
        inner_end = std::min(inner_end, std::ceil(low));
      } else {
        inner_end = low < 0.0 ? lo : inner_end;
      }
    }
    // Within [lo, hi] (lo >= 0), so the conversions are exact and shifts floor.
    const std::int32_t begin = static_cast<std::int32_t>(std::min(outer_begin, hi));
    const std::int32_t end = static_cast<std::int32_t>(std::max(outer_end, lo));
    const std::int32_t full_begin = static_cast<std::int32_t>(std::min(inner_begin, hi));
    const std::int32_t full_end = static_cast<std::int32_t>(std::max(inner_end, lo));
    TileColumns range{begin >> 3, (end + 7) >> 3, (full_begin + 7) >> 3, full_end >> 3};
    if (range.begin >= range.end) range.end = range.begin;
    if (range.full_begin >= range.full_end) range.full_begin = range.full_end = range.end;
    return range;
  }

  // Masks of the (up to) kBlockTiles tiles from relative column `column` (a multiple of 8),
  // the tiles from the count-th on left empty: each row's span is cut to the block as one
  // 24-bit word (2^n is exact in float for n <= 24), whose bytes are the tiles' rows.
  static void block_masks(const Ints* begin, const Ints* end, std::int32_t column,
                          std::int32_t count, std::uint64_t (&masks)[kBlockTiles]) {
    const std::int32_t width = kTileSize * (count < kBlockTiles ? count : kBlockTiles);
    Ints words[kIntParts];
    for (std::size_t h = 0; h < kIntParts; ++h) {
      const Ints zero(0), limit(width), at(column);
      const Ints lo = xsimd::min(xsimd::max(begin[h] - at, zero), limit);
      const Ints hi = xsimd::max(xsimd::min(end[h] - at, limit), lo);
      words[h] = power_of_two<Arch>(hi) - power_of_two<Arch>(lo);  // bits lo .. hi - 1
    }
    for (int tile = 0; tile < kBlockTiles; ++tile) {
      Ints bytes[kIntParts];
      for (std::size_t h = 0; h < kIntParts; ++h)
        bytes[h] = (words[h] >> (kTileSize * tile)) & Ints(0xFF);
      masks[tile] = low_bytes<Arch>(bytes);
    }
  }

 private:
  double scale_[3], offset_[3];        // t at a strip's first row: (G0 + offset) * scale
  Doubles row_term_[3][kDoubleParts];  // t at row k minus t at row 0
  alignas(64) double scalar_row_term_[3][kTileSize];  // the same, one row at a time
};

// The exactness argument above needs every non-horizontal edge to satisfy |b| < 2^20 |a|;
// nearly horizontal edges (over 4096 px long for a 1/256 px rise) take the tile walk.
inline bool span_walk_is_exact(const TriangleSetup& setup) {
  for (const EdgeSetup& edge : setup.edge) {
    const std::int64_t a = edge.a < 0 ? -std::int64_t{edge.a} : edge.a;
    const std::int64_t b = edge.b < 0 ? -std::int64_t{edge.b} : edge.b;
    if (a != 0 && b >= a << 20) return false;
  }
  return true;
}

// Hands on the masks of tile columns [first, last) of a strip, kBlockTiles at a time.
template <class Spans, class Visitor>
[[gnu::always_inline]] inline void deliver_blocks(const typename Spans::Ints* begin,
                                                  const typename Spans::Ints* end,
                                                  std::int32_t first, std::int32_t last,
                                                  std::uint32_t first_tile_x, std::uint32_t tile_y,
                                                  std::uint64_t rows, Visitor& visitor) {
  for (std::int32_t t = first; t < last; t += Spans::kBlockTiles) {
    std::uint64_t masks[Spans::kBlockTiles];
    Spans::block_masks(begin, end, t * kTileSize, last - t, masks);
    for (std::int32_t i = 0; i < Spans::kBlockTiles; ++i)
      deliver_tile(visitor, first_tile_x + t + i, tile_y, masks[i] & rows);
  }
}

// walk_spans() for one edge set (see StripSpans): calls visitor.tile() for partial tiles and
// visitor.full_tiles() for runs of whole tiles, in row order, like walk_tiles().
template <class Arch, int kLefts, int kRights, class Visitor>
[[gnu::always_inline]] inline void walk_spans_of(const TriangleSetup& setup, const int (&order)[3],
                                                 Visitor& visitor) {
  using Spans = StripSpans<Arch, kLefts, kRights>;
  const Spans spans(setup, order);
  const PixelRect& box = setup.box;
  // Columns relative to origin_x; G at column 0 of each strip steps by 8 b per strip.
  const double lo = box.x0 - setup.origin_x, hi = box.x1 - setup.origin_x;
  const std::uint32_t first_tile_x = static_cast<std::uint32_t>(setup.origin_x / kTileSize);
  double g0[3], g_step[3];
  for (int i = 0; i < 3; ++i) {
    g0[i] = static_cast<double>(setup.edge[order[i]].g);
    g_step[i] = kTileSize * static_cast<double>(setup.edge[order[i]].b);
  }
  typename Spans::Ints begin[Spans::kIntParts], end[Spans::kIntParts];

  for (std::int32_t ty = setup.origin_y; ty < box.y1; ty += kTileSize) {
    const int first_row = box.y0 > ty ? box.y0 - ty : 0;
    const int end_row = box.y1 - ty < kTileSize ? box.y1 - ty : kTileSize;
    const std::uint64_t rows = row_bits(first_row, end_row);
    double start[3];
    spans.starts(g0, start);
    spans.compute(start, lo, hi, begin, end);
    const TileColumns range = spans.columns(start, first_row, end_row - 1, lo, hi);
    const std::uint32_t tile_y = static_cast<std::uint32_t>(ty / kTileSize);
    deliver_blocks<Spans>(begin, end, range.begin, range.full_begin, first_tile_x, tile_y, rows,
                          visitor);
    if (range.full_begin < range.full_end) {
      visitor.full_tiles(first_tile_x + range.full_begin, first_tile_x + range.full_end, tile_y,
                         rows);
    }
    deliver_blocks<Spans>(begin, end, range.full_end, range.end, first_tile_x, tile_y, rows,
                          visitor);
    for (int i = 0; i < 3; ++i)
      g0[i] += g_step[i];
  }
}

// Calls walk.template operator()<kLefts, kRights>(order) for the triangle's edge set (see
// StripSpans), with `order` listing its edges as that set orders them: the one branch on the
// edges' signs per triangle.
template <class Walk>
[[gnu::always_inline]] inline void with_edge_set(const TriangleSetup& setup, const Walk& walk) {
  int order[3], lefts = 0, rights = 0;
  for (int e = 0; e < 3; ++e)
    lefts += setup.edge[e].a > 0;
  for (int e = 0; e < 3; ++e)
    rights += setup.edge[e].a < 0;
  int next_left = 0, next_right = lefts, next_horizontal = lefts + rights;
  for (int e = 0; e < 3; ++e) {
    const std::int32_t a = setup.edge[e].a;
    order[a > 0 ? next_left++ : (a < 0 ? next_right++ : next_horizontal++)] = e;
  }
  if (lefts == 2) {
    walk.template operator()<2, 1>(order);
  } else if (rights == 2) {
    walk.template operator()<1, 2>(order);
  } else {
    walk.template operator()<1, 1>(order);
  }
}

// Calls visitor.tile() for partial tiles and visitor.full_tiles() for runs of whole tiles, in
// row order, like walk_tiles().
template <class Arch, class Visitor>
[[gnu::noinline]] void walk_spans(const TriangleSetup& setup, Visitor& visitor) {
  with_edge_set(setup, [&]<int kLefts, int kRights>(const int(&order)[3]) {
    walk_spans_of<Arch, kLefts, kRights>(setup, order, visitor);
  });
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
