// The span walk: a triangle's clipped box in strips of 8 pixel rows. For each row of a strip the
// edges give the exact span of covered columns [L, R); a tile's mask is then read off the eight
// spans, whatever edges cross it, and tiles between the strip's spans are delivered whole. A
// visitor that only counts pixels takes the spans' lengths instead of masks.
//
// Integer edge stepping. Take a non-horizontal edge, G = G0 + a x + b r at column x and row r
// (both from the walk's origin; G >= 0 covers), and write A = |a|, N(r) = G0 + b r,
// F(r) = floor(N(r) / A) and E(r) = N(r) - A F(r), so 0 <= E < A. A left edge (a > 0) covers
// x >= -F(r): G >= 0 <=> x >= -N/A <=> x >= ceil(-N/A) = -F. A right edge (a < 0) covers
// x < F(r) + 1: G >= 0 <=> x <= N/A <=> x <= F. Eight rows down N grows by 8b = q A + s
// (floor division, 0 <= s < A): E + s lies in [0, 2A), so F grows by q + c and E becomes
// E + s - c A, with c = (E + s >= A). This is the scanline DDA (the quotient and remainder of
// the edge's x-step, carried exactly), run on the 8 rows of a strip as 8 int32 lanes.
//
// Ranges. span_walk_fits() admits a triangle only when every such edge has A < 2^22 and
// |N(r)| < 2^29 A at r = 0 and at r = (box.y1 - origin_y) + 16 (or, for a triangle whose tile
// walk fits in int32, A >= 4: then |N| < 2^31 <= 2^29 A on those rows); N is affine in r, so
// the bound holds on every row in between, which holds every row the walk steps to (the strips
// start at or below row 0, and the last one, plus the step past it, ends before box.y1 + 16).
// Hence |F| <= 2^29 and the boundaries -F and F + 1 lie within +-(2^29 + 1). With |b| < 2^25,
// |q| <= 8 |b| < 2^28 and s < A < 2^22; the lanes keep E - A in [-A, 0), and E - A + s in
// [-A, A) carries exactly when it is non-negative. Every int32 value stays far from overflow
// but the lanes' start, computed modulo 2^32 on purpose (StripSpans' constructor); N itself
// (|G0| < 2^42) is formed in int64. The triangles left out have an edge nearly horizontal for
// the box's height (more than 2^14 columns per row for a 2^15-row box), or one over 16384 px
// tall: they take the tile walk.
#pragma once

#include <algorithm>
#include <array>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "../simd/simd_ops-inl.hpp"
#include "tile_masks-inl.hpp"
#include "tile_walk-inl.hpp"
#include "triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// floor(n / d) for d > 0 (C++ division truncates toward zero).
template <class Int>
inline Int floor_divide(Int n, Int d) {
  const Int q = n / d;
  return q - (q * d > n ? 1 : 0);
}

// The edges of one triangle as the span walk steps them, ordered left edges (a > 0) first, then
// right edges (a < 0), then the horizontal edge if any. A triangle has one of three such edge
// sets (its a's sum to zero): two left and one right, one left and two right, or one of each
// kind and a horizontal edge, which only limits the rows (covered_rows()). The set is a template
// argument, so the strip loop tests no edge's sign.
template <class Arch, int kLefts, int kRights>
class StripSpans {
 public:
  using Ints = xsimd::batch<std::int32_t, Arch>;
  using Doubles = xsimd::batch<double, Arch>;
  static constexpr std::size_t kIntParts = kTileSize / Ints::size;
  static constexpr std::size_t kDoubleParts = kTileSize / Doubles::size;
  static constexpr int kEdges = kLefts + kRights;
  static constexpr std::int32_t kBlockTiles = 3;  // tiles whose masks are made at once

  // `order` lists the setup's edges in the order above; the first strip starts `first_row` rows
  // below the origin. Lane k's F at row first_row + k is floor((N + 1/2) / A), computed in
  // double: N + 1/2 is exact (|N| < 2^43), so the product with fl(1/A) errs by under
  // 2^-52 |(N + 1/2) / A| < 2^-23 (|N| < 2^29 A), less than the quotient's distance to the
  // nearest integer, at least 1 / (2A) > 2^-23 for A < 2^22; hence its floor is exact, and
  // floor((N + 1/2) / A) = floor(N / A) for an integer N. E - A = N - A (F + 1), whose true
  // value lies in [-A, 0), is then exact in int32 arithmetic modulo 2^32.
  StripSpans(const TriangleSetup& setup, const int (&order)[3], std::int32_t first_row) {
    alignas(64) static constexpr double kRowValue[kTileSize] = {0, 1, 2, 3, 4, 5, 6, 7};
    for (int i = 0; i < kEdges; ++i) {
      const EdgeSetup& edge = setup.edge[order[i]];
      const std::int32_t a = edge.a < 0 ? -edge.a : edge.a;
      const std::int64_t n0 = edge.g + std::int64_t{edge.b} * first_row;
      const Doubles inverse(1.0 / a), first(static_cast<double>(n0) + 0.5), b(edge.b);
      Doubles quotient[kDoubleParts];
      for (std::size_t h = 0; h < kDoubleParts; ++h) {
        // Exact either way, fused or not (b k and the sum need at most 45 bits).
        const Doubles n =
            xsimd::fma(b, Doubles::load_aligned(kRowValue + h * Doubles::size), first);
        quotient[h] = xsimd::floor(n * inverse);
      }
      Ints f[kIntParts];
      to_int32_rows<Arch>(quotient, f);
      for (std::size_t h = 0; h < kIntParts; ++h)
        x_[i][h] = i < kLefts ? -f[h] : f[h] + Ints(1);
      a_[i] = a;
      b_[i] = edge.b;
      n0_[i] = static_cast<std::int32_t>(n0);  // modulo 2^32
    }
  }

  // What step() needs besides the boundaries, apart so that a box of one strip skips it.
  [[gnu::always_inline]] void prepare_steps() {
    alignas(64) static constexpr std::int32_t kRow[kTileSize] = {0, 1, 2, 3, 4, 5, 6, 7};
    for (int i = 0; i < kEdges; ++i) {
      const std::int32_t a = a_[i];
      for (std::size_t h = 0; h < kIntParts; ++h) {
        const Ints k = Ints::load_aligned(kRow + h * Ints::size);
        const Ints n = Ints(n0_[i]) + k * Ints(b_[i]);               // |k b| < 2^28
        const Ints f1 = i < kLefts ? Ints(1) - x_[i][h] : x_[i][h];  // F + 1
        e_[i][h] = n - wrapping_multiply<Arch>(f1, Ints(a));         // modulo 2^32
      }
      const std::int32_t q8 = floor_divide(8 * b_[i], a);
      x_step_[i] = i < kLefts ? -q8 : q8;
      e_step_[i] = 8 * b_[i] - q8 * a;
    }
  }

  // The spans of the strip's 8 rows in columns from the origin: begin[] and end[], begin >= end
  // when a row is empty, clipped to begin >= lo and end <= hi only.
  [[gnu::always_inline]] void compute(std::int32_t lo, std::int32_t hi, Ints* begin,
                                      Ints* end) const {
    for (std::size_t h = 0; h < kIntParts; ++h) {
      begin[h] = Ints(lo);
      end[h] = Ints(hi);
      for (int i = 0; i < kEdges; ++i) {
        if (i < kLefts) {
          begin[h] = xsimd::max(begin[h], x_[i][h]);
        } else {
          end[h] = xsimd::min(end[h], x_[i][h]);
        }
      }
    }
  }

  // Moves every lane 8 rows down.
  [[gnu::always_inline]] void step() {
    for (int i = 0; i < kEdges; ++i) {
      for (std::size_t h = 0; h < kIntParts; ++h) {
        const Ints e = e_[i][h] + Ints(e_step_[i]);
        const Ints carry = mask_lanes<Arch>(e > Ints(-1));  // -1 where E + s >= A
        e_[i][h] = e - (carry & Ints(a_[i]));
        x_[i][h] += Ints(x_step_[i]);
        x_[i][h] = i < kLefts ? x_[i][h] + carry : x_[i][h] - carry;
      }
    }
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

  // The strip's tile columns from its spans over rows [first_row, end_row): no covered column
  // lies outside [smallest begin, largest end); every row covers [largest begin, smallest end),
  // so the tiles inside it are full (a row's span is exactly the row's covered samples).
  static TileColumns columns(const Ints* begin, const Ints* end, int first_row, int end_row,
                             std::int32_t lo, std::int32_t hi) {
    alignas(64) static constexpr std::int32_t kRow[kTileSize] = {0, 1, 2, 3, 4, 5, 6, 7};
    Ints outer_begin(hi), outer_end(lo), inner_begin(lo), inner_end(hi);
    const bool partial = first_row > 0 || end_row < kTileSize;  // only a box's first or last
    for (std::size_t h = 0; h < kIntParts; ++h) {
      Ints outer_b = begin[h], outer_e = end[h], inner_b = begin[h], inner_e = end[h];
      if (partial) {  // rows outside the box count neither way
        const Ints k = Ints::load_aligned(kRow + h * Ints::size);
        const auto valid = k >= Ints(first_row) && k < Ints(end_row);
        outer_b = xsimd::select(valid, outer_b, Ints(hi));
        outer_e = xsimd::select(valid, outer_e, Ints(lo));
        inner_b = xsimd::select(valid, inner_b, Ints(lo));
        inner_e = xsimd::select(valid, inner_e, Ints(hi));
      }
      outer_begin = xsimd::min(outer_begin, outer_b);
      outer_end = xsimd::max(outer_end, outer_e);
      inner_begin = xsimd::max(inner_begin, inner_b);
      inner_end = xsimd::min(inner_end, inner_e);
    }
    // Within [lo, hi] (lo >= 0), so shifts floor.
    const std::int32_t first = std::min(lane_min<Arch>(outer_begin), hi);
    const std::int32_t last = std::max(lane_max<Arch>(outer_end), lo);
    const std::int32_t full_first = std::min(lane_max<Arch>(inner_begin), hi);
    const std::int32_t full_last = std::max(lane_min<Arch>(inner_end), lo);
    TileColumns range{first >> 3, (last + 7) >> 3, (full_first + 7) >> 3, full_last >> 3};
    if (range.begin >= range.end) range.end = range.begin;
    if (range.full_begin >= range.full_end) range.full_begin = range.full_end = range.end;
    return range;
  }

  // Covered pixels of the strip's first `rows` rows (at most 8): the sum of the spans' lengths.
  [[gnu::always_inline]] static Ints lengths(const Ints* begin, const Ints* end, int rows) {
    alignas(64) static constexpr std::int32_t kRow[kTileSize] = {0, 1, 2, 3, 4, 5, 6, 7};
    Ints sum(0);
    for (std::size_t h = 0; h < kIntParts; ++h) {
      const Ints length = xsimd::max(end[h] - begin[h], Ints(0));
      sum +=
          rows >= kTileSize
              ? length
              : length & mask_lanes<Arch>(Ints::load_aligned(kRow + h * Ints::size) < Ints(rows));
    }
    return sum;
  }

 private:
  Ints x_[kEdges][kIntParts];  // each lane's boundary: -F (left edges) or F + 1 (right edges)
  Ints e_[kEdges][kIntParts];  // each lane's E - A, in [-A, 0): a carry makes it non-negative
  std::int32_t x_step_[kEdges], e_step_[kEdges], a_[kEdges], b_[kEdges], n0_[kEdges];
};

// A triangle's edge set (see StripSpans) and its edges in that set's order, by the signs of
// the edges' a: kEdgeSets[9 s0 + 3 s1 + s2] with s = 0 for a < 0, 1 for a = 0, 2 for a > 0.
struct EdgeSet {
  int lefts, rights;
  int order[3];
};

inline constexpr auto kEdgeSets = [] {
  std::array<EdgeSet, 27> sets{};
  for (int index = 0; index < 27; ++index) {
    const int signs[3] = {index / 9, index / 3 % 3, index % 3};
    EdgeSet& set = sets[static_cast<std::size_t>(index)];
    for (const int sign : signs) {
      set.lefts += sign == 2;
      set.rights += sign == 0;
    }
    int next_left = 0, next_right = set.lefts, next_horizontal = set.lefts + set.rights;
    for (int e = 0; e < 3; ++e)
      set.order[signs[e] == 2 ? next_left++ : (signs[e] == 0 ? next_right++ : next_horizontal++)] =
          e;
  }
  return sets;
}();

inline const EdgeSet& edge_set(const TriangleSetup& setup) {
  const auto sign = [](std::int32_t a) { return (a > 0) - (a < 0) + 1; };
  return kEdgeSets[static_cast<std::size_t>(9 * sign(setup.edge[0].a) + 3 * sign(setup.edge[1].a) +
                                            sign(setup.edge[2].a))];
}

// Admits a triangle to the span walk: see "Ranges" above, and every non-horizontal edge needs
// |a| < 2^22 (StripSpans' constructor; an edge under 16384 px tall). A narrow triangle (the
// tile walk's int32 analysis, triangle_setup-inl.hpp) has |N| < 2^31 on every row from the
// origin to 15 rows past its last tile row's first, which holds every row the walk steps to,
// so |a| >= 4 is enough there; other triangles are checked at the first and last rows.
inline constexpr std::int32_t kMaxSpanA = 1 << 22;

inline bool span_walk_fits(const TriangleSetup& setup) {
  if (setup.narrow) {
    bool fits = true;
    for (const EdgeSetup& edge : setup.edge)
      fits = fits & ((edge.a == 0) | ((edge.a >= 4) & (edge.a < kMaxSpanA)) |
                     ((edge.a <= -4) & (edge.a > -kMaxSpanA)));
    return fits;
  }
  const std::int64_t last_row = setup.box.y1 - setup.origin_y + 2 * kTileSize;
  for (const EdgeSetup& edge : setup.edge) {
    if (edge.a == 0) continue;
    if (edge.a >= kMaxSpanA || edge.a <= -kMaxSpanA) return false;
    const std::int64_t limit = std::int64_t{edge.a < 0 ? -edge.a : edge.a} << 29;
    const std::int64_t n0 = edge.g, n1 = edge.g + std::int64_t{edge.b} * last_row;
    if (n0 <= -limit || n0 >= limit || n1 <= -limit || n1 >= limit) return false;
  }
  return true;
}

// The box's rows [y0, y1) that the horizontal edge, if any, leaves covered (y0 == y1 when
// none): its G = G0 + b r is the same along a row, and covers r >= -floor(G0 / b) for b > 0,
// r <= floor(G0 / -b) for b < 0.
struct RowRange {
  std::int32_t y0, y1;
};
inline RowRange covered_rows(const TriangleSetup& setup, const EdgeSet& set) {
  if (set.lefts + set.rights == 3) return {setup.box.y0, setup.box.y1};
  const EdgeSetup& edge = setup.edge[set.order[2]];
  std::int64_t y0 = setup.box.y0, y1 = setup.box.y1;
  if (edge.b > 0) {
    y0 = std::max(y0, setup.origin_y - floor_divide<std::int64_t>(edge.g, edge.b));
  } else {
    y1 = std::min(y1,
                  setup.origin_y + floor_divide<std::int64_t>(edge.g, -std::int64_t{edge.b}) + 1);
  }
  y1 = std::max(y1, std::int64_t{setup.box.y0});
  return {static_cast<std::int32_t>(std::min(y0, y1)), static_cast<std::int32_t>(y1)};
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
[[gnu::always_inline]] inline void walk_spans_of(const TriangleSetup& setup, const EdgeSet& set,
                                                 RowRange rows, Visitor& visitor) {
  using Spans = StripSpans<Arch, kLefts, kRights>;
  // Strips on tile rows, from the one holding the first covered row.
  const std::int32_t first_ty = rows.y0 - ((rows.y0 - setup.origin_y) & (kTileSize - 1));
  Spans spans(setup, set.order, first_ty - setup.origin_y);
  spans.prepare_steps();
  const std::int32_t lo = setup.box.x0 - setup.origin_x, hi = setup.box.x1 - setup.origin_x;
  const std::uint32_t first_tile_x = static_cast<std::uint32_t>(setup.origin_x / kTileSize);
  typename Spans::Ints begin[Spans::kIntParts], end[Spans::kIntParts];
  for (std::int32_t ty = first_ty; ty < rows.y1; ty += kTileSize) {
    const int first_row = rows.y0 > ty ? rows.y0 - ty : 0;
    const int end_row = rows.y1 - ty < kTileSize ? rows.y1 - ty : kTileSize;
    const std::uint64_t row_mask = row_bits(first_row, end_row);
    spans.compute(lo, hi, begin, end);
    const TileColumns range = Spans::columns(begin, end, first_row, end_row, lo, hi);
    const std::uint32_t tile_y = static_cast<std::uint32_t>(ty / kTileSize);
    deliver_blocks<Spans>(begin, end, range.begin, range.full_begin, first_tile_x, tile_y, row_mask,
                          visitor);
    if (range.full_begin < range.full_end) {
      visitor.full_tiles(first_tile_x + range.full_begin, first_tile_x + range.full_end, tile_y,
                         row_mask);
    }
    deliver_blocks<Spans>(begin, end, range.full_end, range.end, first_tile_x, tile_y, row_mask,
                          visitor);
    spans.step();
  }
}

// walk_spans() for a visitor that only counts pixels: strips from the first covered row, each
// adding its spans' lengths; no mask is made.
template <class Arch, int kLefts, int kRights, class Visitor>
[[gnu::always_inline]] inline void count_spans_of(const TriangleSetup& setup, const EdgeSet& set,
                                                  RowRange rows, Visitor& visitor) {
  using Spans = StripSpans<Arch, kLefts, kRights>;
  using Ints = typename Spans::Ints;
  Spans spans(setup, set.order, rows.y0 - setup.origin_y);
  const std::int32_t lo = setup.box.x0 - setup.origin_x, hi = setup.box.x1 - setup.origin_x;
  Ints begin[Spans::kIntParts], end[Spans::kIntParts];
  Ints sum(0);  // at most 2^15 columns times 2^12 strips per lane
  std::int32_t left = rows.y1 - rows.y0;
  if (left > kTileSize) spans.prepare_steps();
  for (; left > kTileSize; left -= kTileSize) {
    spans.compute(lo, hi, begin, end);
    sum += Spans::lengths(begin, end, kTileSize);
    spans.step();
  }
  if (left > 0) {
    spans.compute(lo, hi, begin, end);
    sum += Spans::lengths(begin, end, left);
  }
  visitor.add_pixels(static_cast<std::uint64_t>(xsimd::hadd(sum)));
}

// walk_spans() for one edge set, out of line: the strip loop compiled once per set.
template <class Arch, int kLefts, int kRights, class Visitor>
[[gnu::noinline]] void walk_spans_as(const TriangleSetup& setup, const EdgeSet& set, RowRange rows,
                                     Visitor& visitor) {
  if constexpr (requires { visitor.add_pixels(std::uint64_t{}); }) {
    count_spans_of<Arch, kLefts, kRights>(setup, set, rows, visitor);
  } else {
    walk_spans_of<Arch, kLefts, kRights>(setup, set, rows, visitor);
  }
}

// Calls visitor.tile() for partial tiles and visitor.full_tiles() for runs of whole tiles, in
// row order, like walk_tiles(); or, for a visitor that only counts (add_pixels), hands it the
// number of covered pixels. Needs span_walk_fits().
template <class Arch, class Visitor>
inline void walk_spans(const TriangleSetup& setup, Visitor& visitor) {
  const EdgeSet& set = edge_set(setup);
  const RowRange rows = covered_rows(setup, set);
  if (rows.y0 >= rows.y1) return;
  if (set.lefts == 2) {
    walk_spans_as<Arch, 2, 1>(setup, set, rows, visitor);
  } else if (set.rights == 2) {
    walk_spans_as<Arch, 1, 2>(setup, set, rows, visitor);
  } else {
    walk_spans_as<Arch, 1, 1>(setup, set, rows, visitor);
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
