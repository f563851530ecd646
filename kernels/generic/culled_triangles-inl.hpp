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
// out of range, is decided by set-up's own arithmetic in double (drop_decision()).
#pragma once

#include <algorithm>
#include <bit>
#include <cmath>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "../src/kernel_table.hpp"
#include "edgewise/coverage.hpp"
#include "simd_ops-inl.hpp"
#include "texel_fetch-inl.hpp"
#include "triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

enum class DropDecision { keep, culled, unseen };

// Whether set-up culls the triangle of `corner` (triangle_setup-inl.hpp, the same operations),
// or draws it with no sample of `window` in its box: its indices in range and its vertices in
// the guard band after snapping, with zero area or facing away under `cull`, or a box that
// setup_triangles() finds empty.
inline DropDecision drop_decision(const Vec2* vertices, std::size_t vertex_count,
                                  const std::uint32_t (&corner)[3], CullMode cull,
                                  const detail::SampleWindow& window) {
  const double band = static_cast<double>(kGuardBandFixed);
  double x[3], y[3];
  for (int i = 0; i < 3; ++i) {
    if (corner[i] >= vertex_count) return DropDecision::keep;
    const double sx = static_cast<double>(vertices[corner[i]].x) * 256.0;
    const double sy = static_cast<double>(vertices[corner[i]].y) * 256.0;
    x[i] = std::nearbyint(sx);
    y[i] = std::nearbyint(sy);
    if (!(std::fabs(sx) <= band && std::fabs(sy) <= band && x[i] < band && y[i] < band))
      return DropDecision::keep;
  }
  const double area2 = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  if (area2 == 0.0 || (cull == CullMode::clockwise && area2 > 0.0) ||
      (cull == CullMode::counter_clockwise && area2 < 0.0)) {
    return DropDecision::culled;
  }
  const double reach = window.reach;
  const auto empty = [&](const double(&v)[3], std::int32_t first, std::int32_t end) {
    const double lo = std::min({v[0], v[1], v[2]}), hi = std::max({v[0], v[1], v[2]});
    return std::max(std::floor((lo + 127.0 - reach) / 256.0), static_cast<double>(first)) >=
           std::min(std::floor((hi - 128.0 + reach) / 256.0) + 1.0, static_cast<double>(end));
  };
  return empty(x, window.clip.x0, window.clip.x1) || empty(y, window.clip.y0, window.clip.y1)
             ? DropDecision::unseen
             : DropDecision::keep;
}

// Drops from `indices` (three per triangle, into `vertices`) every triangle set-up would cull,
// by its winding under `cull` or for zero area after snapping, and every one it would draw with
// no sample of `window` in its box; the others keep their order at the front.
template <class Arch>
detail::DroppedTriangles drop_culled_triangle_list(const Vec2* vertices, std::size_t vertex_count,
                                                   std::uint32_t* indices, std::size_t triangles,
                                                   CullMode cull,
                                                   const detail::SampleWindow& window) {
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  static constexpr std::int32_t kLaneIndex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  static_assert(kLanes <= 8);
  // Lanes address coordinates by 32-bit offsets: larger arrays take the double arithmetic alone.
  const bool lanes_reach = vertex_count <= (std::size_t{1} << 29);
  const Ints lane = Ints::load_unaligned(kLaneIndex);
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
  const auto holds_sample = [&](const Floats(&v)[3], Floats first, Floats last) {
    const Floats lo = xsimd::min(xsimd::min(v[0], v[1]), v[2]);
    const Floats hi = xsimd::max(xsimd::max(v[0], v[1]), v[2]);
    return xsimd::max(xsimd::ceil(lo - to_first), first) <=
           xsimd::min(xsimd::floor(hi - to_last), last);
  };
  detail::DroppedTriangles result;
  std::size_t& kept = result.kept;
  for (std::size_t first = 0; first < triangles; first += kLanes) {
    const std::size_t count = triangles - first < kLanes ? triangles - first : kLanes;
    std::uint32_t dropped = 0, unseen = 0, undecided = (1u << count) - 1;
    if (lanes_reach && vertex_count != 0) {
      // Lanes past the end repeat the last triangle; they are never stored.
      const Ints at = xsimd::min(lane, Ints(static_cast<std::int32_t>(count - 1))) * Ints(3);
      auto in_range = Ints(0) == Ints(0);
      Floats x[3], y[3];
      for (int i = 0; i < 3; ++i) {
        const Ints v = gather_int32<Arch>(corners + 3 * first + i, at);
        // As int32, an index of 2^31 or more is negative: out of range too.
        const auto valid = v >= Ints(0) && v <= last_vertex;
        in_range = in_range && valid;
        const Ints offset = xsimd::select(valid, v, Ints(0)) * Ints(2);
        x[i] = gather_float<Arch>(xy, offset);
        y[i] = gather_float<Arch>(xy + 1, offset);
      }
      auto exact =
          xsimd::batch_cast<float>(xsimd::select(in_range, Ints(1), Ints(0))) == Floats(1.0f);
      for (int i = 0; i < 3; ++i)
        exact = exact && snapped_in_band(x[i]) && snapped_in_band(y[i]);
      const Floats p = (x[1] - x[0]) * (y[2] - y[0]), q = (y[1] - y[0]) * (x[2] - x[0]);
      exact = exact && p != q;
      const auto facing_away = cull == CullMode::clockwise           ? p > q
                               : cull == CullMode::counter_clockwise ? p < q
                                                                     : Floats(0.0f) != Floats(0.0f);
      const auto empty = !(holds_sample(x, clip_x0, clip_x1) && holds_sample(y, clip_y0, clip_y1));
      // Lanes past the end (bits from `count` on) are left out of the counts.
      dropped = bits_of_lanes<Arch>(exact && facing_away) & undecided;
      unseen = bits_of_lanes<Arch>(exact && empty) & undecided & ~dropped;
      undecided &= ~bits_of_lanes<Arch>(exact);
    }
    for (; undecided != 0; undecided &= undecided - 1) {
      const int l = std::countr_zero(undecided);
      const std::uint32_t* corner = indices + 3 * (first + static_cast<std::size_t>(l));
      const std::uint32_t triangle[3] = {corner[0], corner[1], corner[2]};
      switch (drop_decision(vertices, vertex_count, triangle, cull, window)) {
        case DropDecision::keep:
          break;
        case DropDecision::culled:
          dropped |= 1u << l;
          break;
        case DropDecision::unseen:
          unseen |= 1u << l;
          break;
      }
    }
    result.culled += static_cast<std::size_t>(std::popcount(dropped));
    result.unseen += static_cast<std::size_t>(std::popcount(unseen));
    dropped |= unseen;
    for (std::size_t l = 0; l < count; ++l) {
      // Stored whether kept or not (no branch on the winding, which alternates unpredictably);
      // in place: `kept` never passes `first + l`, and the triangle is read before it is stored.
      const std::uint32_t* from = indices + 3 * (first + l);
      const std::uint32_t a = from[0], b = from[1], c = from[2];
      std::uint32_t* to = indices + 3 * kept;
      to[0] = a;
      to[1] = b;
      to[2] = c;
      kept += (dropped >> l) & 1u ? 0 : 1;
    }
  }
  return result;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
