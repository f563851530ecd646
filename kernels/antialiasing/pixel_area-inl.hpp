// Exact-area coverage (edgewise/pixel_area.hpp): the area of each pixel's square inside a
// snapped triangle.
//
// Signed area accumulation, kLanes consecutive pixels of a row at a time (one per double lane,
// the group aligned so that it never straddles a tile): in the row's frame (a band one pixel
// high, y down from its top, in pixels) every edge P -> Q adds, for the pixel column [u, u + 1],
//     I = integral over x in [lo, hi] of clamp(y(x), 0, 1) dx,
// lo and hi being the edge's x extent [L, H] clamped to the column, with the sign of Q_x - P_x;
// the bottom edges minus the top edges give the covered length of each column of the square,
// so |sum of I| is the area (the winding gives the sign, folded into each edge's weights).
//
// No division per pixel: where y rises with x, clamp(y) is 0 left of A (the x where the edge's
// line crosses the band's top), 1 right of B (where it crosses the bottom), and (x - A) s in
// between, s = dy / dx. With a and b, A and B clamped to [lo, hi] (that is, clamped to [L, H]
// once per row, then to the column),
//     I = (hi - b) + (b - a) ((a + b) - 2 A) s / 2.
// Where y falls with x, the same holds for 1 - y, whose A and B are the crossings of the bottom
// and the top: I = (hi - lo) - I' = (b - lo) - ramp. So an edge costs a lane 13 operations
// (three clamps of two operations, three differences, a sum, a product, two multiply-adds), with A,
// B and s / 2 found once per row (A = P_x + (row's y - P_y) dx / dy) or per triangle. The formula
// holds in every row; where an edge does not reach the row's band it reduces to (hi - lo) (the edge
// lies below) or 0 (above), exactly, which a row of candidates takes as such. A horizontal edge
// adds clamp(y) (hi - lo); a vertical one nothing.
//
// Which pixels: a box at most kBoxWalkMaxGroups groups wide is computed whole (walk_box), and
// there a pixel's area is the difference F(u + 1) - F(u) of the row's integral of covered
// height from the box's left, F, taken once per lane (9 operations per edge; walk_box gives
// F). In a wider box, per row each edge's piece inside the band spans a range of pixels: the
// candidates, computed by groups with I above. Between the leftmost and the rightmost
// candidate, a pixel that no piece touches lies wholly inside (the triangle's section of the
// band is convex and reaches both sides of it): its area is 1 without arithmetic. Masks are
// kept as the areas are stored.
//
// Error (the tolerance of pixel_area.hpp), in pixels, x measured from the left side of the
// box's first tile (0 <= u < 2^15 + 8), eps = 2^-53:
// - u, L, H, P and so lo, hi and the clamps X of L or H are exact (multiples of 1/256 below
//   2^17); y - P_y is exact. X - b and b - a are exact (two numbers of [u, u + 1], u >= 1) or
//   within eps of it (u = 0).
// - A (and B) matters only where it falls inside [lo, hi], hence inside the edge's extent: then
//   |A - P_x| <= |dx| < 2^16, and dx / dy, its product (or the fused multiply-add) and the sum
//   err by at most 2^-35.5 in all. Elsewhere only its side of [lo, hi] matters, which such an
//   error cannot change; and where A lies far outside but the ramp still reaches the column
//   (b > a), |A - P_x| <= |dx| + 1 / |s| and its error times |s| (b - a) <= 1 + 2^-10 below stays
//   under 2^-35.
// - The edge's sum is f(a, b, A) = (X - b) + (b - a) ((a + b) - 2 A) s / 2 (signed), with
//   |df/db| = |2 (b - A) s / 2 - 1| <= 1, |df/da| = |(a - A) s| <= 1 and |df/dA| = |(b - a) s| <=
//   1 + 2^-10 (b - a exceeds the ramp's width 1 / |s| by at most twice the error of A, B, and
//   |s| < 2^24): at most 3.01 * 2^-35.5 from a, b and A; the roundings of (a + b) (2^-37 times
//   |(b - a) s / 2| <= 1) and of the rest (a few eps) add below 2^-36.
// - The box walk's F(u + 1) - F(u) is the same integral I. There x lies in [0, 64]
//   (kBoxWalkReach) and the row's constants are clamped to it (set_up_box_rows()), so every
//   term of F lies in [0, 64] and F below 2^9: its roundings add at most 2^-40, the
//   difference's 2^-39; A, B and A' - 2 A enter as above (where the edge misses the row,
//   p = A' = B' and the ramp term is exactly 0).
// Per edge below 2^-33.6, three edges and their sum below 2^-32; areas at most 2^-32
// (kAreaRoundOff) are reported as 0, which removes all round-off where the triangle does not
// reach and misses a true sliver that small by at most as much; the rounding to float adds
// 2^-25. In all below 2^-24.9 px^2 < 1e-6.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include <xsimd/xsimd.hpp>

#include "edgewise/pixel_area.hpp"
#include "../simd/lane_arch-inl.hpp"
#include "../simd/simd_ops-inl.hpp"
#include "pixel_area_box-inl.hpp"
#include "pixel_area_edges-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

namespace area_walk_detail {

// Tiles not yet touched in the current tile row.
inline constexpr std::uint16_t kUntouched = 0xFFFF;

// Between the row's first candidate and its last, pixels no piece touches are whole: the row r
// of each tile that [span_first, span_end) reaches starts as 1 there and 0 elsewhere (a tile is
// cleared when first reached), and the candidates' areas replace it.
template <class Arch>
[[gnu::always_inline]] inline void fill_whole_span(AreaTile* tiles, std::int32_t span_first,
                                                   std::int32_t span_end, int r,
                                                   std::uint32_t triangle,
                                                   std::int32_t first_tile_x, std::int32_t ty) {
  using Floats = xsimd::batch<float, Arch>;
  constexpr int kFloatLanes = static_cast<int>(Floats::size);
  for (std::int32_t c = span_first / kTileSize; c <= (span_end - 1) / kTileSize; ++c) {
    AreaTile& tile = tiles[c];
    if (tile.tile_y == kUntouched) clear_area_tile<Arch>(tile, triangle, first_tile_x + c, ty);
    const std::int32_t from = span_first - c * kTileSize, to = span_end - c * kTileSize;
    float* row = tile.area + r * kTileSize;
    if (from <= 0 && to >= kTileSize) {
      for (int k = 0; k < kTileSize; k += kFloatLanes)
        Floats(1.0f).store_unaligned(row + k);
      tile.mask |= std::uint64_t{0xFF} << (r * kTileSize);
      continue;
    }
    const std::uint32_t whole =
        (0xFFu >> (to < kTileSize ? kTileSize - to : 0)) & (0xFFu << (from > 0 ? from : 0));
    for (int k = 0; k < kTileSize; k += kFloatLanes) {
      xsimd::select(lanes_of_bits<Arch>(whole >> k), Floats(1.0f), Floats(0.0f))
          .store_unaligned(row + k);
    }
    tile.mask |= std::uint64_t{whole} << (r * kTileSize);
  }
}

// The candidates of each edge in row r, [first[e], end[e]), clipped to [x_begin, x_end); returns
// the span from the first candidate to the end of the last.
inline std::pair<std::int32_t, std::int32_t> row_candidates(const TileRowBands& bands, int r,
                                                            std::int32_t x_begin,
                                                            std::int32_t x_end,
                                                            std::int32_t (&first)[3],
                                                            std::int32_t (&end)[3]) {
  for (int e = 0; e < 3; ++e) {
    const std::int32_t f = static_cast<std::int32_t>(bands.first[e][r]);
    const std::int32_t l = static_cast<std::int32_t>(bands.last[e][r]) + 1;
    first[e] = f > x_begin ? f : x_begin;
    end[e] = l < x_end ? l : x_end;
  }
  std::int32_t span_first = first[0] < first[1] ? first[0] : first[1];
  span_first = first[2] < span_first ? first[2] : span_first;
  std::int32_t span_end = end[0] > end[1] ? end[0] : end[1];
  span_end = end[2] > span_end ? end[2] : span_end;
  return {span_first, span_end};
}

// Row r's edges into `row_edges`, those with a ramp first; returns their counts.
struct RowEdgeCounts {
  int ramps = 0, wholes = 0;
};
template <class Arch>
[[gnu::always_inline]] inline RowEdgeCounts load_row_edges(const TileRowBands& bands,
                                                           const AreaEdge (&edges)[3], int r,
                                                           RowEdges<Arch>& row_edges) {
  using Doubles = xsimd::batch<double, Arch>;
  RowEdgeCounts counts;
  for (int e = 0; e < 3; ++e) {
    if (bands.ramp[e][r] != 0.0) {
      const AreaEdge& edge = edges[e];
      const int i = counts.ramps++;
      row_edges.extent[i] = Doubles(edge.rising ? edge.right : edge.left);
      row_edges.start[i] = Doubles(bands.start[e][r]);
      row_edges.end[i] = Doubles(bands.end[e][r]);
      row_edges.twice_start[i] = Doubles(bands.twice_start[e][r]);
      row_edges.upper[i] = Doubles(edge.upper_weight);
      row_edges.ramp[i] = Doubles(edge.ramp_weight);
    } else if (bands.whole[e][r] != 0.0) {
      const int i = counts.wholes++;
      row_edges.left[i] = Doubles(edges[e].left);
      row_edges.right[i] = Doubles(edges[e].right);
      row_edges.whole[i] = Doubles(bands.whole[e][r]);
    }
  }
  return counts;
}

// f.template operator()<ramps, wholes>() for the row's edge counts: the one place they become
// template arguments.
template <class F>
[[gnu::always_inline]] inline void with_edge_counts(RowEdgeCounts counts, F&& f) {
  switch (counts.ramps * 4 + counts.wholes) {
    case 0 * 4 + 1:
      return f.template operator()<0, 1>();
    case 0 * 4 + 2:
      return f.template operator()<0, 2>();
    case 0 * 4 + 3:
      return f.template operator()<0, 3>();
    case 1 * 4 + 0:
      return f.template operator()<1, 0>();
    case 1 * 4 + 1:
      return f.template operator()<1, 1>();
    case 1 * 4 + 2:
      return f.template operator()<1, 2>();
    case 2 * 4 + 0:
      return f.template operator()<2, 0>();
    case 2 * 4 + 1:
      return f.template operator()<2, 1>();
    case 3 * 4 + 0:
      return f.template operator()<3, 0>();
    default:
      return f.template operator()<0, 0>();
  }
}

}  // namespace area_walk_detail

// Walks a triangle's box a tile row at a time and hands its tiles to `emit` (AreaTile&) in row
// order. The tiles of a row are made in the caller's storage: storage.row(columns) gives room
// for `columns` tiles, which stays valid until the row's tiles have been emitted (so a caller
// can hand out rows of its own output buffer, and emit without copying).
template <class Arch, class Storage, class Emit>
void walk_areas(const AreaTriangle& tri, const PixelRect& box, Storage& storage,
                std::uint32_t triangle, Emit&& emit) {
  constexpr std::int32_t kGroupWidth =
      static_cast<std::int32_t>(xsimd::batch<double, WideArch<Arch>>::size);
  if ((box.x1 - 1) / kGroupWidth - box.x0 / kGroupWidth < kBoxWalkMaxGroups) {
    walk_box<Arch>(tri, box, storage, triangle, emit);
    return;
  }
  using Wide = WideArch<Arch>;
  using Doubles = xsimd::batch<double, Wide>;
  constexpr std::int32_t kLanes = static_cast<std::int32_t>(Doubles::size);
  static_assert(kTileSize % kLanes == 0, "a group of lanes never straddles a tile");
  constexpr std::uint64_t kGroupBits = (std::uint64_t{1} << kLanes) - 1;
  using area_walk_detail::kUntouched;
  const std::int32_t first_tile_x = box.x0 / kTileSize;
  const std::int32_t origin = first_tile_x * kTileSize;
  const std::int32_t x_begin = box.x0 - origin, x_end = box.x1 - origin;
  const std::int32_t columns = (box.x1 - 1) / kTileSize - first_tile_x + 1;
  AreaEdge edges[3];
  set_up_area_edges(tri, origin, edges);
  const Doubles lane_columns = lane_offsets<Wide>();
  const Doubles box_begin(static_cast<double>(x_begin)), box_end(static_cast<double>(x_end));
  TileRowBands bands;
  RowEdges<Wide> row_edges;
  for (std::int32_t ty = box.y0 / kTileSize; ty <= (box.y1 - 1) / kTileSize; ++ty) {
    const int r_begin = box.y0 > ty * kTileSize ? box.y0 - ty * kTileSize : 0;
    const int r_end = box.y1 < (ty + 1) * kTileSize ? box.y1 - ty * kTileSize : kTileSize;
    set_up_bands<Wide>(edges, ty * kTileSize, r_begin, r_end, static_cast<double>(x_end), bands);
    AreaTile* const tiles = storage.row(columns);
    for (std::int32_t c = 0; c < columns; ++c)
      tiles[c].tile_y = kUntouched;
    for (int r = r_begin; r < r_end; ++r) {
      std::int32_t first[3], end[3];
      const auto [span_first, span_end] =
          area_walk_detail::row_candidates(bands, r, x_begin, x_end, first, end);
      if (span_first >= span_end) continue;
      area_walk_detail::fill_whole_span<Arch>(tiles, span_first, span_end, r, triangle,
                                              first_tile_x, ty);
      const area_walk_detail::RowEdgeCounts counts =
          area_walk_detail::load_row_edges<Wide>(bands, edges, r, row_edges);
      // The candidates in x order: groups of lanes computed once.
      const auto order = [&](int i, int j) {
        if (first[j] < first[i]) {
          std::swap(first[i], first[j]);
          std::swap(end[i], end[j]);
        }
      };
      order(0, 1);
      order(1, 2);
      order(0, 1);
      const auto compute = [&]<int kRamp, int kWhole>() {
        std::int32_t computed_to = 0;  // groups below this are computed (aligned)
        for (int e = 0; e < 3; ++e) {
          std::int32_t x = first[e] - first[e] % kLanes;
          x = x > computed_to ? x : computed_to;
          for (; x < end[e]; x += kLanes) {
            // x >= 0: the tile and the column by shifts.
            const auto column = static_cast<std::uint32_t>(x);
            AreaTile& tile = tiles[column / kTileSize];
            const Doubles area = row_areas<kRamp, kWhole>(
                row_edges, Doubles(static_cast<double>(x)) + lane_columns, box_begin, box_end);
            const std::uint32_t at = static_cast<std::uint32_t>(r) * kTileSize + column % kTileSize;
            store_as_floats(area, tile.area + at);
            tile.mask =
                (tile.mask & ~(kGroupBits << at)) | (std::uint64_t{positive_lanes(area)} << at);
          }
          computed_to = x > computed_to ? x : computed_to;
        }
      };
      area_walk_detail::with_edge_counts(counts, compute);
    }
    for (std::int32_t c = 0; c < columns; ++c) {
      if (tiles[c].tile_y != kUntouched && tiles[c].mask != 0) emit(tiles[c]);
    }
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
