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
#include <utility>
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

// One edge of a triangle, in pixels, x from the walk's origin (the left side of the box's first
// tile).
struct AreaEdge {
  double left, right;          // x extent (exact)
  double x0, y0;               // P, its x from the origin and its y (exact)
  double inverse_slope;        // dx / dy; 0 for a horizontal edge
  double y_low, y_high;        // y extent (exact)
  double no_ramp;              // kNoRamp for a horizontal edge, else 0
  bool horizontal, rising;     // dy = 0; y grows with x
  // The signed weights of (hi - lo), (hi - b) and (b - a) ((a + b) - 2 A) in the area.
  double whole_weight, upper_weight, ramp_weight;
  double sign;  // of dx, times the winding
};

// Where a horizontal edge's ramp lies: beyond every pixel, so that a = b = hi; and its pixel
// range, widened to the whole of its extent.
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
    edge.whole_weight = edge.horizontal || edge.rising ? 0.0 : edge.sign;
    edge.upper_weight = edge.horizontal ? 0.0 : orient * edge.sign;
    edge.ramp_weight = orient * edge.sign * half_slope;
  }
}

// Pixel ranges are widened by this (pixels) each way: far more than the crossings' error
// (2^-35), so a pixel a piece touches is never left out; a pixel it only grazes gets its area
// computed, which is exact too.
inline constexpr double kRangeMargin = 1.0 / 256.0;

// The rows of one tile row, per edge and row: the ramp [start, end] and the weight of
// (hi - lo), and the pixels the edge's piece in the row touches, [first, last] from the origin
// (first > last where it has none).
struct TileRowBands {
  alignas(64) double start[3][kTileSize];
  alignas(64) double end[3][kTileSize];
  alignas(64) double whole[3][kTileSize];
  alignas(64) double first[3][kTileSize];
  alignas(64) double last[3][kTileSize];
};

// Fills `bands` for the rows top_row .. top_row + 7, kLanes rows at a time.
template <class Arch>
void set_up_bands(const AreaEdge* edges, std::int32_t top_row, double width, TileRowBands& bands) {
  using Doubles = xsimd::batch<double, Arch>;
  constexpr std::size_t kLanes = Doubles::size;
  alignas(64) double offsets[kLanes];
  for (std::size_t l = 0; l < kLanes; ++l)
    offsets[l] = static_cast<double>(l);
  const Doubles lane_rows = Doubles::load_aligned(offsets);
  for (int e = 0; e < 3; ++e) {
    const AreaEdge& edge = edges[e];
    for (std::size_t k = 0; k < kTileSize; k += kLanes) {
      const Doubles top_y = Doubles(static_cast<double>(top_row) + static_cast<double>(k)) + lane_rows;
      const Doubles bottom_y = top_y + Doubles(1.0);
      const Doubles top = xsimd::fma(top_y - Doubles(edge.y0), Doubles(edge.inverse_slope),
                                     Doubles(edge.x0));
      const Doubles bottom = xsimd::fma(bottom_y - Doubles(edge.y0), Doubles(edge.inverse_slope),
                                        Doubles(edge.x0));
      const Doubles no_ramp(edge.no_ramp);
      const Doubles ramp_start = (edge.rising ? top : bottom) + no_ramp;
      const Doubles ramp_end = (edge.rising ? bottom : top) + no_ramp;
      ramp_start.store_aligned(&bands.start[e][k]);
      ramp_end.store_aligned(&bands.end[e][k]);
      if (edge.horizontal) {
        const Doubles height = xsimd::min(xsimd::max(Doubles(edge.y0) - top_y, Doubles(0.0)),
                                          Doubles(1.0));
        (height * Doubles(edge.sign)).store_aligned(&bands.whole[e][k]);
      } else {
        Doubles(edge.whole_weight).store_aligned(&bands.whole[e][k]);
      }
      // The piece's x extent: the line's over the band, within the edge's (all of it when
      // horizontal); none where the edge does not reach the band.
      const Doubles left =
          xsimd::max(xsimd::min(top, bottom) - no_ramp, Doubles(edge.left)) - Doubles(kRangeMargin);
      const Doubles right = xsimd::min(xsimd::max(top, bottom) + no_ramp, Doubles(edge.right)) +
                            Doubles(kRangeMargin);
      const auto reaches = (Doubles(edge.y_low) <= bottom_y) & (Doubles(edge.y_high) >= top_y);
      // Clamped to a pixel beyond either side of the box, to convert to int32 safely.
      const Doubles first = xsimd::select(
          reaches, xsimd::max(xsimd::floor(left), Doubles(-1.0)), Doubles(width + 1.0));
      const Doubles last = xsimd::select(
          reaches, xsimd::min(xsimd::floor(right), Doubles(width + 1.0)), Doubles(-1.0));
      first.store_aligned(&bands.first[e][k]);
      last.store_aligned(&bands.last[e][k]);
    }
  }
}

// The per-lane arithmetic: an edge's constants for the triangle and for the current row, and
// the areas of kLanes consecutive pixels.
template <class Arch>
class AreaLanes {
 public:
  using Doubles = xsimd::batch<double, Arch>;
  static constexpr std::size_t kLanes = Doubles::size;

  // Pixels outside columns [x_begin, x_end) (from the origin) get 0.
  AreaLanes(const AreaEdge* edges, double x_begin, double x_end)
      : x_begin_(x_begin), x_end_(x_end) {
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

  // Row r's constants of every edge.
  void set_row(const TileRowBands& bands, int r) {
    for (int e = 0; e < 3; ++e) {
      start_[e] = Doubles(bands.start[e][r]);
      twice_start_[e] = start_[e] + start_[e];
      end_[e] = Doubles(bands.end[e][r]);
      whole_[e] = Doubles(bands.whole[e][r]);
    }
  }

  // Areas of the pixels whose columns start at first + lane (from the origin).
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
    const auto keep =
        (sum > Doubles(kAreaRoundOff)) & (u >= Doubles(x_begin_)) & (u < Doubles(x_end_));
    return xsimd::select(keep, xsimd::min(sum, Doubles(1.0)), Doubles(0.0));
  }

 private:
  Doubles offsets_;  // 0, 1, .. kLanes - 1
  Doubles left_[3], right_[3], upper_[3], ramp_[3];
  Doubles start_[3], twice_start_[3], end_[3], whole_[3];
  double x_begin_, x_end_;
};

// Walks a triangle's box a tile row at a time and hands its tiles to `emit` (AreaTile&) in row
// order. `row_tiles` is the caller's storage, reused from triangle to triangle.
template <class Arch, class Emit>
void walk_areas(const AreaTriangle& tri, const PixelRect& box, std::vector<AreaTile>& row_tiles,
                std::uint32_t triangle, Emit&& emit) {
  using Wide = WideArch<Arch>;
  using Lanes = AreaLanes<Wide>;
  using Floats = xsimd::batch<float, Arch>;
  constexpr std::int32_t kLanes = static_cast<std::int32_t>(Lanes::kLanes);
  constexpr int kFloatLanes = static_cast<int>(Floats::size);
  static_assert(kTileSize % kLanes == 0, "a group of lanes never straddles a tile");
  const std::int32_t first_tile_x = box.x0 / kTileSize;
  const std::int32_t origin = first_tile_x * kTileSize;
  const std::int32_t x_begin = box.x0 - origin, x_end = box.x1 - origin;
  const std::int32_t columns = (box.x1 - 1) / kTileSize - first_tile_x + 1;
  AreaEdge edges[3];
  set_up_area_edges(tri, origin, edges);
  Lanes lanes(edges, static_cast<double>(x_begin), static_cast<double>(x_end));
  row_tiles.resize(static_cast<std::size_t>(columns));
  alignas(64) float column_offsets[kFloatLanes];
  for (int l = 0; l < kFloatLanes; ++l)
    column_offsets[l] = static_cast<float>(l);
  const Floats lane_columns = Floats::load_aligned(column_offsets);
  TileRowBands bands;
  for (std::int32_t ty = box.y0 / kTileSize; ty <= (box.y1 - 1) / kTileSize; ++ty) {
    const int r_begin = box.y0 > ty * kTileSize ? box.y0 - ty * kTileSize : 0;
    const int r_end = box.y1 < (ty + 1) * kTileSize ? box.y1 - ty * kTileSize : kTileSize;
    set_up_bands<Wide>(edges, ty * kTileSize, static_cast<double>(x_end), bands);
    for (std::int32_t c = 0; c < columns; ++c) {
      AreaTile& tile = row_tiles[static_cast<std::size_t>(c)];
      tile.triangle = triangle;
      tile.tile_x = static_cast<std::uint16_t>(first_tile_x + c);
      tile.tile_y = static_cast<std::uint16_t>(ty);
      // Rows outside the box stay empty.
      for (int r = 0; r < kTileSize; ++r) {
        if (r >= r_begin && r < r_end) continue;
        for (int k = 0; k < kTileSize; k += kFloatLanes)
          Floats(0.0f).store_unaligned(tile.area + r * kTileSize + k);
      }
    }
    for (int r = r_begin; r < r_end; ++r) {
      // The candidates of each edge, clipped to the box.
      std::int32_t first[3], end[3];
      for (int e = 0; e < 3; ++e) {
        const std::int32_t f = static_cast<std::int32_t>(bands.first[e][r]);
        const std::int32_t l = static_cast<std::int32_t>(bands.last[e][r]) + 1;
        first[e] = f > x_begin ? f : x_begin;
        end[e] = l < x_end ? l : x_end;
      }
      // Between the first candidate and the last, pixels no piece touches are whole: the row
      // starts as 1 there and 0 elsewhere, and the candidates' areas replace it.
      std::int32_t span_first = first[0] < first[1] ? first[0] : first[1];
      span_first = first[2] < span_first ? first[2] : span_first;
      std::int32_t span_end = end[0] > end[1] ? end[0] : end[1];
      span_end = end[2] > span_end ? end[2] : span_end;
      const Floats span_from(static_cast<float>(span_first)), span_to(static_cast<float>(span_end));
      for (std::int32_t c = 0; c < columns; ++c) {
        float* row = row_tiles[static_cast<std::size_t>(c)].area + r * kTileSize;
        for (int k = 0; k < kTileSize; k += kFloatLanes) {
          const Floats x = lane_columns + Floats(static_cast<float>(c * kTileSize + k));
          xsimd::select((x >= span_from) & (x < span_to), Floats(1.0f), Floats(0.0f))
              .store_unaligned(row + k);
        }
      }
      if (span_first >= span_end) continue;
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
      lanes.set_row(bands, r);
      std::int32_t computed_to = 0;  // groups below this are computed (aligned)
      for (int e = 0; e < 3; ++e) {
        std::int32_t x = first[e] - first[e] % kLanes;
        x = x > computed_to ? x : computed_to;
        for (; x < end[e]; x += kLanes) {
          float* row = row_tiles[static_cast<std::size_t>(x / kTileSize)].area + r * kTileSize;
          store_as_floats(lanes.areas(static_cast<double>(x)), row + x % kTileSize);
        }
        computed_to = x > computed_to ? x : computed_to;
      }
    }
    // Masks from the areas, over the rows of the box.
    for (AreaTile& tile : row_tiles) {
      std::uint64_t mask = 0;
      for (int r = r_begin; r < r_end; ++r) {
        for (int k = 0; k < kTileSize; k += kFloatLanes) {
          const Floats area = Floats::load_unaligned(tile.area + r * kTileSize + k);
          mask |= std::uint64_t{bits_of_lanes<Arch>(area > Floats(0.0f))} << (r * kTileSize + k);
        }
      }
      tile.mask = mask;
      if (mask != 0) emit(tile);
    }
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
