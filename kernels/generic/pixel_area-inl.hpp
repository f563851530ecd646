// Exact-area coverage (edgewise/pixel_area.hpp): the area of each pixel's square inside a
// snapped triangle, computed only where the triangle's boundary passes.
//
// Per pixel row (a band one pixel high), each edge's piece inside the band spans a range of
// pixels: those are the candidates. Between the leftmost and the rightmost candidate, a pixel
// that no piece touches lies wholly inside (the triangle's section of the band is convex and
// reaches both sides of it), so its area is 1 without arithmetic. Candidates are computed a
// batch of double lanes at a time by signed area accumulation: in the pixel's frame (its corner
// at the origin, y down), every edge P -> Q adds
//     I = integral over x from xs to xe of clamp(y(x), 0, 1) dx,
// xs and xe being P's and Q's x clamped to [0, 1]; the bottom edges minus the top edges give the
// covered length of each column of the square, so |sum of I| is the area.
//
// Error (the tolerance of pixel_area.hpp): every input is exact (fixed-point coordinates over
// 256, at most 2^16 px from the pixel); y(x) = y_P + (x - x_P) m errs by at most 2^-36 px. The
// mean of clamp(y) over the edge's piece is num / (q - p) with q, p its end heights and
//     num = (q' - p') (q' + p') / 2 + max(q, 1) - max(p, 1),  q' and p' clamped to [0, 1]:
// when both ends lie above 1 (or both below 0) num is q - p (or 0) computed by the same operations,
// and the mean is exactly 1 (or 0); otherwise |p|, |q| <= q - p + 1, so for q - p >= 2^-26 the
// quotient errs by at most 2^-24. Below that the mean is clamp((p + q) / 2), off by at most
// 2^-27. Three edges and the rounding to float: below 2^-21 px^2 < 1e-6.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include <xsimd/xsimd.hpp>

#include "edgewise/pixel_area.hpp"
#include "tile_masks-inl.hpp"
#include "triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// A triangle's snapped vertices (fixed point), as the input gives them.
struct AreaTriangle {
  std::int64_t x[3], y[3];
  double orientation;  // -1 where twice the signed area is positive (clockwise), else 1
};

// The areas of pixels of one row band, a batch of double lanes at a time.
template <class Arch>
class AreaBatch {
 public:
  using Doubles = xsimd::batch<double, Arch>;
  static constexpr std::size_t kLanes = Doubles::size;

  explicit AreaBatch(const AreaTriangle& tri) : orientation_(tri.orientation) {
    for (int e = 0; e < 3; ++e) {
      const int j = e == 2 ? 0 : e + 1;
      px_[e] = static_cast<double>(tri.x[e]);
      py_[e] = static_cast<double>(tri.y[e]);
      qx_[e] = static_cast<double>(tri.x[j]);
      const std::int64_t dx = tri.x[j] - tri.x[e], dy = tri.y[j] - tri.y[e];
      // A vertical edge spans no x: its xs and xe are equal and its slope is never used.
      slope_[e] = dx == 0 ? 0.0 : static_cast<double>(dy) / static_cast<double>(dx);
    }
  }

  // Areas of pixels (x[l], y[l]) for the lanes l < count; `x` and `y` hold kLanes entries.
  void areas(const std::int32_t* x, const std::int32_t* y, float* out, std::size_t count) const {
    alignas(64) double corner_x[kLanes], corner_y[kLanes];
    for (std::size_t l = 0; l < kLanes; ++l) {
      corner_x[l] = 256.0 * static_cast<double>(x[l < count ? l : 0]);
      corner_y[l] = 256.0 * static_cast<double>(y[l < count ? l : 0]);
    }
    const Doubles cx = Doubles::load_aligned(corner_x);
    const Doubles cy = Doubles::load_aligned(corner_y);
    const Doubles zero(0.0), one(1.0), inv(1.0 / 256.0);
    Doubles sum(0.0);
    for (int e = 0; e < 3; ++e) {
      // The edge's ends in the pixel's frame, in pixels: exact (multiples of 1/256 below 2^17).
      const Doubles p_x = (Doubles(px_[e]) - cx) * inv;
      const Doubles q_x = (Doubles(qx_[e]) - cx) * inv;
      const Doubles p_y = (Doubles(py_[e]) - cy) * inv;
      const Doubles xs = xsimd::min(xsimd::max(p_x, zero), one);
      const Doubles xe = xsimd::min(xsimd::max(q_x, zero), one);
      const Doubles slope(slope_[e]);
      const Doubles ys = p_y + (xs - p_x) * slope;
      const Doubles ye = p_y + (xe - p_x) * slope;
      const Doubles p = xsimd::min(ys, ye), q = xsimd::max(ys, ye);
      const Doubles pc = xsimd::min(xsimd::max(p, zero), one);
      const Doubles qc = xsimd::min(xsimd::max(q, zero), one);
      const Doubles num =
          (qc - pc) * (qc + pc) * Doubles(0.5) + xsimd::max(q, one) - xsimd::max(p, one);
      const Doubles spread = q - p;
      const auto wide = spread >= Doubles(0x1p-26);
      const Doubles mean = xsimd::select(wide, num / xsimd::select(wide, spread, one),
                                         xsimd::min(xsimd::max((p + q) * Doubles(0.5), zero), one));
      sum = sum + (xe - xs) * mean;
    }
    const Doubles area = xsimd::min(xsimd::max(sum * Doubles(orientation_), zero), one);
    alignas(64) double lanes[kLanes];
    area.store_aligned(lanes);
    for (std::size_t l = 0; l < count; ++l)
      out[l] = static_cast<float>(lanes[l]);
  }

 private:
  double px_[3], py_[3], qx_[3], slope_[3];
  double orientation_;
};

// Candidate pixels of one band: up to three ranges, one per edge piece, [begin, end).
struct BandRanges {
  std::int32_t begin[3], end[3];
  int count = 0;
};

// The pixels of row band y (pixel rows y .. y + 1) that each edge's piece within the band
// touches, not clipped (the section's extent decides which pixels are inside). Conservative by
// one fixed-point unit each way: a pixel the piece only grazes gets its area computed, which is
// then exact too. Every band the triangle reaches holds a piece of each side of it.
inline BandRanges band_ranges(const AreaTriangle& tri, std::int32_t y) {
  BandRanges ranges;
  const std::int64_t band_top = std::int64_t{y} * 256, band_bottom = band_top + 256;
  for (int e = 0; e < 3; ++e) {
    const int j = e == 2 ? 0 : e + 1;
    const std::int64_t ax = tri.x[e], ay = tri.y[e], bx = tri.x[j], by = tri.y[j];
    const std::int64_t low = ay < by ? ay : by, high = ay < by ? by : ay;
    if (high < band_top || low > band_bottom) continue;
    double left, right;
    if (ay == by) {
      left = static_cast<double>(ax < bx ? ax : bx);
      right = static_cast<double>(ax < bx ? bx : ax);
    } else {
      // x where the edge crosses the band's top and bottom (clamped to the edge's ends).
      const double top = static_cast<double>(low > band_top ? low : band_top);
      const double bottom = static_cast<double>(high < band_bottom ? high : band_bottom);
      const double inverse_slope = static_cast<double>(bx - ax) / static_cast<double>(by - ay);
      const double xt = static_cast<double>(ax) + (top - static_cast<double>(ay)) * inverse_slope;
      const double xb =
          static_cast<double>(ax) + (bottom - static_cast<double>(ay)) * inverse_slope;
      left = xt < xb ? xt : xb;
      right = xt < xb ? xb : xt;
    }
    ranges.begin[ranges.count] = static_cast<std::int32_t>(std::floor((left - 1.0) / 256.0));
    ranges.end[ranges.count] = static_cast<std::int32_t>(std::floor((right + 1.0) / 256.0)) + 1;
    ++ranges.count;
  }
  return ranges;
}

// Walks a triangle's box a tile row at a time and hands its tiles to `emit` (AreaTile&) in row
// order. `row_tiles` is the caller's storage, reused from triangle to triangle.
template <class Arch, class Emit>
void walk_areas(const AreaTriangle& tri, const PixelRect& box, std::vector<AreaTile>& row_tiles,
                std::uint32_t triangle, Emit&& emit) {
  const AreaBatch<Arch> batch(tri);
  constexpr std::size_t kLanes = AreaBatch<Arch>::kLanes;
  const std::int32_t first_tile_x = box.x0 / kTileSize;
  const std::int32_t columns = (box.x1 - 1) / kTileSize - first_tile_x + 1;
  row_tiles.resize(static_cast<std::size_t>(columns));
  for (std::int32_t ty = box.y0 / kTileSize; ty <= (box.y1 - 1) / kTileSize; ++ty) {
    for (std::int32_t c = 0; c < columns; ++c) {
      AreaTile& tile = row_tiles[static_cast<std::size_t>(c)];
      tile.triangle = triangle;
      tile.tile_x = static_cast<std::uint16_t>(first_tile_x + c);
      tile.tile_y = static_cast<std::uint16_t>(ty);
      tile.mask = 0;
      for (float& a : tile.area)
        a = 0.0f;
    }
    const auto set = [&](std::int32_t x, std::int32_t y, float area) {
      if (!(area > 0.0f)) return;
      AreaTile& tile = row_tiles[static_cast<std::size_t>(x / kTileSize - first_tile_x)];
      const int bit = (y % kTileSize) * kTileSize + x % kTileSize;
      tile.mask |= std::uint64_t{1} << bit;
      tile.area[bit] = area;
    };
    // Pixels [x_begin, x_end) of row y lie wholly inside.
    const auto fill_whole = [&](std::int32_t y, std::int32_t x_begin, std::int32_t x_end) {
      const int row = y % kTileSize;
      for (std::int32_t x = x_begin; x < x_end;) {
        const std::int32_t tile_left = x - x % kTileSize;
        const std::int32_t stop = tile_left + kTileSize < x_end ? tile_left + kTileSize : x_end;
        AreaTile& tile = row_tiles[static_cast<std::size_t>(tile_left / kTileSize - first_tile_x)];
        tile.mask |= (column_bits(x - tile_left, stop - tile_left) & 0xFFu) << (kTileSize * row);
        for (std::int32_t c = x - tile_left; c < stop - tile_left; ++c)
          tile.area[row * kTileSize + c] = 1.0f;
        x = stop;
      }
    };
    // Candidates wait for a whole batch of lanes, across the tile row's pixel rows.
    alignas(64) std::int32_t pending_x[kLanes], pending_y[kLanes];
    float areas[kLanes];
    std::size_t waiting = 0;
    const auto flush = [&] {
      batch.areas(pending_x, pending_y, areas, waiting);
      for (std::size_t l = 0; l < waiting; ++l)
        set(pending_x[l], pending_y[l], areas[l]);
      waiting = 0;
    };
    const std::int32_t y_end = (ty + 1) * kTileSize < box.y1 ? (ty + 1) * kTileSize : box.y1;
    for (std::int32_t y = ty * kTileSize > box.y0 ? ty * kTileSize : box.y0; y < y_end; ++y) {
      const BandRanges ranges = band_ranges(tri, y);
      if (ranges.count == 0) continue;
      // The candidates as disjoint runs in x order, clipped to the box; between the first and
      // the last, the gaps are whole pixels.
      std::int32_t begin[3], end[3];
      int runs = 0;
      std::int32_t span_begin = box.x1, span_end = box.x0;
      for (int r = 0; r < ranges.count; ++r) {
        const std::int32_t b = ranges.begin[r] < box.x0 ? box.x0 : ranges.begin[r];
        const std::int32_t e = ranges.end[r] > box.x1 ? box.x1 : ranges.end[r];
        span_begin = ranges.begin[r] < span_begin ? ranges.begin[r] : span_begin;
        span_end = ranges.end[r] > span_end ? ranges.end[r] : span_end;
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
      std::int32_t covered_to = span_begin;  // pixels below this are decided
      for (int r = 0; r < runs; ++r) {
        if (begin[r] > covered_to) fill_whole(y, covered_to, begin[r]);
        for (std::int32_t x = begin[r] > covered_to ? begin[r] : covered_to; x < end[r]; ++x) {
          pending_x[waiting] = x;
          pending_y[waiting++] = y;
          if (waiting == kLanes) flush();
        }
        covered_to = end[r] > covered_to ? end[r] : covered_to;
      }
      if (span_end > covered_to) fill_whole(y, covered_to, span_end);
    }
    if (waiting != 0) flush();
    for (const AreaTile& tile : row_tiles) {
      if (tile.mask != 0) emit(tile);
    }
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
