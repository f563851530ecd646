// Triangles that set-up would cull, dropped from draw()'s screen triangles before it: a closed
// mesh's back faces (about half its triangles) then cost set-up, binning and the shading loop
// nothing. The decision is set-up's own (triangle_setup-inl.hpp), exactly. So are the triangles
// set-up would draw with no sample in their box (no pixel of the clip rectangle has a sample
// between the snapped vertices' bounds on both axes): on a fine mesh far from the camera these
// are a third of the triangles, and they would cost set-up for nothing.
//
// A batch of triangles is decided in float lanes where that is exact: draw()'s vertex stage
// snaps every vertex to the 1/256 px grid inside the guard band, so each coordinate is a multiple
// of 2^-8 below 2^15 in magnitude, and the differences of two are multiples of 2^-8 below 2^16,
// exact in float. The two products of twice the area, p = dx1 dy2 and q = dy1 dx2, are rounded
// once each; rounding is monotonic, so fl(p) > fl(q) implies p > q and fl(p) < fl(q) implies
// p < q: the sign of the area p - q. The box's first and last pixels, ceil(min - 1/2 - r) and
// floor(max - 1/2 + r) for a sample reach r of 0 or 1/2 px, are exact too: min - 1/2 - r is a
// multiple of 2^-8 below 2^15 + 1 in magnitude, 24 bits. A lane where fl(p) = fl(q) (zero area,
// or one too small to tell), or whose vertices are not snapped into the band, or whose index is
// out of range, is decided by set-up's own arithmetic, one triangle at a time (drop_decision()).
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>
#include <type_traits>

#include <xsimd/xsimd.hpp>

#include "../../coverage/triangle_binning.hpp"
#include "edgewise/coverage.hpp"
#include "../../simd/interleave-inl.hpp"
#include "../../simd/lane_loads-inl.hpp"
#include "../../simd/simd_ops-inl.hpp"
#include "../../texture/texel_fetch-inl.hpp"
#include "../../coverage/triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

enum class DropDecision { keep, culled, unseen };

// What the pass does with the triangle of `corner`: set-up's decisions in its exact arithmetic
// (classify_triangle(), the binning's), kept when an index is out of range or a vertex is not
// snapped into the band, for set-up to report. `box` is the box of a triangle set-up draws
// (empty for any other).
inline DropDecision drop_decision(const Vec2* vertices, std::size_t vertex_count,
                                  const std::uint32_t (&corner)[3], CullMode cull,
                                  const detail::SampleWindow& window, PixelRect& box) {
  if (corner[0] >= vertex_count || corner[1] >= vertex_count || corner[2] >= vertex_count)
    return DropDecision::keep;
  const Vec2 v[3] = {vertices[corner[0]], vertices[corner[1]], vertices[corner[2]]};
  switch (detail::classify_triangle(v, cull, window.clip, box, window.reach)) {
    case TriangleStatus::culled_zero_area:
    case TriangleStatus::culled_winding:
      return DropDecision::culled;
    case TriangleStatus::drawn:
      return box.empty() ? DropDecision::unseen : DropDecision::keep;
    default:
      box = PixelRect{};
      return DropDecision::keep;
  }
}

// The triangles of the lanes `undecided` (bits into the group whose indices start at
// `corners`), decided one at a time by drop_decision(): culled ones added to `dropped`, unseen
// ones to `unseen`; with a grid, a kept one's bin to lane_bins[lane].
[[gnu::always_inline]] inline void decide_one_by_one(
    const Vec2* vertices, std::size_t vertex_count, const std::uint32_t* corners,
    std::uint32_t undecided, CullMode cull, const detail::SampleWindow& window,
    const detail::BinGrid* grid, std::uint32_t* lane_bins, std::uint32_t& dropped,
    std::uint32_t& unseen) {
  for (; undecided != 0; undecided &= undecided - 1) {
    const int l = std::countr_zero(undecided);
    const std::uint32_t* corner = corners + 3 * static_cast<std::size_t>(l);
    const std::uint32_t triangle[3] = {corner[0], corner[1], corner[2]};
    PixelRect box{};
    switch (drop_decision(vertices, vertex_count, triangle, cull, window, box)) {
      case DropDecision::keep:
        if (grid != nullptr) lane_bins[l] = detail::single_bin_of(*grid, box);
        break;
      case DropDecision::culled:
        dropped |= 1u << l;
        break;
      case DropDecision::unseen:
        unseen |= 1u << l;
        break;
    }
  }
}

// The group's triangles [first, first + count) moved to the front of `indices` at `kept`, but
// for the lanes `dropped`, with their lane_bins to `bins` when it is not null. Stored whether
// kept or not (no branch on the winding, which alternates unpredictably); in place: `kept` never
// passes `first + l`, and the triangle is read before it is stored.
[[gnu::always_inline]] inline void keep_in_place(std::uint32_t* indices, std::size_t first,
                                                 std::size_t count, std::uint32_t dropped,
                                                 const std::uint32_t* lane_bins,
                                                 std::uint32_t* bins, std::size_t& kept) {
  for (std::size_t l = 0; l < count; ++l) {
    const std::uint32_t* from = indices + 3 * (first + l);
    const std::uint32_t a = from[0], b = from[1], c = from[2];
    std::uint32_t* to = indices + 3 * kept;
    to[0] = a;
    to[1] = b;
    to[2] = c;
    if (bins != nullptr) bins[kept] = lane_bins[l];
    kept += (dropped >> l) & 1u ? 0 : 1;
  }
}

namespace culling_detail {

// A box's bin (single_bin_of()) per lane, or kSeveralBins as -1; a grid of one bin without one.
template <class Arch>
struct BinLanes {
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;

  explicit BinLanes(const detail::BinGrid* grid)
      : width_shift(grid != nullptr ? grid->width_shift : 0),
        height_shift(grid != nullptr ? grid->height_shift : 0),
        first_column(grid != nullptr ? grid->first_column : 0),
        first_row(grid != nullptr ? grid->first_row : 0),
        columns(grid != nullptr ? grid->columns : 0) {}

  [[gnu::always_inline]] Ints of(Floats x0, Floats x1, Floats y0, Floats y1) const {
    const Ints column0 = xsimd::batch_cast<std::int32_t>(x0) >> width_shift;
    const Ints column1 = xsimd::batch_cast<std::int32_t>(x1) >> width_shift;
    const Ints row0 = xsimd::batch_cast<std::int32_t>(y0) >> height_shift;
    const Ints row1 = xsimd::batch_cast<std::int32_t>(y1) >> height_shift;
    const Ints bin = (row0 - first_row) * columns + (column0 - first_column);
    return xsimd::select(column0 == column1 && row0 == row1, bin, Ints(-1));
  }

  int width_shift, height_shift;
  Ints first_column, first_row, columns;
};

// The first and last pixels of a box on one axis: those with a sample within the vertices'
// bounds (pixel i's samples lie from i + 1/2 - r to i + 1/2 + r: to_first = 1/2 + r, to_last =
// 1/2 - r), in the clip rectangle (from `first` to `last`).
template <class Arch>
[[gnu::always_inline]] inline void box_span(const xsimd::batch<float, Arch> (&v)[3],
                                            xsimd::batch<float, Arch> to_first,
                                            xsimd::batch<float, Arch> to_last,
                                            xsimd::batch<float, Arch> first,
                                            xsimd::batch<float, Arch> last,
                                            xsimd::batch<float, Arch>& from,
                                            xsimd::batch<float, Arch>& to) {
  const auto lo = xsimd::min(xsimd::min(v[0], v[1]), v[2]);
  const auto hi = xsimd::max(xsimd::max(v[0], v[1]), v[2]);
  from = xsimd::max(xsimd::ceil(lo - to_first), first);
  to = xsimd::min(xsimd::floor(hi - to_last), last);
}

// The corners of triangles [first, first + count) of `corners` (count at most the lanes; lanes
// past the end repeat the last triangle) and their positions; returns the lanes whose three
// indices lie within [0, last_vertex] (the others read vertex 0).
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch_bool<float, Arch> load_group_positions(
    const std::int32_t* corners, std::size_t first, std::size_t count, const float* xy,
    xsimd::batch<std::int32_t, Arch> last_vertex, xsimd::batch<float, Arch> (&x)[3],
    xsimd::batch<float, Arch> (&y)[3]) {
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  static constexpr std::int32_t kLaneIndex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  static_assert(Ints::size <= 8);
  Ints v[3];
  if (count == Ints::size) {
    load_records3_int32<Arch>(corners + 3 * first, v);
  } else {
    const Ints lane = Ints::load_unaligned(kLaneIndex);
    const Ints at = xsimd::min(lane, Ints(static_cast<std::int32_t>(count - 1))) * Ints(3);
    for (int i = 0; i < 3; ++i)
      v[i] = gather_int32<Arch>(corners + 3 * first + i, at);
  }
  auto in_range = Ints(0) == Ints(0);
  for (int i = 0; i < 3; ++i) {
    // As int32, an index of 2^31 or more is negative: out of range too.
    const auto valid = v[i] >= Ints(0) && v[i] <= last_vertex;
    in_range = in_range && valid;
    gather_float_pairs<Arch>(xy, xsimd::select(valid, v[i], Ints(0)), x[i], y[i]);
  }
  return xsimd::batch_cast<float>(xsimd::select(in_range, Ints(1), Ints(0))) == Floats(1.0f);
}

}  // namespace culling_detail

// Drops from `indices` (three per triangle, into `vertices`) every triangle set-up would cull,
// by its winding under `cull` or for zero area after snapping, and every one it would draw with
// no sample of `window` in its box; the others keep their order at the front, with their bins
// in `output` when it has a grid (over the window's clip rectangle).
template <class Arch>
detail::DroppedTriangles drop_culled_triangle_list(const Vec2* vertices, std::size_t vertex_count,
                                                   std::uint32_t* indices, std::size_t triangles,
                                                   CullMode cull,
                                                   const detail::SampleWindow& window,
                                                   const detail::BinOutput& output) {
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  // Lanes address coordinates by 32-bit offsets: larger arrays take the double arithmetic alone.
  const bool lanes_reach = vertex_count <= (std::size_t{1} << 29);
  const Ints last_vertex(static_cast<std::int32_t>(vertex_count - 1));
  const Floats band(static_cast<float>(kGuardBand));
  const float* xy = &vertices->x;
  const auto* corners = reinterpret_cast<const std::int32_t*>(indices);
  const auto snapped_in_band = [&](Floats v) {
    const Floats fixed = v * Floats(256.0f);
    return xsimd::abs(v) < band && xsimd::nearbyint(fixed) == fixed;
  };
  // Pixel i's samples lie from i + 1/2 - r to i + 1/2 + r.
  const Floats reach(static_cast<float>(window.reach) / 256.0f);
  const Floats to_first = Floats(0.5f) + reach, to_last = Floats(0.5f) - reach;
  const Floats clip_x0(static_cast<float>(window.clip.x0));
  const Floats clip_y0(static_cast<float>(window.clip.y0));
  const Floats clip_x1(static_cast<float>(window.clip.x1 - 1));
  const Floats clip_y1(static_cast<float>(window.clip.y1 - 1));
  const detail::BinGrid* grid = output.grid;
  const culling_detail::BinLanes<Arch> bins(grid);
  detail::DroppedTriangles result;
  std::size_t& kept = result.kept;
  for (std::size_t first = 0; first < triangles; first += kLanes) {
    const std::size_t count = triangles - first < kLanes ? triangles - first : kLanes;
    std::uint32_t dropped = 0, unseen = 0, undecided = (1u << count) - 1;
    alignas(64) std::uint32_t lane_bins[kLanes];
    if (lanes_reach && vertex_count != 0) {
      Floats x[3], y[3];
      auto exact =
          culling_detail::load_group_positions<Arch>(corners, first, count, xy, last_vertex, x, y);
      for (int i = 0; i < 3; ++i)
        exact = exact && snapped_in_band(x[i]) && snapped_in_band(y[i]);
      const Floats p = (x[1] - x[0]) * (y[2] - y[0]), q = (y[1] - y[0]) * (x[2] - x[0]);
      exact = exact && p != q;
      const auto facing_away = cull == CullMode::clockwise           ? p > q
                               : cull == CullMode::counter_clockwise ? p < q
                                                                     : Floats(0.0f) != Floats(0.0f);
      Floats x0, x1, y0, y1;
      culling_detail::box_span<Arch>(x, to_first, to_last, clip_x0, clip_x1, x0, x1);
      culling_detail::box_span<Arch>(y, to_first, to_last, clip_y0, clip_y1, y0, y1);
      const auto empty = !(x0 <= x1 && y0 <= y1);
      // Lanes that are not exact, or not kept, are decided below or never stored.
      if (grid != nullptr) {
        bins.of(x0, x1, y0, y1).store_aligned(reinterpret_cast<std::int32_t*>(lane_bins));
      }
      // Lanes past the end (bits from `count` on) are left out of the counts.
      dropped = bits_of_lanes<Arch>(exact && facing_away) & undecided;
      unseen = bits_of_lanes<Arch>(exact && empty) & undecided & ~dropped;
      undecided &= ~bits_of_lanes<Arch>(exact);
    }
    decide_one_by_one(vertices, vertex_count, indices + 3 * first, undecided, cull, window, grid,
                      lane_bins, dropped, unseen);
    result.culled += static_cast<std::size_t>(std::popcount(dropped));
    result.unseen += static_cast<std::size_t>(std::popcount(unseen));
    keep_in_place(indices, first, count, dropped | unseen, lane_bins, output.bins, kept);
  }
  return result;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
