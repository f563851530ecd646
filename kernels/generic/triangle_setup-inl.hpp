// Triangle setup: snapping, validation, winding, the top-left rule, and the edge functions
// in the form the tile walk consumes. Included by each per-ISA translation unit inside its
// own namespace (EDGEWISE_ISA_NAMESPACE), so no inline symbol is shared between ISAs.
//
// Overflow analysis (all quantities are integers; "fixed" means 1/256 px):
//   Snapped coordinates X, Y lie in [-2^23, 2^23) fixed (the +-32768 px guard band), and pixel
//   samples 256 i + 128 lie in [128, 2^23) fixed (targets are at most 32768 px).
//   Edge a->b:   A = Ya - Yb,  B = Xb - Xa            |A|, |B| < 2^24           (25-bit signed)
//   Twice the area: (X1-X0)(Y2-Y0) - (Y1-Y0)(X2-X0)  |.| < 2^49                (50 bits)
//   Edge function at a sample P:
//                E(P) = A (Px - Xa) + B (Py - Ya)    |Px - Xa| < 2^24, |E| < 2^49 (50 bits)
//   Setup holds these in double lanes, which are exact for integers below 2^53 (see
//   setup_triangles); the walks keep G in int64 or, where proven safe, int32.
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
//   steps in int64 and clamps per tile ("wide"). The span walk (span_walk-inl.hpp) works from
//   the same G in double, exact for the same reason.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>

#include <xsimd/xsimd.hpp>

#include "edgewise/coverage.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

struct EdgeSetup {
  std::int32_t a, b;  // per-pixel steps of G in x and y
  std::int64_t g;     // G at the sample of pixel (origin_x, origin_y)
  // (E + bias) - 256 G, in [0, 255]: the same at every pixel centre (E steps by multiples of
  // 256), so a sample moved from the centre by (sx, sy) fixed-point units has
  // G + floor((remainder + A sx + B sy) / 256) (sample_walk-inl.hpp).
  std::int32_t remainder;
};

// How far a call's samples lie from the pixel centre, in fixed-point units (1/256 px): zero
// for single-sample calls, the sample pattern's extremes for multisampled ones.
struct SampleReach {
  std::int32_t x_min = 0, x_max = 0, y_min = 0, y_max = 0;
  bool any() const { return x_min != 0 || x_max != 0 || y_min != 0 || y_max != 0; }
};

struct TriangleSetup {
  EdgeSetup edge[3];
  PixelRect box;                    // samples that can be covered, clipped; never empty when drawn
  std::int32_t origin_x, origin_y;  // first sample of the box's first tile (multiples of 8)
  // The larger side of the box before clipping, capped at kMaxExtent: the size that chooses a
  // small triangle's walk, the same whatever rectangle (a thread's bin) the call clips to.
  std::int32_t extent;
  bool narrow;  // the whole tile walk fits in int32
};

inline constexpr std::int32_t kMaxExtent = 1 << 16;

inline constexpr std::int32_t kGuardBandFixed = kGuardBand << kSubpixelBits;

// The status of a triangle whose coordinates did not snap into the guard band.
inline TriangleStatus snap_failure(float x0, float y0, float x1, float y1, float x2, float y2) {
  const bool finite = std::isfinite(x0) && std::isfinite(y0) && std::isfinite(x1) &&
                      std::isfinite(y1) && std::isfinite(x2) && std::isfinite(y2);
  return finite ? TriangleStatus::error_outside_guard_band : TriangleStatus::error_non_finite;
}

// Triangles set up together, one per double lane.
template <class Arch>
inline constexpr std::size_t kSetupLanes = xsimd::batch<double, Arch>::size;

// Input of one group of triangles: vertex coordinates as given, one lane per triangle.
template <class Arch>
struct TriangleGroup {
  alignas(64) float x[3][kSetupLanes<Arch>];
  alignas(64) float y[3][kSetupLanes<Arch>];
};

// The vertices of a group's triangles, lane by lane: valid when all three indices are in range.
template <class Arch>
struct GroupCorners {
  std::size_t vertex[kSetupLanes<Arch>][3];
  bool valid[kSetupLanes<Arch>];
};

// Sets up a group of triangles at once. Every quantity of the analysis above is an integer of
// at most 51 bits, so double lanes hold it exactly and every sum, difference and product below
// is exact (products of two 25-bit values, sums of at most three 50-bit values); division by
// 256 or 8 is exact, and floor() of an exact quotient is exact. Writes each lane's status and,
// for drawn triangles, `visible` (the clipped box is not empty) and `setups`. Returns the lanes
// that are drawn and visible, bit l for lane l.
template <class Arch>
inline std::uint32_t setup_triangles(const TriangleGroup<Arch>& in, const PixelRect& clip,
                                     CullMode cull, TriangleSetup* setups, TriangleStatus* statuses,
                                     bool* visible, const SampleReach& reach = {}) {
  using D = xsimd::batch<double, Arch>;
  static constexpr std::size_t kLanes = kSetupLanes<Arch>;  // static: lambdas may use it
  const auto load = [](const float* v) {
    alignas(64) double lanes[kLanes];
    for (std::size_t i = 0; i < kLanes; ++i)
      lanes[i] = v[i];
    return D::load_aligned(lanes);
  };
  // Snap: scaling by 256 is exact; |scaled| <= 2^23 fails for NaN and infinity, and after
  // rounding (nearest, ties to even: the default mode) only exactly 2^23 can be outside.
  const D kBand(static_cast<double>(kGuardBandFixed));
  auto in_band = D(0.0) == D(0.0);
  D x[3], y[3];
  for (int i = 0; i < 3; ++i) {
    const D sx = load(in.x[i]) * D(256.0), sy = load(in.y[i]) * D(256.0);
    x[i] = xsimd::nearbyint(sx);
    y[i] = xsimd::nearbyint(sy);
    in_band = in_band && xsimd::abs(sx) <= kBand && xsimd::abs(sy) <= kBand && x[i] < kBand &&
              y[i] < kBand;
  }
  // Lanes that failed are zeroed so that nothing below sees NaN, infinity or huge values
  // (some ISAs convert to integers inside floor()); their status is decided apart.
  for (int i = 0; i < 3; ++i) {
    x[i] = xsimd::select(in_band, x[i], D(0.0));
    y[i] = xsimd::select(in_band, y[i], D(0.0));
  }
  // Twice the signed area; positive is clockwise on screen (y down).
  const D area2 = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  const auto clockwise = area2 > D(0.0);
  const auto counter_clockwise = area2 < D(0.0);
  // Make every edge function positive inside.
  const D x1 = xsimd::select(counter_clockwise, x[2], x[1]);
  const D y1 = xsimd::select(counter_clockwise, y[2], y[1]);
  x[2] = xsimd::select(counter_clockwise, x[1], x[2]);
  y[2] = xsimd::select(counter_clockwise, y[1], y[2]);
  x[1] = x1;
  y[1] = y1;

  // Pixels with a sample 256 i + 128 + s (s within the reach) within [min, max] of the snapped
  // vertices, clipped: i from ceil((min - 128 - s_max) / 256) to floor((max - 128 - s_min) / 256).
  const D kInvPixel(1.0 / 256.0), kInvTile(1.0 / kTileSize), kTile(kTileSize);
  const D min_x = xsimd::min(xsimd::min(x[0], x[1]), x[2]) - D(reach.x_max);
  const D max_x = xsimd::max(xsimd::max(x[0], x[1]), x[2]) - D(reach.x_min);
  const D min_y = xsimd::min(xsimd::min(y[0], y[1]), y[2]) - D(reach.y_max);
  const D max_y = xsimd::max(xsimd::max(y[0], y[1]), y[2]) - D(reach.y_min);
  const D box_x0 = xsimd::max(xsimd::floor((min_x + D(127.0)) * kInvPixel), D(clip.x0));
  const D box_y0 = xsimd::max(xsimd::floor((min_y + D(127.0)) * kInvPixel), D(clip.y0));
  const D box_x1 = xsimd::min(xsimd::floor((max_x - D(128.0)) * kInvPixel) + D(1.0), D(clip.x1));
  const D box_y1 = xsimd::min(xsimd::floor((max_y - D(128.0)) * kInvPixel) + D(1.0), D(clip.y1));
  const auto nonempty = box_x0 < box_x1 && box_y0 < box_y1;
  const D extent = xsimd::min(xsimd::max(xsimd::floor((max_x - D(128.0)) * kInvPixel) -
                                             xsimd::floor((min_x + D(127.0)) * kInvPixel),
                                         xsimd::floor((max_y - D(128.0)) * kInvPixel) -
                                             xsimd::floor((min_y + D(127.0)) * kInvPixel)) +
                                  D(1.0),
                              D(kMaxExtent));
  const D origin_x = xsimd::floor(box_x0 * kInvTile) * kTile;
  const D origin_y = xsimd::floor(box_y0 * kInvTile) * kTile;
  // The walk reaches one tile past the last in each direction, plus 7 samples within a tile.
  const D reach_x = xsimd::floor((box_x1 - D(1.0) - origin_x) * kInvTile) * kTile + D(15.0);
  const D reach_y = xsimd::floor((box_y1 - D(1.0) - origin_y) * kInvTile) * kTile + D(15.0);
  const D px = origin_x * D(256.0) + D(128.0), py = origin_y * D(256.0) + D(128.0);

  alignas(64) double a[3][kLanes], b[3][kLanes], g[3][kLanes], remainder[3][kLanes];
  auto narrow = in_band;
  // A sample off the centre moves G by at most (|A| |s_x| + |B| |s_y|) / 256 + 1.
  const D sample_x(std::max(std::abs(reach.x_min), std::abs(reach.x_max)));
  const D sample_y(std::max(std::abs(reach.y_min), std::abs(reach.y_max)));
  const D sample_slack(reach.any() ? 1.0 : 0.0);
  for (int e = 0; e < 3; ++e) {
    const int i = e, j = e == 2 ? 0 : e + 1;
    const D ea = y[i] - y[j], eb = x[j] - x[i];
    const auto top_left = ea > D(0.0) || (ea == D(0.0) && eb > D(0.0));
    const D bias = xsimd::select(top_left, D(0.0), D(-1.0));
    const D biased = ea * (px - x[i]) + eb * (py - y[i]) + bias;
    const D ge = xsimd::floor(biased * kInvPixel);
    const D sample_shift =
        (xsimd::abs(ea) * sample_x + xsimd::abs(eb) * sample_y) * kInvPixel + sample_slack;
    narrow = narrow &&
             xsimd::abs(ge) + xsimd::abs(ea) * reach_x + xsimd::abs(eb) * reach_y + sample_shift <=
                 D(INT32_MAX);
    ea.store_aligned(a[e]);
    eb.store_aligned(b[e]);
    ge.store_aligned(g[e]);
    (biased - ge * D(256.0)).store_aligned(remainder[e]);
  }

  alignas(64) double box[4][kLanes], origin[2][kLanes], flags[5][kLanes], extents[kLanes];
  extent.store_aligned(extents);
  box_x0.store_aligned(box[0]);
  box_y0.store_aligned(box[1]);
  box_x1.store_aligned(box[2]);
  box_y1.store_aligned(box[3]);
  origin_x.store_aligned(origin[0]);
  origin_y.store_aligned(origin[1]);
  const D one(1.0), zero(0.0);
  xsimd::select(in_band, one, zero).store_aligned(flags[0]);
  xsimd::select(area2 == zero, one, zero).store_aligned(flags[1]);
  const auto never = zero != zero;
  const auto culled = cull == CullMode::clockwise           ? clockwise
                      : cull == CullMode::counter_clockwise ? counter_clockwise
                                                            : never;
  xsimd::select(culled, one, zero).store_aligned(flags[2]);
  xsimd::select(nonempty, one, zero).store_aligned(flags[3]);
  xsimd::select(narrow, one, zero).store_aligned(flags[4]);

  std::uint32_t visible_lanes = 0;
  for (std::size_t l = 0; l < kLanes; ++l) {
    if (flags[0][l] == 0.0) {
      statuses[l] =
          snap_failure(in.x[0][l], in.y[0][l], in.x[1][l], in.y[1][l], in.x[2][l], in.y[2][l]);
    } else if (flags[1][l] != 0.0) {
      statuses[l] = TriangleStatus::culled_zero_area;
    } else if (flags[2][l] != 0.0) {
      statuses[l] = TriangleStatus::culled_winding;
    } else {
      statuses[l] = TriangleStatus::drawn;
    }
    visible[l] = statuses[l] == TriangleStatus::drawn && flags[3][l] != 0.0;
    if (!visible[l]) continue;
    visible_lanes |= 1u << l;
    TriangleSetup& setup = setups[l];
    for (int e = 0; e < 3; ++e) {
      setup.edge[e] = {static_cast<std::int32_t>(a[e][l]), static_cast<std::int32_t>(b[e][l]),
                       static_cast<std::int64_t>(g[e][l]),
                       static_cast<std::int32_t>(remainder[e][l])};
    }
    setup.box = {static_cast<std::int32_t>(box[0][l]), static_cast<std::int32_t>(box[1][l]),
                 static_cast<std::int32_t>(box[2][l]), static_cast<std::int32_t>(box[3][l])};
    setup.origin_x = static_cast<std::int32_t>(origin[0][l]);
    setup.origin_y = static_cast<std::int32_t>(origin[1][l]);
    setup.extent = static_cast<std::int32_t>(extents[l]);
    setup.narrow = flags[4][l] != 0.0;
  }
  return visible_lanes;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
