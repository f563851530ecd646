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
#include "../simd/double_lanes-inl.hpp"
#include "../simd/lane_arch-inl.hpp"
#include "../simd/simd_ops-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

static_assert(kTileSize == 8, "a tile's row of areas is one byte of its mask");

// A triangle's snapped vertices (fixed point), as the input gives them.
struct AreaTriangle {
  std::int64_t x[3], y[3];
  double orientation;  // -1 where twice the signed area is positive (clockwise), else 1
};

// Areas up to this are reported as 0: it bounds the round-off where the triangle does not reach
// (the error analysis above); a true sliver that small is within the tolerance of 0.
inline constexpr double kAreaRoundOff = 0x1p-32;

// One edge of a triangle, in pixels, x from the walk's origin (the left side of the box's first
// tile).
struct AreaEdge {
  double left, right;       // x extent (exact)
  double x0, y0;            // P, its x from the origin and its y (exact)
  double inverse_slope;     // dx / dy; 0 for a horizontal edge
  double y_low, y_high;     // y extent (exact)
  double no_ramp;           // kNoRamp for a horizontal edge, else 0
  bool horizontal, rising;  // dy = 0; y grows with x
  // The signed weights of (X - b) and (b - a) ((a + b) - 2 A) in the area (RowEdges).
  double upper_weight, ramp_weight;
  double sign;  // of dx, times the winding
};

// Added to a horizontal edge's crossings (which it has none of): its ramp lies beyond every
// pixel, and its piece in a band spans its whole extent.
inline constexpr double kNoRamp = 0x1p60;

// The triangle's edges from its vertices, x measured from origin_x (pixels).
inline void set_up_area_edges(const AreaTriangle& tri, std::int32_t origin_x, AreaEdge* edges) {
  const std::int64_t origin = std::int64_t{origin_x} * 256;
  for (int e = 0; e < 3; ++e) {
    const int j = e == 2 ? 0 : e + 1;
    const std::int64_t dx = tri.x[j] - tri.x[e], dy = tri.y[j] - tri.y[e];
    AreaEdge& edge = edges[e];
    edge.left = static_cast<double>((dx < 0 ? tri.x[j] : tri.x[e]) - origin) / 256.0;
    edge.right = static_cast<double>((dx < 0 ? tri.x[e] : tri.x[j]) - origin) / 256.0;
    edge.x0 = static_cast<double>(tri.x[e] - origin) / 256.0;
    edge.y0 = static_cast<double>(tri.y[e]) / 256.0;
    edge.y_low = static_cast<double>(dy < 0 ? tri.y[j] : tri.y[e]) / 256.0;
    edge.y_high = static_cast<double>(dy < 0 ? tri.y[e] : tri.y[j]) / 256.0;
    edge.horizontal = dy == 0;
    edge.no_ramp = edge.horizontal ? kNoRamp : 0.0;
    edge.rising = (dx > 0) == (dy > 0);
    edge.inverse_slope = dy == 0 ? 0.0 : static_cast<double>(dx) / static_cast<double>(dy);
    edge.sign = dx == 0 ? 0.0 : (dx > 0 ? tri.orientation : -tri.orientation);
    // A vertical edge spans no x (lo = hi): it adds nothing, whatever its weights.
    const double half_slope =
        dx == 0 || dy == 0 ? 0.0
                           : std::fabs(static_cast<double>(dy) / static_cast<double>(dx)) / 2.0;
    const double orient = edge.horizontal || edge.rising ? 1.0 : -1.0;  // I or (hi - lo) - I'
    edge.upper_weight = edge.horizontal ? 0.0 : orient * edge.sign;
    edge.ramp_weight = orient * edge.sign * half_slope;
  }
}

// Pixel ranges are widened by this (pixels) each way: far more than the crossings' error
// (2^-35.5), so a pixel a piece touches is never left out; a pixel it only grazes gets its area
// computed, which is exact too.
inline constexpr double kRangeMargin = 1.0 / 256.0;

// The rows of one tile row, per edge and row. An edge that reaches the row's band has a ramp:
// [start, end] clamped to the edge's extent, and 2 A from the line itself; one wholly below the
// band adds whole (hi - lo) (so does a horizontal edge, with whole its clamped height); one
// above adds nothing (whole = 0). [first, last]: the pixels the edge's piece in the band
// touches, from the origin (first > last where it has none).
struct TileRowBands {
  alignas(64) double start[3][kTileSize];
  alignas(64) double end[3][kTileSize];
  alignas(64) double twice_start[3][kTileSize];
  alignas(64) double whole[3][kTileSize];
  alignas(64) double ramp[3][kTileSize];  // 1 where the edge has a ramp, else 0
  alignas(64) double first[3][kTileSize];
  alignas(64) double last[3][kTileSize];
};

// Fills `bands` for rows top_row + r_begin .. top_row + r_end - 1, kLanes rows at a time.
template <class Arch>
void set_up_bands(const AreaEdge* edges, std::int32_t top_row, int r_begin, int r_end, double width,
                  TileRowBands& bands) {
  using Doubles = xsimd::batch<double, Arch>;
  constexpr int kLanes = static_cast<int>(Doubles::size);
  alignas(64) double offsets[kLanes];
  for (int l = 0; l < kLanes; ++l)
    offsets[l] = static_cast<double>(l);
  const Doubles lane_rows = Doubles::load_aligned(offsets);
  const Doubles zero(0.0), one(1.0);
  for (int e = 0; e < 3; ++e) {
    const AreaEdge& edge = edges[e];
    const Doubles left(edge.left), right(edge.right), no_ramp(edge.no_ramp);
    for (int k = r_begin - r_begin % kLanes; k < r_end; k += kLanes) {
      const Doubles top_y = Doubles(static_cast<double>(top_row + k)) + lane_rows;
      const Doubles bottom_y = top_y + one;
      const Doubles top =
          xsimd::fma(top_y - Doubles(edge.y0), Doubles(edge.inverse_slope), Doubles(edge.x0));
      const Doubles bottom =
          xsimd::fma(bottom_y - Doubles(edge.y0), Doubles(edge.inverse_slope), Doubles(edge.x0));
      const Doubles ramp_start = (edge.rising ? top : bottom) + no_ramp;
      const Doubles ramp_end = (edge.rising ? bottom : top) + no_ramp;
      xsimd::min(xsimd::max(ramp_start, left), right).store_aligned(&bands.start[e][k]);
      xsimd::min(xsimd::max(ramp_end, left), right).store_aligned(&bands.end[e][k]);
      (ramp_start + ramp_start).store_aligned(&bands.twice_start[e][k]);
      const auto reaches = (Doubles(edge.y_low) <= bottom_y) & (Doubles(edge.y_high) >= top_y);
      const auto below = Doubles(edge.y_low) > bottom_y;
      Doubles whole = xsimd::select(below, Doubles(edge.sign), zero);
      Doubles ramp = xsimd::select(reaches, one, zero);
      if (edge.horizontal) {
        whole = xsimd::min(xsimd::max(Doubles(edge.y0) - top_y, zero), one) * Doubles(edge.sign);
        ramp = zero;
      } else if (edge.sign == 0.0) {
        ramp = zero;  // vertical: no x extent, nothing to add
      }
      whole.store_aligned(&bands.whole[e][k]);
      ramp.store_aligned(&bands.ramp[e][k]);
      // The piece's x extent: the line's over the band, within the edge's (all of it when
      // horizontal); none where the edge does not reach the band.
      const Doubles piece_left =
          xsimd::max(xsimd::min(top, bottom) - no_ramp, left) - Doubles(kRangeMargin);
      const Doubles piece_right =
          xsimd::min(xsimd::max(top, bottom) + no_ramp, right) + Doubles(kRangeMargin);
      // Clamped to a pixel beyond either side of the box, to convert to int32 safely.
      const Doubles first = xsimd::select(
          reaches, xsimd::max(xsimd::floor(piece_left), Doubles(-1.0)), Doubles(width + 1.0));
      const Doubles last = xsimd::select(
          reaches, xsimd::min(xsimd::floor(piece_right), Doubles(width + 1.0)), Doubles(-1.0));
      first.store_aligned(&bands.first[e][k]);
      last.store_aligned(&bands.last[e][k]);
    }
  }
}

// One row's edges as the lanes use them: those with a ramp first, then those that add
// whole (hi - lo).
template <class Arch>
struct RowEdges {
  using Doubles = xsimd::batch<double, Arch>;
  // Ramp edges: X is the edge's right end where y rises with x (the edge adds
  // upper (X - b) + ramp (b - a) ((a + b) - 2 A)), its left end where y falls.
  Doubles extent[3], start[3], end[3], twice_start[3], upper[3], ramp[3];
  // Whole edges: whole (hi - lo).
  Doubles left[3], right[3], whole[3];
};

// Areas of the pixels whose columns start at u (from the origin): the sum over the row's
// edges, of which kRamp have a ramp and kWhole add whole (hi - lo); round-off below
// kAreaRoundOff and pixels outside [x_begin, x_end) give 0.
template <int kRamp, int kWhole, class Arch>
inline xsimd::batch<double, Arch> row_areas(const RowEdges<Arch>& edges,
                                            xsimd::batch<double, Arch> u,
                                            xsimd::batch<double, Arch> x_begin,
                                            xsimd::batch<double, Arch> x_end) {
  using Doubles = xsimd::batch<double, Arch>;
  const Doubles u1 = u + Doubles(1.0);
  Doubles sum(0.0);
  for (int e = 0; e < kRamp; ++e) {
    const Doubles x = xsimd::min(xsimd::max(edges.extent[e], u), u1);
    const Doubles a = xsimd::min(xsimd::max(edges.start[e], u), u1);
    const Doubles b = xsimd::min(xsimd::max(edges.end[e], u), u1);
    sum = xsimd::fma(edges.upper[e], x - b, sum);
    sum = xsimd::fma(edges.ramp[e], (b - a) * ((a + b) - edges.twice_start[e]), sum);
  }
  for (int e = 0; e < kWhole; ++e) {
    const Doubles lo = xsimd::min(xsimd::max(edges.left[e], u), u1);
    const Doubles hi = xsimd::min(xsimd::max(edges.right[e], u), u1);
    sum = xsimd::fma(edges.whole[e], hi - lo, sum);
  }
  const auto keep = (sum > Doubles(kAreaRoundOff)) & (u >= x_begin) & (u < x_end);
  return xsimd::select(keep, xsimd::min(sum, Doubles(1.0)), Doubles(0.0));
}

// A box at most this many groups of lanes wide is computed whole (walk_box): for small
// triangles, that costs less than finding the candidates of each row.
inline constexpr std::int32_t kBoxWalkMaxGroups = 6;

// One row's edges as the box walk uses them (walk_box): sloped ones, then a horizontal one.
template <class Arch>
struct BoxRowEdges {
  using Doubles = xsimd::batch<double, Arch>;
  // The edge adds weight clamp(x, from, to) + ramp (p - A') (p + offset), p = clamp(x, A', B').
  Doubles start[3], end[3], offset[3], from[3], to[3], weight[3], ramp[3];
  Doubles left, right, whole;  // a horizontal edge adds whole clamp(x, left, right)
};

// The integral of the row's covered height from the box's left to x, summed over the edges,
// up to a constant of the row: a pixel's area is its value at the pixel's right side minus its
// value at the left side.
template <int kRamp, int kWhole, class Arch>
inline xsimd::batch<double, Arch> covered_up_to(const BoxRowEdges<Arch>& edges,
                                                xsimd::batch<double, Arch> x) {
  using Doubles = xsimd::batch<double, Arch>;
  Doubles sum(0.0);
  for (int e = 0; e < kRamp; ++e) {
    const Doubles p = xsimd::min(xsimd::max(x, edges.start[e]), edges.end[e]);
    const Doubles flat = xsimd::min(xsimd::max(x, edges.from[e]), edges.to[e]);
    sum = xsimd::fma(edges.weight[e], flat, sum);
    sum = xsimd::fma(edges.ramp[e], (p - edges.start[e]) * (p + edges.offset[e]), sum);
  }
  if constexpr (kWhole > 0)
    sum = xsimd::fma(edges.whole, xsimd::min(xsimd::max(x, edges.left), edges.right), sum);
  return sum;
}

// Every x where the box walk takes F, from the origin, lies in [0, kBoxWalkReach]: the box's
// first pixel is at most 7 to the right of the origin, and its groups end at most kLanes <= 8
// past the box.
inline constexpr double kBoxWalkReach = 64.0;
static_assert(7 + (kBoxWalkMaxGroups + 1) * 8 <= kBoxWalkReach);

// The box walk's per-row constants of its sloped edges, rows r_begin .. r_end - 1 of a tile
// row, kLanes rows at a time: the ramp [A', B'] as set_up_bands() finds it and the extent of
// the edge's flat part, all clamped to [0, kBoxWalkReach]. Over that range F changes only by a
// constant of the row (clamp(x, from, to) and p = clamp(x, A', B') are the same there, the ramp
// term moves by s / 2 ((A'' - A)^2 - (A' - A)^2) with A'' the clamped A'), and every term of F
// stays within [0, kBoxWalkReach] (the ramp term: (p - A'') times a height of at most 1).
struct BoxRows {
  alignas(64) double start[3][kTileSize];
  alignas(64) double end[3][kTileSize];
  alignas(64) double offset[3][kTileSize];  // A' - 2 A
  alignas(64) double from[3][kTileSize];
  alignas(64) double to[3][kTileSize];
};

template <class Arch>
void set_up_box_rows(const AreaEdge* edges, const int* ramp_edges, int ramps, std::int32_t top_row,
                     int r_begin, int r_end, BoxRows& rows) {
  using Doubles = xsimd::batch<double, Arch>;
  constexpr int kLanes = static_cast<int>(Doubles::size);
  alignas(64) double offsets[kLanes];
  for (int l = 0; l < kLanes; ++l)
    offsets[l] = static_cast<double>(l);
  const Doubles lane_rows = Doubles::load_aligned(offsets);
  const Doubles zero(0.0), reach(kBoxWalkReach);
  for (int i = 0; i < ramps; ++i) {
    const AreaEdge& edge = edges[ramp_edges[i]];
    const Doubles left(edge.left), right(edge.right), x0(edge.x0), y0(edge.y0);
    const Doubles near_left = xsimd::min(xsimd::max(left, zero), reach);
    const Doubles near_right = xsimd::min(xsimd::max(right, zero), reach);
    const Doubles inverse_slope(edge.inverse_slope);
    for (int k = r_begin - r_begin % kLanes; k < r_end; k += kLanes) {
      const Doubles top_y = Doubles(static_cast<double>(top_row + k)) + lane_rows;
      // As the candidate walk: x0 + (y - y0) dx / dy, y - y0 exact.
      const Doubles top = x0 + (top_y - y0) * inverse_slope;
      const Doubles bottom = x0 + ((top_y + Doubles(1.0)) - y0) * inverse_slope;
      const Doubles start = edge.rising ? top : bottom, end = edge.rising ? bottom : top;
      // Clamped to [L, R], then to [0, kBoxWalkReach] ([L, R] clamped to it first keeps the
      // order).
      const Doubles clamped_start = xsimd::min(xsimd::max(start, near_left), near_right);
      const Doubles clamped_end = xsimd::min(xsimd::max(end, near_left), near_right);
      clamped_start.store_aligned(&rows.start[i][k]);
      clamped_end.store_aligned(&rows.end[i][k]);
      (clamped_start - (start + start)).store_aligned(&rows.offset[i][k]);
      (edge.rising ? clamped_end : near_left).store_aligned(&rows.from[i][k]);
      (edge.rising ? near_right : clamped_end).store_aligned(&rows.to[i][k]);
    }
  }
}

// Every pixel of the box by the lanes, a tile row at a time: tiles as walk_areas(). Along a row
// the integral of the covered height, F(x) = integral from the box's left to x, is taken at
// every pixel's left side, one lane per pixel, and a pixel's area is F(u + 1) - F(u): F at the
// next lane. Where y rises with x, an edge's clamped height is 0 up to A', a ramp (t - A) s up
// to B' and 1 up to its right end R (A', B': the crossings clamped to the edge's extent
// [L, R]), so with p = clamp(x, A', B'), up to a constant,
//     F(x) = clamp(x, B', R) + (p - A') (p + A' - 2 A) s / 2;
// where it falls, 1 from L to A', a ramp down to 0 at B', so F(x) = clamp(x, L, B') - the same
// ramp term. Per edge 9 lane operations, F once per group: at the pixels' right sides, a
// pixel's left side being the lane before (the previous group's last lane).
template <class Arch, class Storage, class Emit>
void walk_box(const AreaTriangle& tri, const PixelRect& box, Storage& storage,
              std::uint32_t triangle, Emit&& emit) {
  using Wide = WideArch<Arch>;
  using Doubles = xsimd::batch<double, Wide>;
  using Floats = xsimd::batch<float, Arch>;
  constexpr std::int32_t kLanes = static_cast<std::int32_t>(Doubles::size);
  constexpr int kFloatLanes = static_cast<int>(Floats::size);
  const std::int32_t first_tile_x = box.x0 / kTileSize;
  const std::int32_t origin = first_tile_x * kTileSize;
  const std::int32_t x_begin = box.x0 - origin, x_end = box.x1 - origin;
  const std::int32_t columns = (box.x1 - 1) / kTileSize - first_tile_x + 1;
  AreaEdge edges[3];
  set_up_area_edges(tri, origin, edges);
  alignas(64) double lane_offsets[kLanes];
  for (int l = 0; l < kLanes; ++l)
    lane_offsets[l] = static_cast<double>(l);
  const Doubles lane_columns = Doubles::load_aligned(lane_offsets);
  const Doubles box_begin(static_cast<double>(x_begin)), box_end(static_cast<double>(x_end));
  // The edges by kind, once for the triangle: sloped ones have a ramp in every row (the
  // formula holds for any row, reached or not); a horizontal one adds its clamped height
  // times its clamped extent; vertical ones add nothing.
  int ramp_edges[3], ramps = 0, horizontal = -1;
  BoxRowEdges<Wide> row_edges;
  for (int e = 0; e < 3; ++e) {
    const AreaEdge& edge = edges[e];
    if (edge.horizontal) {
      row_edges.left = Doubles(edge.left);
      row_edges.right = Doubles(edge.right);
      horizontal = e;
    } else if (edge.sign != 0.0) {
      row_edges.weight[ramps] = Doubles(edge.sign);
      row_edges.ramp[ramps] = Doubles(edge.ramp_weight);
      ramp_edges[ramps++] = e;
    }
  }
  const std::int32_t group_begin = x_begin - x_begin % kLanes;
  BoxRows rows;
  const auto walk = [&]<int kRamp, int kWhole>() {
    for (std::int32_t ty = box.y0 / kTileSize; ty <= (box.y1 - 1) / kTileSize; ++ty) {
      const int r_begin = box.y0 > ty * kTileSize ? box.y0 - ty * kTileSize : 0;
      const int r_end = box.y1 < (ty + 1) * kTileSize ? box.y1 - ty * kTileSize : kTileSize;
      set_up_box_rows<Wide>(edges, ramp_edges, kRamp, ty * kTileSize, r_begin, r_end, rows);
      AreaTile* const tiles = storage.row(columns);
      for (std::int32_t c = 0; c < columns; ++c) {
        AreaTile& tile = tiles[c];
        tile.triangle = triangle;
        tile.tile_x = static_cast<std::uint16_t>(first_tile_x + c);
        tile.tile_y = static_cast<std::uint16_t>(ty);
        tile.mask = 0;
        for (int k = 0; k < kTileSize * kTileSize; k += kFloatLanes)
          Floats(0.0f).store_unaligned(tile.area + k);
      }
      for (int r = r_begin; r < r_end; ++r) {
        const double y = static_cast<double>(ty * kTileSize + r);
        for (int i = 0; i < kRamp; ++i) {
          row_edges.start[i] = Doubles(rows.start[i][r]);
          row_edges.end[i] = Doubles(rows.end[i][r]);
          row_edges.offset[i] = Doubles(rows.offset[i][r]);
          row_edges.from[i] = Doubles(rows.from[i][r]);
          row_edges.to[i] = Doubles(rows.to[i][r]);
        }
        if constexpr (kWhole > 0) {
          const AreaEdge& edge = edges[horizontal];
          const double height = edge.y0 - y;
          row_edges.whole =
              Doubles(edge.sign * (height < 0.0 ? 0.0 : (height > 1.0 ? 1.0 : height)));
        }
        // F at the pixels' right sides, and at the first one's left side where that pixel
        // lies in the box (else its lane is cleared).
        Doubles right_side = Doubles(static_cast<double>(group_begin + 1)) + lane_columns;
        Doubles before = x_begin == group_begin
                             ? covered_up_to<kRamp, kWhole>(
                                   row_edges, right_side - Doubles(static_cast<double>(kLanes)))
                             : Doubles(0.0);
        for (std::int32_t x = group_begin; x < x_end; x += kLanes) {
          const Doubles covered = covered_up_to<kRamp, kWhole>(row_edges, right_side);
          const Doubles sum = covered - previous_lanes(before, covered);
          const auto keep =
              (sum > Doubles(kAreaRoundOff)) & (right_side > box_begin) & (right_side <= box_end);
          const Doubles area = xsimd::select(keep, xsimd::min(sum, Doubles(1.0)), Doubles(0.0));
          // x >= 0: the tile and the column by shifts.
          const auto column = static_cast<std::uint32_t>(x);
          AreaTile& tile = tiles[column / kTileSize];
          const std::uint32_t at = static_cast<std::uint32_t>(r) * kTileSize + column % kTileSize;
          store_as_floats(area, tile.area + at);
          tile.mask |= std::uint64_t{positive_lanes(area)} << at;
          right_side = right_side + Doubles(static_cast<double>(kLanes));
          before = covered;
        }
      }
      for (std::int32_t c = 0; c < columns; ++c) {
        if (tiles[c].mask != 0) emit(tiles[c]);
      }
    }
  };
  // A triangle has at most one horizontal edge, and at most one vertical edge.
  switch (ramps * 2 + (horizontal >= 0 ? 1 : 0)) {
    case 3 * 2 + 0:
      walk.template operator()<3, 0>();
      break;
    case 2 * 2 + 1:
      walk.template operator()<2, 1>();
      break;
    case 2 * 2 + 0:
      walk.template operator()<2, 0>();
      break;
    default:
      walk.template operator()<1, 1>();
      break;
  }
}

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
  using Floats = xsimd::batch<float, Arch>;
  constexpr std::int32_t kLanes = static_cast<std::int32_t>(Doubles::size);
  constexpr int kFloatLanes = static_cast<int>(Floats::size);
  static_assert(kTileSize % kLanes == 0, "a group of lanes never straddles a tile");
  constexpr std::uint64_t kGroupBits = (std::uint64_t{1} << kLanes) - 1;
  // Tiles not yet touched in the current tile row.
  constexpr std::uint16_t kUntouched = 0xFFFF;
  const std::int32_t first_tile_x = box.x0 / kTileSize;
  const std::int32_t origin = first_tile_x * kTileSize;
  const std::int32_t x_begin = box.x0 - origin, x_end = box.x1 - origin;
  const std::int32_t columns = (box.x1 - 1) / kTileSize - first_tile_x + 1;
  AreaEdge edges[3];
  set_up_area_edges(tri, origin, edges);
  alignas(64) double lane_offsets[kLanes];
  for (int l = 0; l < kLanes; ++l)
    lane_offsets[l] = static_cast<double>(l);
  const Doubles lane_columns = Doubles::load_aligned(lane_offsets);
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
      // The candidates of each edge, clipped to the box.
      std::int32_t first[3], end[3];
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
      if (span_first >= span_end) continue;
      // Between the first candidate and the last, pixels no piece touches are whole: the row
      // of each tile the span reaches starts as 1 there and 0 elsewhere (a tile is cleared
      // when first reached), and the candidates' areas replace it.
      for (std::int32_t c = span_first / kTileSize; c <= (span_end - 1) / kTileSize; ++c) {
        AreaTile& tile = tiles[c];
        if (tile.tile_y == kUntouched) {
          tile.triangle = triangle;
          tile.tile_x = static_cast<std::uint16_t>(first_tile_x + c);
          tile.tile_y = static_cast<std::uint16_t>(ty);
          tile.mask = 0;
          for (int k = 0; k < kTileSize * kTileSize; k += kFloatLanes)
            Floats(0.0f).store_unaligned(tile.area + k);
        }
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
      // The row's edges: those with a ramp first.
      int ramps = 0, wholes = 0;
      for (int e = 0; e < 3; ++e) {
        if (bands.ramp[e][r] != 0.0) {
          const AreaEdge& edge = edges[e];
          row_edges.extent[ramps] = Doubles(edge.rising ? edge.right : edge.left);
          row_edges.start[ramps] = Doubles(bands.start[e][r]);
          row_edges.end[ramps] = Doubles(bands.end[e][r]);
          row_edges.twice_start[ramps] = Doubles(bands.twice_start[e][r]);
          row_edges.upper[ramps] = Doubles(edge.upper_weight);
          row_edges.ramp[ramps] = Doubles(edge.ramp_weight);
          ++ramps;
        } else if (bands.whole[e][r] != 0.0) {
          row_edges.left[wholes] = Doubles(edges[e].left);
          row_edges.right[wholes] = Doubles(edges[e].right);
          row_edges.whole[wholes] = Doubles(bands.whole[e][r]);
          ++wholes;
        }
      }
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
      switch (ramps * 4 + wholes) {
        case 0 * 4 + 1:
          compute.template operator()<0, 1>();
          break;
        case 0 * 4 + 2:
          compute.template operator()<0, 2>();
          break;
        case 0 * 4 + 3:
          compute.template operator()<0, 3>();
          break;
        case 1 * 4 + 0:
          compute.template operator()<1, 0>();
          break;
        case 1 * 4 + 1:
          compute.template operator()<1, 1>();
          break;
        case 1 * 4 + 2:
          compute.template operator()<1, 2>();
          break;
        case 2 * 4 + 0:
          compute.template operator()<2, 0>();
          break;
        case 2 * 4 + 1:
          compute.template operator()<2, 1>();
          break;
        case 3 * 4 + 0:
          compute.template operator()<3, 0>();
          break;
        default:
          compute.template operator()<0, 0>();
          break;
      }
    }
    for (std::int32_t c = 0; c < columns; ++c) {
      if (tiles[c].tile_y != kUntouched && tiles[c].mask != 0) emit(tiles[c]);
    }
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
