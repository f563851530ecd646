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

#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "simd_ops-inl.hpp"
#include "tile_masks-inl.hpp"
#include "triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class StripSpans {
 public:
  using Doubles = xsimd::batch<double, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  static constexpr std::size_t kDoubleParts = kTileSize / Doubles::size;
  static constexpr std::size_t kIntParts = kTileSize / Ints::size;

  explicit StripSpans(const TriangleSetup& setup) {
    alignas(64) static constexpr double kRow[kTileSize] = {0, 1, 2, 3, 4, 5, 6, 7};
    for (int e = 0; e < 3; ++e) {
      const EdgeSetup& edge = setup.edge[e];
      // Horizontal edges step G itself (exact); the others step t (see above).
      scale_[e] = edge.a != 0 ? -1.0 / edge.a : 1.0;
      offset_[e] = edge.a != 0 ? 0.5 : 0.0;
      const Doubles step(edge.a != 0 ? edge.b * scale_[e] : static_cast<double>(edge.b));
      for (std::size_t h = 0; h < kDoubleParts; ++h) {
        row_term_[e][h] = step * Doubles::load_aligned(kRow + h * Doubles::size);
      }
    }
  }

  // Spans of the 8 rows from a strip's first row, in columns from the box's first tile:
  // begin[] and end[] (begin >= end when a row is empty). `g0` is each edge's G at the strip's
  // first row and first tile column; [lo, hi) the box's columns.
  void compute(const TriangleSetup& setup, const double g0[3], double lo, double hi, Ints* begin,
               Ints* end) const {
    Doubles first[kDoubleParts], last[kDoubleParts];  // last is exclusive
    for (std::size_t h = 0; h < kDoubleParts; ++h) {
      first[h] = Doubles(lo);
      last[h] = Doubles(hi);
    }
    for (int e = 0; e < 3; ++e) {
      const std::int32_t a = setup.edge[e].a;
      const Doubles start((g0[e] + offset_[e]) * scale_[e]);
      for (std::size_t h = 0; h < kDoubleParts; ++h) {
        const Doubles t = start + row_term_[e][h];
        if (a > 0) {
          first[h] = xsimd::max(first[h], xsimd::ceil(t));
        } else if (a < 0) {
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

  // Mask of the tile whose first column is `column` (relative, a multiple of 8).
  static std::uint64_t tile_mask(const Ints* begin, const Ints* end, std::int32_t column) {
    Ints bytes[kIntParts];
    for (std::size_t h = 0; h < kIntParts; ++h) {
      const Ints zero(0), eight(kTileSize), at(column);
      const Ints lo = xsimd::min(xsimd::max(begin[h] - at, zero), eight);
      const Ints hi = xsimd::max(xsimd::min(end[h] - at, eight), lo);
      bytes[h] = power_of_two<Arch>(hi) - power_of_two<Arch>(lo);  // bits lo .. hi - 1
    }
    return low_bytes<Arch>(bytes);
  }

 private:
  double scale_[3], offset_[3];        // t at a strip's first row: (G0 + offset) * scale
  Doubles row_term_[3][kDoubleParts];  // t at row k minus t at row 0
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

// Calls visitor.tile() for partial tiles and visitor.full_tiles() for runs of whole tiles, in
// row order, like walk_tiles().
template <class Arch, class Visitor>
[[gnu::noinline]] void walk_spans(const TriangleSetup& setup, Visitor& visitor) {
  using Spans = StripSpans<Arch>;
  const Spans spans(setup);
  const PixelRect& box = setup.box;
  // Columns relative to origin_x; G at column 0 of each strip steps by 8 b per strip.
  const double lo = box.x0 - setup.origin_x, hi = box.x1 - setup.origin_x;
  const std::uint32_t first_tile_x = static_cast<std::uint32_t>(setup.origin_x / kTileSize);
  double g0[3];
  for (int e = 0; e < 3; ++e)
    g0[e] = static_cast<double>(setup.edge[e].g);
  alignas(64) static constexpr std::int32_t kRowIndex[kTileSize] = {0, 1, 2, 3, 4, 5, 6, 7};
  typename Spans::Ints begin[Spans::kIntParts], end[Spans::kIntParts];

  for (std::int32_t ty = setup.origin_y; ty < box.y1; ty += kTileSize) {
    const int first_row = box.y0 > ty ? box.y0 - ty : 0;
    const int end_row = box.y1 - ty < kTileSize ? box.y1 - ty : kTileSize;
    const std::uint64_t rows = row_bits(first_row, end_row);
    spans.compute(setup, g0, lo, hi, begin, end);
    // Over the rows inside the box: the union of the spans, and their intersection. Spans lie
    // in [lo, hi], far inside +-kUnused, so negated ends take maxima as minima.
    using Ints = typename Spans::Ints;
    constexpr std::int32_t kUnused = 1 << 30;
    Ints bounds[4] = {Ints(kUnused), Ints(kUnused), Ints(kUnused), Ints(kUnused)};
    for (std::size_t h = 0; h < Spans::kIntParts; ++h) {
      const Ints row = Ints::load_aligned(kRowIndex + h * Ints::size);
      const auto in_box = row >= Ints(first_row) && row < Ints(end_row);
      const auto covered = in_box && begin[h] < end[h];
      bounds[0] = xsimd::min(bounds[0], xsimd::select(covered, begin[h], Ints(kUnused)));
      bounds[1] = xsimd::min(bounds[1], xsimd::select(covered, -end[h], Ints(kUnused)));
      bounds[2] = xsimd::min(bounds[2], xsimd::select(in_box, -begin[h], Ints(kUnused)));
      bounds[3] = xsimd::min(bounds[3], xsimd::select(in_box, end[h], Ints(kUnused)));
    }
    std::int32_t minima[4];
    horizontal_min4<Arch>(bounds, minima);
    const std::int32_t union_begin = minima[0], union_end = -minima[1];
    const std::int32_t common_begin = -minima[2], common_end = minima[3];
    if (union_begin < union_end) {
      const std::int32_t tile_begin = union_begin >> 3, tile_end = (union_end + 7) >> 3;
      std::int32_t full_begin = (common_begin + 7) >> 3, full_end = common_end >> 3;
      if (full_begin >= full_end) full_begin = full_end = tile_end;
      const std::uint32_t tile_y = static_cast<std::uint32_t>(ty / kTileSize);
      for (std::int32_t t = tile_begin; t < full_begin; ++t) {
        const std::uint64_t mask = Spans::tile_mask(begin, end, t * kTileSize) & rows;
        if (mask != 0) visitor.tile(first_tile_x + t, tile_y, mask);
      }
      if (full_begin < full_end) {
        visitor.full_tiles(first_tile_x + full_begin, first_tile_x + full_end, tile_y, rows);
      }
      for (std::int32_t t = full_end; t < tile_end; ++t) {
        const std::uint64_t mask = Spans::tile_mask(begin, end, t * kTileSize) & rows;
        if (mask != 0) visitor.tile(first_tile_x + t, tile_y, mask);
      }
    }
    for (int e = 0; e < 3; ++e)
      g0[e] += kTileSize * static_cast<double>(setup.edge[e].b);
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
