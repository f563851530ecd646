// Exact-area coverage of a small box, computed whole (walk_box; pixel_area-inl.hpp says when
// and why): the integral of each row's covered height from the box's left, taken once per lane.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <utility>

#include <xsimd/xsimd.hpp>

#include "pixel_area_edges-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

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
  const Doubles lane_rows = lane_offsets<Arch>();
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

// The triangle's edges by kind, for the box walk: sloped ones have a ramp in every row (the
// formula holds for any row, reached or not); a horizontal one adds its clamped height times its
// clamped extent; vertical ones add nothing. Their constant terms go into `row_edges`.
struct BoxEdgeKinds {
  int ramp_edges[3] = {0, 0, 0};
  int ramps = 0;
  int horizontal = -1;
};

template <class Arch>
[[gnu::always_inline]] inline BoxEdgeKinds sort_box_edges(const AreaEdge (&edges)[3],
                                                          BoxRowEdges<Arch>& row_edges) {
  using Doubles = xsimd::batch<double, Arch>;
  BoxEdgeKinds kinds;
  for (int e = 0; e < 3; ++e) {
    const AreaEdge& edge = edges[e];
    if (edge.horizontal) {
      row_edges.left = Doubles(edge.left);
      row_edges.right = Doubles(edge.right);
      kinds.horizontal = e;
    } else if (edge.sign != 0.0) {
      row_edges.weight[kinds.ramps] = Doubles(edge.sign);
      row_edges.ramp[kinds.ramps] = Doubles(edge.ramp_weight);
      kinds.ramp_edges[kinds.ramps++] = e;
    }
  }
  return kinds;
}

// Row r's terms (pixel row y) of the edges set up in `rows`, and the horizontal edge's height.
template <int kRamp, int kWhole, class Arch>
[[gnu::always_inline]] inline void load_box_row(const BoxRows& rows, int r, double y,
                                                const AreaEdge* horizontal,
                                                BoxRowEdges<Arch>& row_edges) {
  using Doubles = xsimd::batch<double, Arch>;
  for (int i = 0; i < kRamp; ++i) {
    row_edges.start[i] = Doubles(rows.start[i][r]);
    row_edges.end[i] = Doubles(rows.end[i][r]);
    row_edges.offset[i] = Doubles(rows.offset[i][r]);
    row_edges.from[i] = Doubles(rows.from[i][r]);
    row_edges.to[i] = Doubles(rows.to[i][r]);
  }
  if constexpr (kWhole > 0) {
    const double height = horizontal->y0 - y;
    row_edges.whole =
        Doubles(horizontal->sign * (height < 0.0 ? 0.0 : (height > 1.0 ? 1.0 : height)));
  }
}

// The `columns` tiles of tile row ty from tile column first_tile_x, cleared.
template <class Arch, class Storage>
[[gnu::always_inline]] inline AreaTile* begin_box_tile_row(Storage& storage, std::int32_t columns,
                                                           std::int32_t first_tile_x,
                                                           std::int32_t ty,
                                                           std::uint32_t triangle) {
  AreaTile* const tiles = storage.row(columns);
  for (std::int32_t c = 0; c < columns; ++c)
    clear_area_tile<Arch>(tiles[c], triangle, first_tile_x + c, ty);
  return tiles;
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
  constexpr std::int32_t kLanes = static_cast<std::int32_t>(Doubles::size);
  const std::int32_t first_tile_x = box.x0 / kTileSize;
  const std::int32_t origin = first_tile_x * kTileSize;
  const std::int32_t x_begin = box.x0 - origin, x_end = box.x1 - origin;
  const std::int32_t columns = (box.x1 - 1) / kTileSize - first_tile_x + 1;
  AreaEdge edges[3];
  set_up_area_edges(tri, origin, edges);
  const Doubles lane_columns = lane_offsets<Wide>();
  const Doubles box_begin(static_cast<double>(x_begin)), box_end(static_cast<double>(x_end));
  BoxRowEdges<Wide> row_edges;
  const BoxEdgeKinds kinds = sort_box_edges<Wide>(edges, row_edges);
  const AreaEdge* const horizontal = kinds.horizontal >= 0 ? &edges[kinds.horizontal] : nullptr;
  const std::int32_t group_begin = x_begin - x_begin % kLanes;
  BoxRows rows;
  const auto walk = [&]<int kRamp, int kWhole>() {
    for (std::int32_t ty = box.y0 / kTileSize; ty <= (box.y1 - 1) / kTileSize; ++ty) {
      const int r_begin = box.y0 > ty * kTileSize ? box.y0 - ty * kTileSize : 0;
      const int r_end = box.y1 < (ty + 1) * kTileSize ? box.y1 - ty * kTileSize : kTileSize;
      set_up_box_rows<Wide>(edges, kinds.ramp_edges, kRamp, ty * kTileSize, r_begin, r_end, rows);
      AreaTile* const tiles =
          begin_box_tile_row<Arch>(storage, columns, first_tile_x, ty, triangle);
      for (int r = r_begin; r < r_end; ++r) {
        load_box_row<kRamp, kWhole>(rows, r, static_cast<double>(ty * kTileSize + r), horizontal,
                                    row_edges);
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
  switch (kinds.ramps * 2 + (horizontal != nullptr ? 1 : 0)) {
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

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
