// Exact-area coverage (edgewise/pixel_area.hpp): the area of each pixel's square inside a
// snapped triangle, computed only where the triangle's boundary passes.
//
// Per pixel row (a band one pixel high), each edge's piece inside the band spans a range of
// pixels: those are the candidates. Between the leftmost and the rightmost candidate, a pixel
// that no piece touches lies wholly inside (the triangle's section of the band is convex and
// reaches both sides of it), so its area is 1 without arithmetic. Candidates are computed as
// aligned groups of consecutive pixels, one per double lane, by signed area accumulation: in
// the row's frame (y down from the band's top, in pixels) every edge P -> Q adds, for the pixel
// column [u, u + 1],
//     I = integral over x in [lo, hi] of clamp(y(x), 0, 1) dx,
// lo and hi being the edge's x extent clamped to the column, with the sign of Q_x - P_x; the
// bottom edges minus the top edges give the covered length of each column of the square, so
// |sum of I| is the area (the winding gives the sign).
//
// No division per pixel: where y rises with x, clamp(y) is 0 left of A (the x where the edge's
// line crosses the band's top), 1 right of B (where it crosses the bottom), and (x - A) s in
// between, s = dy / dx. With a and b, A and B clamped to [lo, hi],
//     I = (hi - b) + (b - a) ((a + b) - 2 A) s / 2.
// Where y falls with x, the same holds for 1 - y, whose A and B are the crossings of the bottom
// and the top: I = (hi - lo) - I'. A horizontal edge adds clamp(y) (hi - lo). A and B are found
// once per band per edge (A = P_x + (band's y - P_y) dx / dy), so a lane does 16 operations
// per edge: minima, maxima, differences and three multiply-adds.
//
// Error (the tolerance of pixel_area.hpp), in pixels, x measured from the clipped box's left
// side (|x| < 2^16 where it matters), eps = 2^-53:
// - u, the edge's extent and so lo and hi are exact (multiples of 1/256 below 2^17); hi - lo
//   and hi - b are exact or within one rounding of a number below 1 (both lie in [u, u + 1]).
// - A (and B) matters only where it falls inside [lo, hi], hence inside the edge's extent: then
//   |A - P_x| <= |dx| < 2^16 and the product and sum that give A err by at most 2^-35.
//   Elsewhere only its side of [lo, hi] matters, which such an error cannot change. So a and b
//   err by at most 2^-35, and I depends on each of hi, b, a with a slope of at most 1.
// - The ramp term: where b > a, a and b lie within 2^-35 of [A, B], whose width is 1 / |s|, so
//   (b - a) |s| <= 1 + 2^-34 |s| and ((a + b) - 2 A) rounds by at most 3 eps (|a + b| + 2 |A|):
//   the term errs by at most 2^-33 (from a, b and A) plus a few eps.
// Per edge below 2^-31, three edges and the sum below 2^-29; areas below 2^-30 are reported as
// 0 (they are round-off where no edge reaches, or a true sliver below 2^-30); the rounding to
// float adds 2^-25. In all below 2^-24 px^2 < 1e-6.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <type_traits>
#include <vector>

#include <xsimd/xsimd.hpp>

#if defined(__SSE2__)
#include <immintrin.h>
#endif
#if defined(__ARM_NEON)
#include <arm_neon.h>
#endif

#include "edgewise/pixel_area.hpp"
#include "lane_arch-inl.hpp"
#include "simd_ops-inl.hpp"
#include "tile_masks-inl.hpp"
#include "triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// A triangle's snapped vertices (fixed point), as the input gives them.
struct AreaTriangle {
  std::int64_t x[3], y[3];
  double orientation;  // -1 where twice the signed area is positive (clockwise), else 1
};

// Areas below this are round-off where no edge reaches (or a sliver of no consequence): 0.
inline constexpr double kAreaRoundOff = 0x1p-30;

// The lanes of `v` rounded to float and stored at out[0 .. lanes).
template <class Arch>
inline void store_as_floats(xsimd::batch<double, Arch> v, float* out) {
#if defined(__AVX512F__)
  if constexpr (std::is_base_of_v<xsimd::avx512f, Arch>) {
    _mm256_storeu_ps(out, _mm512_cvtpd_ps(v));
  } else
#endif
#if defined(__AVX2__)
      if constexpr (std::is_base_of_v<xsimd::avx2, Arch>) {
    _mm_storeu_ps(out, _mm256_cvtpd_ps(v));
  } else
#endif
#if defined(__SSE2__)
      if constexpr (std::is_base_of_v<xsimd::sse2, Arch>) {
    _mm_storel_pi(reinterpret_cast<__m64*>(out), _mm_cvtpd_ps(v));
  } else
#endif
#if defined(__aarch64__)
      if constexpr (std::is_base_of_v<xsimd::neon64, Arch>) {
    vst1_f32(out, vcvt_f32_f64(v));
  } else
#endif
  {
    static_assert(!sizeof(Arch), "store_as_floats: no implementation for this architecture");
  }
}

// One edge of a triangle, in pixels, x from the clipped box's left side (origin_x).
struct AreaEdge {
  double left, right;  // x extent (exact)
  double x0, y0;       // P, its x from the origin and its y (exact)
  double inverse_slope;  // dx / dy; 0 for a horizontal edge
  std::int64_t y_low, y_high;  // y extent, fixed point
  bool horizontal, rising;     // dy = 0; y grows with x
  // The signed weights of (hi - lo), (hi - b) and (b - a) ((a + b) - 2 A) in the area.
  double whole_weight, upper_weight, ramp_weight;
  double sign;  // of dx, times the winding

  // x where the edge's line crosses the horizontal line at y (pixels).
  double crossing(double y) const { return x0 + (y - y0) * inverse_slope; }
};

// Where a horizontal edge's ramp lies: beyond every pixel, so that a = b = hi.
inline constexpr double kNoRamp = 0x1p60;

// The per-lane arithmetic: an edge's constants for the triangle and for the current band, and
// the areas of kLanes consecutive pixels.
template <class Arch>
class AreaLanes {
 public:
  using Doubles = xsimd::batch<double, Arch>;
  static constexpr std::size_t kLanes = Doubles::size;

  AreaLanes(const AreaEdge* edges, double width) : width_(width) {
    alignas(64) double offsets[kLanes];
    for (std::size_t l = 0; l < kLanes; ++l)
      offsets[l] = static_cast<double>(l);
    offsets_ = Doubles::load_aligned(offsets);
    for (int e = 0; e < 3; ++e) {
      left_[e] = Doubles(edges[e].left);
      right_[e] = Doubles(edges[e].right);
      upper_[e] = Doubles(edges[e].upper_weight);
      ramp_[e] = Doubles(edges[e].ramp_weight);
    }
  }

  // The band's constants of edge e: the ramp [start, end] and the weight of (hi - lo).
  void set_band(int e, double start, double end, double whole_weight) {
    start_[e] = Doubles(start);
    twice_start_[e] = Doubles(2.0 * start);
    end_[e] = Doubles(end);
    whole_[e] = Doubles(whole_weight);
  }

  // Areas of the pixels whose columns start at u + lane (from the origin); 0 outside
  // [0, width).
  Doubles areas(double first) const {
    const Doubles u = Doubles(first) + offsets_;
    const Doubles u1 = u + Doubles(1.0);
    Doubles sum(0.0);
    for (int e = 0; e < 3; ++e) {
      const Doubles lo = xsimd::min(xsimd::max(left_[e], u), u1);
      const Doubles hi = xsimd::min(xsimd::max(right_[e], u), u1);
      const Doubles a = xsimd::min(xsimd::max(start_[e], lo), hi);
      const Doubles b = xsimd::min(xsimd::max(end_[e], lo), hi);
      sum = xsimd::fma(whole_[e], hi - lo, sum);
      sum = xsimd::fma(upper_[e], hi - b, sum);
      sum = xsimd::fma(ramp_[e], (b - a) * ((a + b) - twice_start_[e]), sum);
    }
    const auto keep = (sum > Doubles(kAreaRoundOff)) & (u >= Doubles(0.0)) & (u < Doubles(width_));
    return xsimd::select(keep, xsimd::min(sum, Doubles(1.0)), Doubles(0.0));
  }

 private:
  Doubles offsets_;  // 0, 1, .. kLanes - 1
  Doubles left_[3], right_[3], upper_[3], ramp_[3];
  Doubles start_[3], twice_start_[3], end_[3], whole_[3];
  double width_;
};

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
    edge.y_low = dy < 0 ? tri.y[j] : tri.y[e];
    edge.y_high = dy < 0 ? tri.y[e] : tri.y[j];
    edge.horizontal = dy == 0;
    edge.rising = (dx > 0) == (dy > 0);
    edge.inverse_slope = dy == 0 ? 0.0 : static_cast<double>(dx) / static_cast<double>(dy);
    edge.sign = dx == 0 ? 0.0 : (dx > 0 ? tri.orientation : -tri.orientation);
    // A vertical edge spans no x (lo = hi): it adds nothing, whatever its weights.
    const double half_slope =
        dx == 0 || dy == 0 ? 0.0
                           : std::fabs(static_cast<double>(dy) / static_cast<double>(dx)) / 2.0;
    const double orient = edge.horizontal || edge.rising ? 1.0 : -1.0;  // I or (hi - lo) - I'
    edge.whole_weight = edge.horizontal || edge.rising ? 0.0 : edge.sign;
    edge.upper_weight = edge.horizontal ? 0.0 : orient * edge.sign;
    edge.ramp_weight = orient * edge.sign * half_slope;
  }
}

// Candidate pixels of one band: up to three ranges, one per edge piece, [begin, end), from the
// origin, not clipped.
struct BandRanges {
  std::int32_t begin[3], end[3];
  int count = 0;
};

// Pixel ranges are widened by this (pixels) each way: far more than the crossings' error
// (2^-35), so a pixel a piece touches is never left out; a pixel it only grazes gets its area
// computed, which is exact too.
inline constexpr double kRangeMargin = 1.0 / 256.0;

// Walks a triangle's box a tile row at a time and hands its tiles to `emit` (AreaTile&) in row
// order. `row_tiles` is the caller's storage, reused from triangle to triangle.
template <class Arch, class Emit>
void walk_areas(const AreaTriangle& tri, const PixelRect& box, std::vector<AreaTile>& row_tiles,
                std::uint32_t triangle, Emit&& emit) {
  using Lanes = AreaLanes<WideArch<Arch>>;
  constexpr std::int32_t kLanes = static_cast<std::int32_t>(Lanes::kLanes);
  static_assert(kTileSize % kLanes == 0, "a group of lanes never straddles a tile");
  AreaEdge edges[3];
  set_up_area_edges(tri, box.x0, edges);
  Lanes lanes(edges, static_cast<double>(box.x1 - box.x0));
  const std::int32_t first_tile_x = box.x0 / kTileSize;
  const std::int32_t columns = (box.x1 - 1) / kTileSize - first_tile_x + 1;
  row_tiles.resize(static_cast<std::size_t>(columns));
  // The crossings of each edge's line with the top of the current band.
  double top_crossing[3];
  for (int e = 0; e < 3; ++e)
    top_crossing[e] = edges[e].crossing(static_cast<double>(box.y0));
  for (std::int32_t ty = box.y0 / kTileSize; ty <= (box.y1 - 1) / kTileSize; ++ty) {
    for (std::int32_t c = 0; c < columns; ++c) {
      AreaTile& tile = row_tiles[static_cast<std::size_t>(c)];
      tile.triangle = triangle;
      tile.tile_x = static_cast<std::uint16_t>(first_tile_x + c);
      tile.tile_y = static_cast<std::uint16_t>(ty);
      for (float& a : tile.area)
        a = 0.0f;
    }
    // Pixels [x_begin, x_end) of row y lie wholly inside.
    const auto fill_whole = [&](std::int32_t y, std::int32_t x_begin, std::int32_t x_end) {
      const int row = y % kTileSize;
      for (std::int32_t x = x_begin; x < x_end; ++x) {
        AreaTile& tile = row_tiles[static_cast<std::size_t>(x / kTileSize - first_tile_x)];
        tile.area[row * kTileSize + x % kTileSize] = 1.0f;
      }
    };
    const std::int32_t y_begin = ty * kTileSize > box.y0 ? ty * kTileSize : box.y0;
    const std::int32_t y_end = (ty + 1) * kTileSize < box.y1 ? (ty + 1) * kTileSize : box.y1;
    for (std::int32_t y = y_begin; y < y_end; ++y) {
      const std::int64_t band_top = std::int64_t{y} * 256, band_bottom = band_top + 256;
      BandRanges ranges;
      for (int e = 0; e < 3; ++e) {
        const AreaEdge& edge = edges[e];
        const double top = top_crossing[e];
        const double bottom = edge.crossing(static_cast<double>(y + 1));
        top_crossing[e] = bottom;
        if (edge.horizontal) {
          const double height = edge.y0 - static_cast<double>(y);
          const double clamped = height < 0.0 ? 0.0 : (height > 1.0 ? 1.0 : height);
          lanes.set_band(e, kNoRamp, kNoRamp, edge.sign * clamped);
        } else if (edge.rising) {
          lanes.set_band(e, top, bottom, edge.whole_weight);
        } else {
          lanes.set_band(e, bottom, top, edge.whole_weight);
        }
        if (edge.y_high < band_top || edge.y_low > band_bottom) continue;
        double left = edge.left, right = edge.right;
        if (!edge.horizontal) {
          const double low = top < bottom ? top : bottom, high = top < bottom ? bottom : top;
          left = low > left ? low : left;
          right = high < right ? high : right;
        }
        ranges.begin[ranges.count] = static_cast<std::int32_t>(std::floor(left - kRangeMargin));
        ranges.end[ranges.count] = static_cast<std::int32_t>(std::floor(right + kRangeMargin)) + 1;
        ++ranges.count;
      }
      if (ranges.count == 0) continue;
      // The candidates as disjoint runs in x order, clipped to the box; between the first and
      // the last, the gaps are whole pixels. (From here on x is the pixel's own.)
      std::int32_t begin[3], end[3];
      int runs = 0;
      std::int32_t span_begin = box.x1, span_end = box.x0;
      for (int r = 0; r < ranges.count; ++r) {
        const std::int32_t rb = ranges.begin[r] + box.x0, re = ranges.end[r] + box.x0;
        const std::int32_t b = rb < box.x0 ? box.x0 : rb;
        const std::int32_t e = re > box.x1 ? box.x1 : re;
        span_begin = rb < span_begin ? rb : span_begin;
        span_end = re > span_end ? re : span_end;
        if (b >= e) continue;
        int at = runs++;
        for (; at > 0 && begin[at - 1] > b; --at) {
          begin[at] = begin[at - 1];
          end[at] = end[at - 1];
        }
        begin[at] = b;
        end[at] = e;
      }
      span_begin = span_begin < box.x0 ? box.x0 : span_begin;
      span_end = span_end > box.x1 ? box.x1 : span_end;
      const int row = y % kTileSize;
      std::int32_t covered_to = span_begin;  // pixels below this are decided
      std::int32_t computed_to = 0;          // groups below this are computed (aligned)
      for (int r = 0; r < runs; ++r) {
        if (begin[r] > covered_to) fill_whole(y, covered_to, begin[r]);
        std::int32_t x = begin[r] - begin[r] % kLanes;
        x = x > computed_to ? x : computed_to;
        for (; x < end[r]; x += kLanes) {
          AreaTile& tile = row_tiles[static_cast<std::size_t>(x / kTileSize - first_tile_x)];
          store_as_floats(lanes.areas(static_cast<double>(x - box.x0)),
                          tile.area + row * kTileSize + x % kTileSize);
        }
        computed_to = x > computed_to ? x : computed_to;
        covered_to = end[r] > covered_to ? end[r] : covered_to;
      }
      if (span_end > covered_to) fill_whole(y, covered_to, span_end);
    }
    // Masks from the areas: the rows of the band.
    using Floats = xsimd::batch<float, Arch>;
    constexpr int kFloatLanes = static_cast<int>(Floats::size);
    for (AreaTile& tile : row_tiles) {
      std::uint64_t mask = 0;
      for (std::int32_t y = y_begin; y < y_end; ++y) {
        const int row = y % kTileSize;
        for (int c = 0; c < kTileSize; c += kFloatLanes) {
          const Floats area = Floats::load_unaligned(tile.area + row * kTileSize + c);
          mask |= std::uint64_t{bits_of_lanes<Arch>(area > Floats(0.0f))}
                  << (row * kTileSize + c);
        }
      }
      tile.mask = mask;
      if (mask != 0) emit(tile);
    }
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
