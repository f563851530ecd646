#include "pixel_area_reference.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "../core/reference_kernels.hpp"
#include "../coverage/coverage_reference.hpp"

namespace edgewise::reference {
namespace {

// Error analysis of pixel_area() (kPixelAreaErrorBound = 2^-44 px^2).
//
// Work happens in the pixel's frame, in pixels: the square is [0, 1]^2. Edge i's function at
// (u, v) is E = a u + b v + c with a = -256 (y_j - y_i), b = 256 (x_j - x_i) and c the edge
// function at the square's corner, all in fixed-point units (1/256 px) and exact: the snapped
// coordinates lie in [-2^23, 2^23), so |a|, |b| < 2^32 and |c| < 2^49 are integers below 2^53.
// - At the square's corners every E is exact (integers below 2^51), so a line that misses the
//   square leaves all four corners on one side, decided exactly, and makes no crossing.
// - A line that cuts the square has |c| = |a u + b v| <= |a| + |b| for some (u, v) in the
//   square. At a point of the square E then errs by at most 3 ulps of |a| + |b| <= 2^0.5 n
//   (n = |(a, b)|): 3 * 2^0.5 * 2^-52 n, a distance to the line below 2^-49 px. So a vertex is
//   put on the wrong side only within 2^-49 px of the line, and a crossing (t = e_p / (e_p -
//   e_q), then one multiply-add per coordinate) lands within 2^-49 + 2^-51 px of the line.
// - Intersecting with the same half-plane never enlarges the symmetric difference between the
//   computed and the exact polygon; each clip adds at most the band of those widths along its
//   chord (at most 2^0.5 px long): 2^0.5 * 2^-48.6 < 2^-48 px^2. Three clips: below 2^-46.
// - The shoelace sum (at most 7 terms, products of coordinates in [0, 1] within 2^-48 of it)
//   adds at most 16 * 2^-53 = 2^-49.
// In all below 2^-45 px^2; the bound states 2^-44.
constexpr std::size_t kMaxVertices = 4 + 3;  // a square clipped by three lines

struct Point {
  double u, v;
};

struct Polygon {
  Point p[kMaxVertices + 1];  // one spare: a clip adds at most one vertex
  std::size_t n = 0;
};

// The part of `in` on the interior side (orientation * E >= 0) of the line E = a u + b v + c.
Polygon clip(const Polygon& in, double a, double b, double c, double orientation) {
  Polygon out;
  for (std::size_t k = 0; k < in.n; ++k) {
    const Point& p = in.p[k];
    const Point& q = in.p[(k + 1) % in.n];
    const double ep = orientation * (a * p.u + b * p.v + c);
    const double eq = orientation * (a * q.u + b * q.v + c);
    if (ep >= 0) out.p[out.n++] = p;
    if ((ep >= 0) != (eq >= 0)) {
      const double t = ep / (ep - eq);
      out.p[out.n++] = {p.u + t * (q.u - p.u), p.v + t * (q.v - p.v)};
    }
  }
  return out;
}

double shoelace_area(const Polygon& polygon) {
  double twice = 0.0;
  for (std::size_t k = 0; k < polygon.n; ++k) {
    const Point& p = polygon.p[k];
    const Point& q = polygon.p[(k + 1) % polygon.n];
    twice += p.u * q.v - q.u * p.v;
  }
  return std::fabs(twice) / 2.0;
}

std::int64_t twice_area_fixed(const SnappedTriangle& t) {
  return (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
}

}  // namespace

double pixel_area(const SnappedTriangle& tri, std::int32_t px, std::int32_t py) {
  // The interior is where every edge function has the sign of twice the area.
  const double orientation = twice_area_fixed(tri) > 0 ? 1.0 : -1.0;
  const std::int64_t corner_x = std::int64_t{px} * 256, corner_y = std::int64_t{py} * 256;
  Polygon polygon;
  polygon.p[0] = {0, 0};
  polygon.p[1] = {1, 0};
  polygon.p[2] = {1, 1};
  polygon.p[3] = {0, 1};
  polygon.n = 4;
  for (int i = 0; i < 3 && polygon.n > 0; ++i) {
    const int j = (i + 1) % 3;
    const std::int64_t dx = tri.x[j] - tri.x[i], dy = tri.y[j] - tri.y[i];
    // E(p) = cross(v_i, v_j, p) = dx (p_y - y_i) - dy (p_x - x_i), p = corner + 256 (u, v).
    const std::int64_t c = dx * (corner_y - tri.y[i]) - dy * (corner_x - tri.x[i]);
    polygon = clip(polygon, static_cast<double>(-dy * 256), static_cast<double>(dx * 256),
                   static_cast<double>(c), orientation);
  }
  return polygon.n < 3 ? 0.0 : shoelace_area(polygon);
}

double triangle_area(const SnappedTriangle& tri) {
  const std::int64_t twice = twice_area_fixed(tri);
  // Exact: |twice| < 2^50 converts exactly, and the scaling is by a power of two.
  return static_cast<double>(twice < 0 ? -twice : twice) / (2.0 * 65536.0);
}

// Every pixel of the triangle's candidate box (widened by a pixel: squares reach half a pixel
// past their centres) by the exact-area reference, tile by tile in row order.
void rasterize_areas(const detail::TriangleBatch& batch, AreaSink& sink, RasterReport& report) {
  std::vector<AreaTile> tiles;
  for_each_drawn_triangle(batch, report, [&](std::size_t t, const SnappedTriangle& snapped) {
    PixelRect box = candidate_pixels(snapped, batch.clip);
    box = {std::max(box.x0 - 1, batch.clip.x0), std::max(box.y0 - 1, batch.clip.y0),
           std::min(box.x1 + 1, batch.clip.x1), std::min(box.y1 + 1, batch.clip.y1)};
    if (box.empty()) return;
    for (std::int32_t ty = box.y0 / kTileSize; ty <= (box.y1 - 1) / kTileSize; ++ty) {
      for (std::int32_t tx = box.x0 / kTileSize; tx <= (box.x1 - 1) / kTileSize; ++tx) {
        AreaTile tile{static_cast<std::uint32_t>(t),
                      static_cast<std::uint16_t>(tx),
                      static_cast<std::uint16_t>(ty),
                      0,
                      {}};
        for (int bit = 0; bit < kTileSize * kTileSize; ++bit) {
          const std::int32_t px = tx * kTileSize + bit % kTileSize;
          const std::int32_t py = ty * kTileSize + bit / kTileSize;
          if (px < box.x0 || px >= box.x1 || py < box.y0 || py >= box.y1) continue;
          const double area = pixel_area(snapped, px, py);
          if (area > 0.0) {
            tile.mask |= std::uint64_t{1} << bit;
            tile.area[bit] = static_cast<float>(area);
          }
        }
        if (tile.mask != 0) tiles.push_back(tile);
      }
    }
  });
  if (!tiles.empty()) sink.consume(tiles);
}

}  // namespace edgewise::reference
