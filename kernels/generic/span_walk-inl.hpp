// The span walk: a triangle's clipped box in strips of 8 pixel rows (one tile row). For each
// row of a strip the three edge functions give the exact span of covered columns [L, R):
// a left edge (a > 0) covers x from ceil(-G0 / a), a right edge (a < 0) up to floor(G0 / -a),
// where G0 is the edge's G at the box's first tile column. A tile's mask is then read off the
// eight spans, whatever edges cross it; tiles between the strip's spans are delivered whole.
//
// Exactness: G0 is an integer below 2^42 and a a nonzero integer below 2^25, both exact in
// double. An integer quotient divides exactly; any other lies at least 1/|a| >= 2^-25 from an
// integer, while the division errs by at most |q| 2^-53 <= 2^-37 for |q| <= 2^16 (every
// column of the guard band). Quotients beyond that are clamped to the box either way, so
// ceil() and floor() of the double quotient are the exact integer bounds.
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
      const Doubles b(setup.edge[e].b);
      for (std::size_t h = 0; h < kDoubleParts; ++h) {
        row_offset_[e][h] = b * Doubles::load_aligned(kRow + h * Doubles::size);
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
      const double a = setup.edge[e].a;
      const Doubles start(g0[e]);
      for (std::size_t h = 0; h < kDoubleParts; ++h) {
        const Doubles g = start + row_offset_[e][h];
        if (a > 0) {
          first[h] = xsimd::max(first[h], xsimd::ceil(-g / Doubles(a)));
        } else if (a < 0) {
          last[h] = xsimd::min(last[h], xsimd::floor(g / Doubles(-a)) + Doubles(1.0));
        } else {  // horizontal: the whole row is in or out
          last[h] = xsimd::select(g < Doubles(0.0), Doubles(lo), last[h]);
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
  Doubles row_offset_[3][kDoubleParts];  // b * row
};

// Calls visitor.tile() for partial tiles and visitor.full_tiles() for runs of whole tiles, in
// row order, like walk_tiles().
template <class Arch, class Visitor>
void walk_spans(const TriangleSetup& setup, Visitor& visitor) {
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
    // Over the rows inside the box: the union of the spans, and their intersection.
    using Ints = typename Spans::Ints;
    Ints union_begin_lanes(INT32_MAX), union_end_lanes(INT32_MIN);
    Ints common_begin_lanes(INT32_MIN), common_end_lanes(INT32_MAX);
    for (std::size_t h = 0; h < Spans::kIntParts; ++h) {
      const Ints row = Ints::load_aligned(kRowIndex + h * Ints::size);
      const auto in_box = row >= Ints(first_row) && row < Ints(end_row);
      const auto covered = in_box && begin[h] < end[h];
      union_begin_lanes =
          xsimd::min(union_begin_lanes, xsimd::select(covered, begin[h], Ints(INT32_MAX)));
      union_end_lanes =
          xsimd::max(union_end_lanes, xsimd::select(covered, end[h], Ints(INT32_MIN)));
      common_begin_lanes =
          xsimd::max(common_begin_lanes, xsimd::select(in_box, begin[h], Ints(INT32_MIN)));
      common_end_lanes =
          xsimd::min(common_end_lanes, xsimd::select(in_box, end[h], Ints(INT32_MAX)));
    }
    const std::int32_t union_begin = horizontal_min<Arch>(union_begin_lanes);
    const std::int32_t union_end = horizontal_max<Arch>(union_end_lanes);
    const std::int32_t common_begin = horizontal_max<Arch>(common_begin_lanes);
    const std::int32_t common_end = horizontal_min<Arch>(common_end_lanes);
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
