// Exact-area coverage's shared parts (pixel_area-inl.hpp says how the areas are computed and
// bounded): a triangle's edges in pixels, the bands of a tile row's rows, and a row's areas from
// its edges' ramps and whole heights.
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

// 0, 1, 2, ... per lane: the lanes' column (or row) offsets from a group's first.
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<double, Arch> lane_offsets() {
  using Doubles = xsimd::batch<double, Arch>;
  alignas(64) double offsets[Doubles::size];
  for (std::size_t l = 0; l < Doubles::size; ++l)
    offsets[l] = static_cast<double>(l);
  return Doubles::load_aligned(offsets);
}

// Tile (tile_x, tile_y) of `triangle`, with no area yet.
template <class Arch>
[[gnu::always_inline]] inline void clear_area_tile(AreaTile& tile, std::uint32_t triangle,
                                                   std::int32_t tile_x, std::int32_t tile_y) {
  using Floats = xsimd::batch<float, Arch>;
  tile.triangle = triangle;
  tile.tile_x = static_cast<std::uint16_t>(tile_x);
  tile.tile_y = static_cast<std::uint16_t>(tile_y);
  tile.mask = 0;
  for (int k = 0; k < kTileSize * kTileSize; k += static_cast<int>(Floats::size))
    Floats(0.0f).store_unaligned(tile.area + k);
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
  const Doubles lane_rows = lane_offsets<Arch>();
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

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
