#include "coverage_reference.hpp"

#include <algorithm>
#include <cmath>
#include <vector>

#include "../core/reference_kernels.hpp"

namespace edgewise::reference {
namespace {

constexpr double kFixedScale = 256.0;
constexpr double kBandFixed = 32768.0 * kFixedScale;

// Twice the signed area of (a, b, c) in fixed-point units squared.
std::int64_t cross(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by,
                   std::int64_t cx, std::int64_t cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

// docs/design/rasterization.md, "Fill rule and watertightness": a top edge is exactly horizontal
// with the third vertex below it (larger y); a left edge is not horizontal and has the interior
// (the third vertex's side) to its right.
bool is_top_left(std::int64_t ax, std::int64_t ay, std::int64_t bx, std::int64_t by,
                 std::int64_t cx, std::int64_t cy) {
  if (ay == by) return cy > ay;
  // x of the edge's line at height cy is xa + (xb - xa)(cy - ya)/(yb - ya); c is to the
  // right when cx exceeds it. Multiply through by (yb - ya), minding its sign.
  const std::int64_t lhs = (cx - ax) * (by - ay);
  const std::int64_t rhs = (bx - ax) * (cy - ay);
  return by > ay ? lhs > rhs : lhs < rhs;
}

}  // namespace

TriangleStatus snap_and_classify(const Vec2& p0, const Vec2& p1, const Vec2& p2, CullMode cull,
                                 SnappedTriangle& out) {
  const Vec2 p[3] = {p0, p1, p2};
  for (const Vec2& v : p) {
    if (!std::isfinite(v.x) || !std::isfinite(v.y)) return TriangleStatus::error_non_finite;
  }
  for (int i = 0; i < 3; ++i) {
    const double sx = std::nearbyint(static_cast<double>(p[i].x) * kFixedScale);
    const double sy = std::nearbyint(static_cast<double>(p[i].y) * kFixedScale);
    if (sx < -kBandFixed || sx >= kBandFixed || sy < -kBandFixed || sy >= kBandFixed) {
      return TriangleStatus::error_outside_guard_band;
    }
    out.x[i] = static_cast<std::int64_t>(sx);
    out.y[i] = static_cast<std::int64_t>(sy);
  }
  const std::int64_t area2 = cross(out.x[0], out.y[0], out.x[1], out.y[1], out.x[2], out.y[2]);
  if (area2 == 0) return TriangleStatus::culled_zero_area;
  const bool clockwise = area2 > 0;  // y points down, so a positive cross is clockwise
  if ((cull == CullMode::clockwise && clockwise) ||
      (cull == CullMode::counter_clockwise && !clockwise)) {
    return TriangleStatus::culled_winding;
  }
  return TriangleStatus::drawn;
}

bool covers(const SnappedTriangle& t, std::int32_t px, std::int32_t py) {
  return covers_sample(t, px, py, SampleOffset{0, 0});
}

bool covers_sample(const SnappedTriangle& t, std::int32_t px, std::int32_t py,
                   SampleOffset offset) {
  // The pixel's centre moved by the offset (1/16 px = 16 fixed-point steps).
  const std::int64_t sx = std::int64_t{px} * 256 + 128 + 16 * std::int64_t{offset.x};
  const std::int64_t sy = std::int64_t{py} * 256 + 128 + 16 * std::int64_t{offset.y};
  const std::int64_t area2 = cross(t.x[0], t.y[0], t.x[1], t.y[1], t.x[2], t.y[2]);
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3, k = (i + 2) % 3;
    const std::int64_t e = cross(t.x[i], t.y[i], t.x[j], t.y[j], sx, sy);
    const bool inside = area2 > 0 ? e > 0 : e < 0;
    const bool on_edge = e == 0;
    if (!inside && !(on_edge && is_top_left(t.x[i], t.y[i], t.x[j], t.y[j], t.x[k], t.y[k]))) {
      return false;
    }
  }
  return true;
}

PixelRect candidate_pixels(const SnappedTriangle& t, const PixelRect& clip) {
  const auto [min_x, max_x] = std::minmax({t.x[0], t.x[1], t.x[2]});
  const auto [min_y, max_y] = std::minmax({t.y[0], t.y[1], t.y[2]});
  // One pixel of margin on each side: floor division of the extremes is enough to be generous.
  const auto pixel_floor = [](std::int64_t v) { return static_cast<std::int32_t>(v >> 8); };
  return PixelRect{
      std::max(clip.x0, pixel_floor(min_x) - 1), std::max(clip.y0, pixel_floor(min_y) - 1),
      std::min(clip.x1, pixel_floor(max_x) + 2), std::min(clip.y1, pixel_floor(max_y) + 2)};
}

void for_each_tile(const SnappedTriangle& t, const PixelRect& clip,
                   const std::function<void(std::uint32_t, std::uint32_t, std::uint64_t)>& tile) {
  const PixelRect box = candidate_pixels(t, clip);
  if (box.empty()) return;
  for (std::int32_t ty = box.y0 / kTileSize; ty <= (box.y1 - 1) / kTileSize; ++ty) {
    for (std::int32_t tx = box.x0 / kTileSize; tx <= (box.x1 - 1) / kTileSize; ++tx) {
      std::uint64_t mask = 0;
      for (int y = 0; y < kTileSize; ++y) {
        for (int x = 0; x < kTileSize; ++x) {
          const std::int32_t px = tx * kTileSize + x, py = ty * kTileSize + y;
          const bool in_box = px >= box.x0 && px < box.x1 && py >= box.y0 && py < box.y1;
          if (in_box && covers(t, px, py)) mask |= std::uint64_t{1} << (y * kTileSize + x);
        }
      }
      if (mask != 0) tile(static_cast<std::uint32_t>(tx), static_cast<std::uint32_t>(ty), mask);
    }
  }
}

void for_each_multisample_tile(
    const SnappedTriangle& t, const PixelRect& clip, std::span<const SampleOffset> pattern,
    const std::function<void(std::uint32_t, std::uint32_t, std::uint8_t, std::uint64_t)>& tile) {
  // Samples lie inside their pixel's square, so the centres' generous box holds them too.
  const PixelRect box = candidate_pixels(t, clip);
  if (box.empty()) return;
  for (std::int32_t ty = box.y0 / kTileSize; ty <= (box.y1 - 1) / kTileSize; ++ty) {
    for (std::int32_t tx = box.x0 / kTileSize; tx <= (box.x1 - 1) / kTileSize; ++tx) {
      for (std::size_t k = 0; k < pattern.size(); ++k) {
        std::uint64_t mask = 0;
        for (int y = 0; y < kTileSize; ++y) {
          for (int x = 0; x < kTileSize; ++x) {
            const std::int32_t px = tx * kTileSize + x, py = ty * kTileSize + y;
            const bool in_box = px >= box.x0 && px < box.x1 && py >= box.y0 && py < box.y1;
            if (in_box && covers_sample(t, px, py, pattern[k])) {
              mask |= std::uint64_t{1} << (y * kTileSize + x);
            }
          }
        }
        if (mask != 0) {
          tile(static_cast<std::uint32_t>(tx), static_cast<std::uint32_t>(ty),
               static_cast<std::uint8_t>(k), mask);
        }
      }
    }
  }
}

}  // namespace edgewise::reference

namespace edgewise::reference {

void for_each_drawn_triangle(
    const detail::TriangleBatch& batch, RasterReport& report,
    const std::function<void(std::size_t, const SnappedTriangle&)>& triangle) {
  report.triangles += batch.triangle_count;
  for (std::size_t t = 0; t < batch.triangle_count; ++t) {
    std::size_t idx[3] = {3 * t, 3 * t + 1, 3 * t + 2};
    if (batch.indices != nullptr) {
      for (int i = 0; i < 3; ++i)
        idx[i] = batch.indices[3 * t + i];
    }
    TriangleStatus status = TriangleStatus::error_bad_index;
    SnappedTriangle snapped{};
    if (idx[0] < batch.vertex_count && idx[1] < batch.vertex_count && idx[2] < batch.vertex_count) {
      status = snap_and_classify(batch.vertices[idx[0]], batch.vertices[idx[1]],
                                 batch.vertices[idx[2]], batch.cull, snapped);
    }
    if (batch.statuses != nullptr) batch.statuses[t] = status;
    if (status == TriangleStatus::drawn) {
      ++report.drawn;
      triangle(t, snapped);
    } else {
      detail::count_not_drawn(report, t, status);
    }
  }
}

namespace {

// The smallest integer at least a / 256.
std::int64_t ceil_fixed_to_pixels(std::int64_t a) {
  const std::int64_t q = a / 256;
  return q * 256 < a ? q + 1 : q;
}

// Whether some sample of `window` lies between the snapped triangle's smallest and largest
// coordinates on both axes: a pixel of the clip rectangle whose samples, from its centre
// 256 i + 128 less the reach to the centre plus the reach, meet [lo, hi]. The first pixel whose
// last sample reaches lo is the only one to try: later pixels' first samples lie further on.
bool box_holds_sample(const SnappedTriangle& t, const detail::SampleWindow& window) {
  const auto axis_meets = [&](const std::int64_t(&v)[3], std::int32_t first, std::int32_t end) {
    const std::int64_t lo = std::min({v[0], v[1], v[2]}), hi = std::max({v[0], v[1], v[2]});
    const std::int64_t i =
        std::max<std::int64_t>(ceil_fixed_to_pixels(lo - 128 - window.reach), first);
    return i < end && 256 * i + 128 - window.reach <= hi;
  };
  return axis_meets(t.x, window.clip.x0, window.clip.x1) &&
         axis_meets(t.y, window.clip.y0, window.clip.y1);
}

// The largest integer at most a / 256.
std::int64_t floor_fixed_to_pixels(std::int64_t a) {
  const std::int64_t q = a / 256;
  return q * 256 > a ? q - 1 : q;
}

// The pixels of the window's clip rectangle with a sample between the snapped triangle's
// smallest and largest coordinates on both axes (from the first whose last sample reaches lo to
// the last whose first sample is within hi), as set-up bounds its walk.
PixelRect sample_box(const SnappedTriangle& t, const detail::SampleWindow& window) {
  const auto axis = [&](const std::int64_t(&v)[3], std::int32_t first, std::int32_t end,
                        std::int32_t& from, std::int32_t& to) {
    const std::int64_t lo = std::min({v[0], v[1], v[2]}), hi = std::max({v[0], v[1], v[2]});
    from = static_cast<std::int32_t>(
        std::max<std::int64_t>(ceil_fixed_to_pixels(lo - 128 - window.reach), first));
    to = static_cast<std::int32_t>(
        std::min<std::int64_t>(floor_fixed_to_pixels(hi - 128 + window.reach) + 1, end));
  };
  PixelRect box{};
  axis(t.x, window.clip.x0, window.clip.x1, box.x0, box.x1);
  axis(t.y, window.clip.y0, window.clip.y1, box.y0, box.y1);
  return box;
}

}  // namespace

// Drops from `indices` each triangle whose indices are in range and that snap_and_classify()
// culls, or draws with no sample of `window` between its vertices' bounds, one at a time; the
// rest keep their order; with a grid in `output`, the bin of each kept triangle's box, computed
// from its snapped vertices.
detail::DroppedTriangles drop_culled_triangles(const Vec2* vertices, std::size_t vertex_count,
                                               std::uint32_t* indices, std::size_t triangles,
                                               CullMode cull, const detail::SampleWindow& window,
                                               const detail::BinOutput& output) {
  detail::DroppedTriangles result;
  for (std::size_t t = 0; t < triangles; ++t) {
    const std::uint32_t corner[3] = {indices[3 * t], indices[3 * t + 1], indices[3 * t + 2]};
    std::uint32_t bin = detail::kSeveralBins;
    if (corner[0] < vertex_count && corner[1] < vertex_count && corner[2] < vertex_count) {
      SnappedTriangle snapped;
      const TriangleStatus status = snap_and_classify(vertices[corner[0]], vertices[corner[1]],
                                                      vertices[corner[2]], cull, snapped);
      if (status == TriangleStatus::culled_zero_area || status == TriangleStatus::culled_winding) {
        ++result.culled;
        continue;
      }
      if (status == TriangleStatus::drawn && !box_holds_sample(snapped, window)) {
        ++result.unseen;
        continue;
      }
      if (status == TriangleStatus::drawn && output.grid != nullptr)
        bin = detail::single_bin_of(*output.grid, sample_box(snapped, window));
    }
    for (int i = 0; i < 3; ++i)
      indices[3 * result.kept + i] = corner[i];
    if (output.grid != nullptr) output.bins[result.kept] = bin;
    ++result.kept;
  }
  return result;
}

// The reference's coverage kernels (kernel_table.hpp).

namespace {

// Runs the reference over a batch; `tile` receives (triangle, tile_x, tile_y, mask, sample):
// pixel centres (sample 0) or, with a multisample pattern, every sample of it.
template <class TileFn>
void for_each_covered_tile(const detail::TriangleBatch& batch, RasterReport& report,
                           TileFn&& tile) {
  for_each_drawn_triangle(batch, report, [&](std::size_t t, const SnappedTriangle& snapped) {
    const auto triangle = static_cast<std::uint32_t>(t);
    if (batch.samples.size() > 1) {
      for_each_multisample_tile(snapped, batch.clip, batch.samples,
                                [&](std::uint32_t tx, std::uint32_t ty, std::uint8_t sample,
                                    std::uint64_t mask) { tile(triangle, tx, ty, mask, sample); });
      return;
    }
    for_each_tile(snapped, batch.clip, [&](std::uint32_t tx, std::uint32_t ty, std::uint64_t mask) {
      tile(triangle, tx, ty, mask, std::uint8_t{0});
    });
  });
}

}  // namespace

void rasterize(const detail::TriangleBatch& batch, CoverageSink& sink, RasterReport& report) {
  std::vector<TileCoverage> tiles;
  for_each_covered_tile(batch, report,
                        [&](std::uint32_t t, std::uint32_t tx, std::uint32_t ty, std::uint64_t mask,
                            std::uint8_t sample) {
                          tiles.push_back({t, static_cast<std::uint16_t>(tx),
                                           static_cast<std::uint16_t>(ty), mask, sample});
                        });
  if (!tiles.empty()) sink.consume(tiles);
}

void count_coverage(const detail::TriangleBatch& batch, RasterReport& report,
                    std::uint64_t& pixels) {
  for_each_covered_tile(
      batch, report,
      [&](std::uint32_t, std::uint32_t, std::uint32_t, std::uint64_t mask, std::uint8_t) {
        for (; mask != 0; mask &= mask - 1)
          ++pixels;  // plain bit counting, no intrinsics
      });
}

}  // namespace edgewise::reference
