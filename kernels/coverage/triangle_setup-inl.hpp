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
//   [-2^30, 2^30]: a value beyond the clamp has the same sign at every sample of the tile, and
//   clamped values stay within +-(2^30 + 2^28), far from int32 overflow. (The clamp leaves room
//   for the steps of reduced buffers' blocks, up to 2^26: block_setup-inl.hpp.)
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
  // G + floor((remainder + A sx + B sy) / 256) (multisample_walk-inl.hpp).
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

namespace setup_detail {

// A group's lanes as doubles.
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<double, Arch> load_lanes(const float* v) {
  constexpr std::size_t kLanes = kSetupLanes<Arch>;
  alignas(64) double lanes[kLanes];
  for (std::size_t i = 0; i < kLanes; ++i)
    lanes[i] = v[i];
  return xsimd::batch<double, Arch>::load_aligned(lanes);
}

// Snaps the vertices to 1/256 pixel: scaling by 256 is exact; |scaled| <= 2^23 fails for NaN and
// infinity, and after rounding (nearest, ties to even: the default mode) only exactly 2^23 can be
// outside. Returns the lanes within the band; the others are zeroed so that nothing after sees
// NaN, infinity or huge values (some ISAs convert to integers inside floor()), their status
// decided apart.
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch_bool<double, Arch> snap_vertices(
    const TriangleGroup<Arch>& in, xsimd::batch<double, Arch> (&x)[3],
    xsimd::batch<double, Arch> (&y)[3]) {
  using D = xsimd::batch<double, Arch>;
  const D kBand(static_cast<double>(kGuardBandFixed));
  auto in_band = D(0.0) == D(0.0);
  for (int i = 0; i < 3; ++i) {
    const D sx = load_lanes<Arch>(in.x[i]) * D(256.0), sy = load_lanes<Arch>(in.y[i]) * D(256.0);
    x[i] = xsimd::nearbyint(sx);
    y[i] = xsimd::nearbyint(sy);
    in_band = in_band && xsimd::abs(sx) <= kBand && xsimd::abs(sy) <= kBand && x[i] < kBand &&
              y[i] < kBand;
  }
  for (int i = 0; i < 3; ++i) {
    x[i] = xsimd::select(in_band, x[i], D(0.0));
    y[i] = xsimd::select(in_band, y[i], D(0.0));
  }
  return in_band;
}

// Twice the signed area (positive is clockwise on screen, y down), after which vertices 1 and 2
// of counter-clockwise lanes are swapped so that every edge function is positive inside.
template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<double, Arch> wind_clockwise(
    xsimd::batch<double, Arch> (&x)[3], xsimd::batch<double, Arch> (&y)[3]) {
  using D = xsimd::batch<double, Arch>;
  const D area2 = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  const auto counter_clockwise = area2 < D(0.0);
  const D x1 = xsimd::select(counter_clockwise, x[2], x[1]);
  const D y1 = xsimd::select(counter_clockwise, y[2], y[1]);
  x[2] = xsimd::select(counter_clockwise, x[1], x[2]);
  y[2] = xsimd::select(counter_clockwise, y[1], y[2]);
  x[1] = x1;
  y[1] = y1;
  return area2;
}

// The pixels a group's triangles may reach and the walk's start and extent.
template <class Arch>
struct GroupBoxes {
  using D = xsimd::batch<double, Arch>;
  D x0, y0, x1, y1;      // clipped, [x0, x1) x [y0, y1)
  D extent;              // the larger side before clipping, at most kMaxExtent
  D origin_x, origin_y;  // the first tile's top-left pixel
  D reach_x, reach_y;    // how far past the origin the walk reaches, in pixels
};

// Pixels with a sample 256 i + 128 + s (s within the reach) within [min, max] of the snapped
// vertices, clipped: i from ceil((min - 128 - s_max) / 256) to floor((max - 128 - s_min) / 256).
template <class Arch>
[[gnu::always_inline]] inline GroupBoxes<Arch> group_boxes(const xsimd::batch<double, Arch> (&x)[3],
                                                           const xsimd::batch<double, Arch> (&y)[3],
                                                           const PixelRect& clip,
                                                           const SampleReach& reach) {
  using D = xsimd::batch<double, Arch>;
  const D kInvPixel(1.0 / 256.0), kInvTile(1.0 / kTileSize), kTile(kTileSize);
  const D min_x = xsimd::min(xsimd::min(x[0], x[1]), x[2]) - D(reach.x_max);
  const D max_x = xsimd::max(xsimd::max(x[0], x[1]), x[2]) - D(reach.x_min);
  const D min_y = xsimd::min(xsimd::min(y[0], y[1]), y[2]) - D(reach.y_max);
  const D max_y = xsimd::max(xsimd::max(y[0], y[1]), y[2]) - D(reach.y_min);
  GroupBoxes<Arch> b;
  b.x0 = xsimd::max(xsimd::floor((min_x + D(127.0)) * kInvPixel), D(clip.x0));
  b.y0 = xsimd::max(xsimd::floor((min_y + D(127.0)) * kInvPixel), D(clip.y0));
  b.x1 = xsimd::min(xsimd::floor((max_x - D(128.0)) * kInvPixel) + D(1.0), D(clip.x1));
  b.y1 = xsimd::min(xsimd::floor((max_y - D(128.0)) * kInvPixel) + D(1.0), D(clip.y1));
  b.extent = xsimd::min(xsimd::max(xsimd::floor((max_x - D(128.0)) * kInvPixel) -
                                       xsimd::floor((min_x + D(127.0)) * kInvPixel),
                                   xsimd::floor((max_y - D(128.0)) * kInvPixel) -
                                       xsimd::floor((min_y + D(127.0)) * kInvPixel)) +
                            D(1.0),
                        D(kMaxExtent));
  b.origin_x = xsimd::floor(b.x0 * kInvTile) * kTile;
  b.origin_y = xsimd::floor(b.y0 * kInvTile) * kTile;
  // The walk reaches one tile past the last in each direction, plus 7 samples within a tile.
  b.reach_x = xsimd::floor((b.x1 - D(1.0) - b.origin_x) * kInvTile) * kTile + D(15.0);
  b.reach_y = xsimd::floor((b.y1 - D(1.0) - b.origin_y) * kInvTile) * kTile + D(15.0);
  return b;
}

// Each edge's A, B, G at the first tile's first sample and remainder, per lane; returns the lanes
// whose edge values stay within 32 bits over the walk (`narrow`, from the lanes given).
template <class Arch>
struct GroupEdges {
  alignas(64) double a[3][kSetupLanes<Arch>], b[3][kSetupLanes<Arch>];
  alignas(64) double g[3][kSetupLanes<Arch>], remainder[3][kSetupLanes<Arch>];
};

template <class Arch>
[[gnu::always_inline]] inline xsimd::batch_bool<double, Arch> group_edges(
    const xsimd::batch<double, Arch> (&x)[3], const xsimd::batch<double, Arch> (&y)[3],
    const GroupBoxes<Arch>& boxes, const SampleReach& reach, xsimd::batch_bool<double, Arch> narrow,
    GroupEdges<Arch>& out) {
  using D = xsimd::batch<double, Arch>;
  const D kInvPixel(1.0 / 256.0);
  const D px = boxes.origin_x * D(256.0) + D(128.0), py = boxes.origin_y * D(256.0) + D(128.0);
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
    narrow = narrow && xsimd::abs(ge) + xsimd::abs(ea) * boxes.reach_x +
                               xsimd::abs(eb) * boxes.reach_y + sample_shift <=
                           D(INT32_MAX);
    ea.store_aligned(out.a[e]);
    eb.store_aligned(out.b[e]);
    ge.store_aligned(out.g[e]);
    (biased - ge * D(256.0)).store_aligned(out.remainder[e]);
  }
  return narrow;
}

// The lanes' outcomes as 0 or 1 per lane, for the scalar write-out.
template <class Arch>
struct GroupFlags {
  alignas(64) double box[4][kSetupLanes<Arch>], origin[2][kSetupLanes<Arch>];
  alignas(64) double in_band[kSetupLanes<Arch>], zero_area[kSetupLanes<Arch>];
  alignas(64) double culled[kSetupLanes<Arch>], nonempty[kSetupLanes<Arch>];
  alignas(64) double narrow[kSetupLanes<Arch>], extent[kSetupLanes<Arch>];
};

// Each lane's status and, for drawn triangles, `visible` and `setups`; returns the visible lanes.
template <class Arch>
[[gnu::always_inline]] inline std::uint32_t write_setups(const TriangleGroup<Arch>& in,
                                                         const GroupEdges<Arch>& edges,
                                                         const GroupFlags<Arch>& flags,
                                                         TriangleSetup* setups,
                                                         TriangleStatus* statuses, bool* visible) {
  std::uint32_t visible_lanes = 0;
  for (std::size_t l = 0; l < kSetupLanes<Arch>; ++l) {
    if (flags.in_band[l] == 0.0) {
      statuses[l] =
          snap_failure(in.x[0][l], in.y[0][l], in.x[1][l], in.y[1][l], in.x[2][l], in.y[2][l]);
    } else if (flags.zero_area[l] != 0.0) {
      statuses[l] = TriangleStatus::culled_zero_area;
    } else if (flags.culled[l] != 0.0) {
      statuses[l] = TriangleStatus::culled_winding;
    } else {
      statuses[l] = TriangleStatus::drawn;
    }
    visible[l] = statuses[l] == TriangleStatus::drawn && flags.nonempty[l] != 0.0;
    if (!visible[l]) continue;
    visible_lanes |= 1u << l;
    TriangleSetup& setup = setups[l];
    for (int e = 0; e < 3; ++e) {
      setup.edge[e] = {static_cast<std::int32_t>(edges.a[e][l]),
                       static_cast<std::int32_t>(edges.b[e][l]),
                       static_cast<std::int64_t>(edges.g[e][l]),
                       static_cast<std::int32_t>(edges.remainder[e][l])};
    }
    setup.box = {
        static_cast<std::int32_t>(flags.box[0][l]), static_cast<std::int32_t>(flags.box[1][l]),
        static_cast<std::int32_t>(flags.box[2][l]), static_cast<std::int32_t>(flags.box[3][l])};
    setup.origin_x = static_cast<std::int32_t>(flags.origin[0][l]);
    setup.origin_y = static_cast<std::int32_t>(flags.origin[1][l]);
    setup.extent = static_cast<std::int32_t>(flags.extent[l]);
    setup.narrow = flags.narrow[l] != 0.0;
  }
  return visible_lanes;
}

}  // namespace setup_detail

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
  D x[3], y[3];
  const auto in_band = setup_detail::snap_vertices(in, x, y);
  const D area2 = setup_detail::wind_clockwise(x, y);
  const setup_detail::GroupBoxes<Arch> boxes = setup_detail::group_boxes(x, y, clip, reach);
  setup_detail::GroupEdges<Arch> edges;
  const auto narrow = setup_detail::group_edges(x, y, boxes, reach, in_band, edges);

  setup_detail::GroupFlags<Arch> flags;
  boxes.extent.store_aligned(flags.extent);
  boxes.x0.store_aligned(flags.box[0]);
  boxes.y0.store_aligned(flags.box[1]);
  boxes.x1.store_aligned(flags.box[2]);
  boxes.y1.store_aligned(flags.box[3]);
  boxes.origin_x.store_aligned(flags.origin[0]);
  boxes.origin_y.store_aligned(flags.origin[1]);
  const D one(1.0), zero(0.0);
  xsimd::select(in_band, one, zero).store_aligned(flags.in_band);
  xsimd::select(area2 == zero, one, zero).store_aligned(flags.zero_area);
  const auto never = zero != zero;
  const auto culled = cull == CullMode::clockwise           ? area2 > zero
                      : cull == CullMode::counter_clockwise ? area2 < zero
                                                            : never;
  xsimd::select(culled, one, zero).store_aligned(flags.culled);
  xsimd::select(boxes.x0 < boxes.x1 && boxes.y0 < boxes.y1, one, zero)
      .store_aligned(flags.nonempty);
  xsimd::select(narrow, one, zero).store_aligned(flags.narrow);
  return setup_detail::write_setups(in, edges, flags, setups, statuses, visible);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
