// Triangle setup: snapping, validation, winding, the top-left rule, and the edge functions
// in the form the tile walk consumes. Included by each per-ISA translation unit inside its
// own namespace (EDGEWISE_ISA_NAMESPACE), so no inline symbol is shared between ISAs.
//
// Overflow analysis (all quantities are integers; "fixed" means 1/256 px):
//   Snapped coordinates X, Y lie in [-2^23, 2^23) fixed (the +-32768 px guard band), and pixel
//   samples 256 i + 128 lie in [128, 2^23) fixed (targets are at most 32768 px).
//   Edge a->b:   A = Ya - Yb,  B = Xb - Xa            |A|, |B| < 2^24           (25-bit signed)
//   Twice the area: (X1-X0)(Y2-Y0) - (Y1-Y0)(X2-X0)  |.| < 2^49                (int64)
//   Edge function at a sample P:
//                E(P) = A (Px - Xa) + B (Py - Ya)    |Px - Xa| < 2^24, |E| < 2^49 (int64)
//   A sample is covered when E + bias >= 0 for all three edges, bias = 0 on top-left edges and
//   -1 elsewhere (so that E = 0 counts only on top-left edges). Moving one pixel changes E by
//   exactly 256 A (or 256 B), so with  G = floor((E + bias) / 256)  we have
//                E + bias >= 0  <=>  G >= 0,   and  G(i + 1, j) = G(i, j) + A  exactly.
//   G is the tile walk's edge function: integer, exact, steps A and B per pixel.
//   Inside one 8x8 tile G varies by at most 7 (|A| + |B|) < 7 * 2^25 < 2^28 from its value at
//   the tile's first sample, so per-tile lanes are 32-bit once that first value is clamped to
//   [-2^29, 2^29]: a value beyond the clamp has the same sign at every sample of the tile, and
//   clamped values stay within +-(2^29 + 2^28), far from int32 overflow.
//   The walk itself steps G from tile to tile. Over the tiles of a triangle's clipped box
//   (plus one step past the last tile, and 7 samples into each tile) G is affine, so
//   |G| <= |G(origin)| + |A| reach_x + |B| reach_y; when that bound fits in int32 the whole walk
//   runs in int32 ("narrow": every triangle up to several hundred pixels across); otherwise it
//   steps in int64 and clamps per tile ("wide").
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "edgewise/raster.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

struct EdgeSetup {
  std::int32_t a, b;  // per-pixel steps of G in x and y
  std::int64_t g;     // G at the sample of pixel (origin_x, origin_y)
};

struct TriangleSetup {
  EdgeSetup edge[3];
  PixelRect box;                    // samples that can be covered, clipped; never empty when drawn
  std::int32_t origin_x, origin_y;  // first sample of the box's first tile (multiples of 8)
  bool narrow;                      // the whole tile walk fits in int32
};

inline constexpr std::int32_t kGuardBandFixed = kGuardBand << kSubpixelBits;
inline constexpr std::size_t kSnapLanes = 8;  // x0 y0 x1 y1 x2 y2 and two pads

// Snaps the six coordinates to 1/256 px, ties to even, all lanes at once. False when any is
// NaN, infinite or outside the guard band (the caller then tells which).
template <class Arch>
inline bool snap_vertices(const Vec2& p0, const Vec2& p1, const Vec2& p2,
                          std::int32_t fixed[kSnapLanes]) {
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  static_assert(kSnapLanes % Floats::size == 0, "whole batches of coordinates");
  alignas(64) const float coords[kSnapLanes] = {p0.x, p0.y, p1.x, p1.y, p2.x, p2.y, 0.0f, 0.0f};
  bool in_band = true;
  for (std::size_t h = 0; h < kSnapLanes; h += Floats::size) {
    // Scaling by 256 is exact. |scaled| <= 2^23 is false for NaN and infinity; after rounding
    // (the default mode: nearest, ties to even) only exactly 2^23 can still be out of the band.
    const Floats scaled = Floats::load_aligned(coords + h) * Floats(256.0f);
    const Ints rounded = xsimd::nearbyint_as_int(scaled);
    in_band = in_band && xsimd::all(xsimd::abs(scaled) <= Floats(8388608.0f)) &&
              xsimd::all(rounded < Ints(kGuardBandFixed));
    rounded.store_aligned(fixed + h);
  }
  return in_band;
}

// The status of a triangle that snap_vertices() refused.
inline TriangleStatus snap_failure(const Vec2& p0, const Vec2& p1, const Vec2& p2) {
  const bool finite = std::isfinite(p0.x) && std::isfinite(p0.y) && std::isfinite(p1.x) &&
                      std::isfinite(p1.y) && std::isfinite(p2.x) && std::isfinite(p2.y);
  return finite ? TriangleStatus::error_outside_guard_band : TriangleStatus::error_non_finite;
}

inline std::int64_t min3(std::int64_t a, std::int64_t b, std::int64_t c) {
  const std::int64_t m = a < b ? a : b;
  return m < c ? m : c;
}
inline std::int64_t max3(std::int64_t a, std::int64_t b, std::int64_t c) {
  const std::int64_t m = a > b ? a : b;
  return m > c ? m : c;
}
inline bool fits_int32(std::int64_t v) {
  return v >= INT32_MIN && v <= INT32_MAX;
}

// Fills `setup` for a drawn triangle; `empty` tells whether its box misses the clip rectangle.
inline TriangleStatus setup_triangle(const Vec2& p0, const Vec2& p1, const Vec2& p2,
                                     const PixelRect& clip, CullMode cull, TriangleSetup& setup,
                                     bool& empty) {
  empty = true;
  alignas(64) std::int32_t fixed[kSnapLanes];
  if (!snap_vertices<EDGEWISE_ARCH>(p0, p1, p2, fixed)) return snap_failure(p0, p1, p2);
  std::int64_t x[3] = {fixed[0], fixed[2], fixed[4]};
  std::int64_t y[3] = {fixed[1], fixed[3], fixed[5]};

  // Twice the signed area; positive is clockwise on screen (y down).
  const std::int64_t area2 = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  if (area2 == 0) return TriangleStatus::culled_zero_area;
  if ((cull == CullMode::clockwise && area2 > 0) ||
      (cull == CullMode::counter_clockwise && area2 < 0)) {
    return TriangleStatus::culled_winding;
  }
  if (area2 < 0) {  // make every edge function positive inside
    std::int64_t t = x[1];
    x[1] = x[2];
    x[2] = t;
    t = y[1];
    y[1] = y[2];
    y[2] = t;
  }

  // Pixels whose sample 256 i + 128 lies within [min, max] of the snapped vertices.
  const std::int64_t min_x = min3(x[0], x[1], x[2]), max_x = max3(x[0], x[1], x[2]);
  const std::int64_t min_y = min3(y[0], y[1], y[2]), max_y = max3(y[0], y[1], y[2]);
  PixelRect box{static_cast<std::int32_t>((min_x - 128 + 255) >> 8),
                static_cast<std::int32_t>((min_y - 128 + 255) >> 8),
                static_cast<std::int32_t>(((max_x - 128) >> 8) + 1),
                static_cast<std::int32_t>(((max_y - 128) >> 8) + 1)};
  box.x0 = box.x0 > clip.x0 ? box.x0 : clip.x0;
  box.y0 = box.y0 > clip.y0 ? box.y0 : clip.y0;
  box.x1 = box.x1 < clip.x1 ? box.x1 : clip.x1;
  box.y1 = box.y1 < clip.y1 ? box.y1 : clip.y1;
  if (box.empty()) return TriangleStatus::drawn;
  empty = false;

  setup.box = box;
  setup.origin_x = box.x0 & ~(kTileSize - 1);
  setup.origin_y = box.y0 & ~(kTileSize - 1);
  const std::int64_t px = (std::int64_t{setup.origin_x} << 8) + 128;
  const std::int64_t py = (std::int64_t{setup.origin_y} << 8) + 128;
  // The walk reaches one tile past the last in each direction, plus 7 samples within a tile.
  const std::int64_t reach_x = ((box.x1 - 1 - setup.origin_x) | (kTileSize - 1)) + kTileSize;
  const std::int64_t reach_y = ((box.y1 - 1 - setup.origin_y) | (kTileSize - 1)) + kTileSize;
  bool narrow = true;
  for (int e = 0; e < 3; ++e) {
    const int a = e, b = e == 2 ? 0 : e + 1;
    const std::int64_t ea = y[a] - y[b];
    const std::int64_t eb = x[b] - x[a];
    const bool top_left = ea > 0 || (ea == 0 && eb > 0);
    const std::int64_t value = ea * (px - x[a]) + eb * (py - y[a]) - (top_left ? 0 : 1);
    const std::int64_t g = value >> 8;  // floor division (arithmetic shift)
    setup.edge[e] = {static_cast<std::int32_t>(ea), static_cast<std::int32_t>(eb), g};
    const std::int64_t bound =
        (g < 0 ? -g : g) + (ea < 0 ? -ea : ea) * reach_x + (eb < 0 ? -eb : eb) * reach_y;
    narrow = narrow && bound <= INT32_MAX;
  }
  setup.narrow = narrow;
  return TriangleStatus::drawn;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
