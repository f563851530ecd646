// Sort-middle binning: bin grids, triangle statuses decided once per call, per-bin lists.
#include "triangle_binning.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

namespace edgewise::detail {
namespace {

std::int32_t floor_div(std::int32_t a, std::int32_t b) {
  return a >= 0 ? a / b : -((-a + b - 1) / b);
}

// The pool of lists that calls borrow (BinLists).
struct ListPool {
  std::mutex mutex;
  std::vector<std::unique_ptr<BinLists::Lists>> free;
};
ListPool& list_pool() {
  static ListPool pool;
  return pool;
}

}  // namespace

BinGrid::BinGrid(const PixelRect& clip_rect) : clip(clip_rect) {
  if (clip.empty()) return;
  first_column = floor_div(clip.x0, kBinWidth);
  first_row = floor_div(clip.y0, kBinHeight);
  columns = floor_div(clip.x1 - 1, kBinWidth) - first_column + 1;
  rows = floor_div(clip.y1 - 1, kBinHeight) - first_row + 1;
}

PixelRect BinGrid::rect(std::size_t bin) const {
  const std::int32_t column = first_column + static_cast<std::int32_t>(bin % columns);
  const std::int32_t row = first_row + static_cast<std::int32_t>(bin / columns);
  return {std::max(clip.x0, column * kBinWidth), std::max(clip.y0, row * kBinHeight),
          std::min(clip.x1, (column + 1) * kBinWidth), std::min(clip.y1, (row + 1) * kBinHeight)};
}

TriangleStatus classify_triangle(const Vec2 vertices[3], CullMode cull, const PixelRect& clip,
                                 PixelRect& box) {
  // setup_triangles' steps, one lane at a time: the same exact double operations.
  constexpr double kBand = static_cast<double>(kGuardBand << kSubpixelBits);
  double x[3], y[3];
  bool in_band = true, finite = true;
  for (int i = 0; i < 3; ++i) {
    const double sx = static_cast<double>(vertices[i].x) * 256.0;
    const double sy = static_cast<double>(vertices[i].y) * 256.0;
    x[i] = std::nearbyint(sx);
    y[i] = std::nearbyint(sy);
    in_band =
        in_band && std::fabs(sx) <= kBand && std::fabs(sy) <= kBand && x[i] < kBand && y[i] < kBand;
    finite = finite && std::isfinite(vertices[i].x) && std::isfinite(vertices[i].y);
  }
  if (!in_band) {
    return finite ? TriangleStatus::error_outside_guard_band : TriangleStatus::error_non_finite;
  }
  // Exact: products of 25-bit differences (triangle_setup-inl.hpp's overflow analysis).
  const double area2 = (x[1] - x[0]) * (y[2] - y[0]) - (y[1] - y[0]) * (x[2] - x[0]);
  if (area2 == 0.0) return TriangleStatus::culled_zero_area;
  if ((cull == CullMode::clockwise && area2 > 0.0) ||
      (cull == CullMode::counter_clockwise && area2 < 0.0)) {
    return TriangleStatus::culled_winding;
  }
  const double min_x = std::min({x[0], x[1], x[2]}), max_x = std::max({x[0], x[1], x[2]});
  const double min_y = std::min({y[0], y[1], y[2]}), max_y = std::max({y[0], y[1], y[2]});
  constexpr double kInvPixel = 1.0 / 256.0;
  box.x0 = std::max(static_cast<std::int32_t>(std::floor((min_x + 127.0) * kInvPixel)), clip.x0);
  box.y0 = std::max(static_cast<std::int32_t>(std::floor((min_y + 127.0) * kInvPixel)), clip.y0);
  box.x1 =
      std::min(static_cast<std::int32_t>(std::floor((max_x - 128.0) * kInvPixel)) + 1, clip.x1);
  box.y1 =
      std::min(static_cast<std::int32_t>(std::floor((max_y - 128.0) * kInvPixel)) + 1, clip.y1);
  return TriangleStatus::drawn;
}

BinLists::BinLists(std::size_t ranges, std::size_t bins) : bins_(bins) {
  ListPool& pool = list_pool();
  {
    const std::lock_guard lock(pool.mutex);
    if (!pool.free.empty()) {
      lists_ = std::move(pool.free.back());
      pool.free.pop_back();
    }
  }
  if (!lists_) lists_ = std::make_unique<Lists>();
  if (lists_->size() < ranges * bins) lists_->resize(ranges * bins);
  for (std::size_t i = 0; i < ranges * bins; ++i)
    (*lists_)[i].clear();
}

BinLists::~BinLists() {
  ListPool& pool = list_pool();
  const std::lock_guard lock(pool.mutex);
  pool.free.push_back(std::move(lists_));
}

void bin_triangles(const TriangleBatch& batch, std::size_t first, std::size_t last,
                   const BinGrid& grid, std::vector<std::uint32_t>* lists, RasterReport& report) {
  report.triangles += last - first;
  for (std::size_t t = first; t < last; ++t) {
    std::uint32_t corner[3] = {static_cast<std::uint32_t>(3 * t),
                               static_cast<std::uint32_t>(3 * t + 1),
                               static_cast<std::uint32_t>(3 * t + 2)};
    if (batch.indices != nullptr) {
      for (int i = 0; i < 3; ++i)
        corner[i] = batch.indices[3 * t + i];
    }
    TriangleStatus status = TriangleStatus::drawn;
    PixelRect box{};
    if (corner[0] >= batch.vertex_count || corner[1] >= batch.vertex_count ||
        corner[2] >= batch.vertex_count) {
      status = TriangleStatus::error_bad_index;
    } else {
      const Vec2 v[3] = {batch.vertices[corner[0]], batch.vertices[corner[1]],
                         batch.vertices[corner[2]]};
      status = classify_triangle(v, batch.cull, grid.clip, box);
    }
    if (batch.statuses != nullptr) batch.statuses[t] = status;
    if (status != TriangleStatus::drawn) {
      count_not_drawn(report, t, status);
      continue;
    }
    ++report.drawn;
    if (box.empty()) continue;
    const std::int32_t column0 = box.x0 / kBinWidth - grid.first_column;
    const std::int32_t column1 = (box.x1 - 1) / kBinWidth - grid.first_column;
    const std::int32_t row0 = box.y0 / kBinHeight - grid.first_row;
    const std::int32_t row1 = (box.y1 - 1) / kBinHeight - grid.first_row;
    for (std::int32_t row = row0; row <= row1; ++row) {
      std::vector<std::uint32_t>* row_lists = lists + static_cast<std::size_t>(row) * grid.columns;
      for (std::int32_t column = column0; column <= column1; ++column)
        row_lists[column].insert(row_lists[column].end(), corner, corner + 3);
    }
  }
}

void add_range_report(RasterReport& total, const RasterReport& part) {
  if (total.errors == 0 && part.errors != 0) {
    total.first_error_triangle = part.first_error_triangle;
    total.first_error = part.first_error;
  }
  total.triangles += part.triangles;
  total.drawn += part.drawn;
  total.culled += part.culled;
  total.errors += part.errors;
}

std::size_t binning_ranges(std::size_t triangles, std::size_t threads) {
  const std::size_t by_size = (triangles + kMinTrianglesPerRange - 1) / kMinTrianglesPerRange;
  return std::max<std::size_t>(1, std::min(threads, by_size));
}

}  // namespace edgewise::detail
