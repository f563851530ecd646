// Sort-middle binning: bin grids, triangle statuses decided once per call, per-bin lists.
#include "triangle_binning.hpp"

#include <algorithm>
#include <cmath>
#include <mutex>

namespace edgewise::detail {
namespace {

// The pool of lists that calls borrow (BinLists).
struct ListPool {
  std::mutex mutex;
  std::vector<std::unique_ptr<BinLists::Storage>> free;
};
ListPool& list_pool() {
  static ListPool pool;
  return pool;
}

}  // namespace

TriangleStatus classify_triangle(const Vec2 vertices[3], CullMode cull, const PixelRect& clip,
                                 PixelRect& box, std::int32_t sample_reach) {
  // setup_triangles' decisions, one triangle at a time, in its exact arithmetic, without a
  // library call (this runs once per triangle of a binned call; see docs/design/threads.md).
  // Scaling by 256 is exact in double, and |scaled| <= 2^23 fails for NaN and infinity.
  constexpr double kBand = static_cast<double>(kGuardBand << kSubpixelBits);
  double scaled[6];
  bool in_band = true;
  for (int i = 0; i < 3; ++i) {
    scaled[2 * i] = static_cast<double>(vertices[i].x) * 256.0;
    scaled[2 * i + 1] = static_cast<double>(vertices[i].y) * 256.0;
    in_band = in_band && std::fabs(scaled[2 * i]) <= kBand && std::fabs(scaled[2 * i + 1]) <= kBand;
  }
  // Adding and subtracting 1.5 * 2^52 rounds a double below 2^51 to an integer, ties to even,
  // as nearbyint() does in the default rounding mode; after rounding only 2^23 itself can leave
  // the band.
  constexpr double kRound = 0x1.8p52;
  std::int32_t fixed[6] = {};
  for (int i = 0; i < 6 && in_band; ++i) {
    const double rounded = (scaled[i] + kRound) - kRound;
    in_band = rounded < kBand;
    fixed[i] = static_cast<std::int32_t>(rounded);
  }
  if (!in_band) {
    bool finite = true;
    for (int i = 0; i < 3; ++i)
      finite = finite && std::isfinite(vertices[i].x) && std::isfinite(vertices[i].y);
    return finite ? TriangleStatus::error_outside_guard_band : TriangleStatus::error_non_finite;
  }
  const std::int64_t x0 = fixed[0], y0 = fixed[1], x1 = fixed[2], y1 = fixed[3], x2 = fixed[4],
                     y2 = fixed[5];
  // Exact in int64 as in double: products of 25-bit differences (the overflow analysis of
  // triangle_setup-inl.hpp).
  const std::int64_t area2 = (x1 - x0) * (y2 - y0) - (y1 - y0) * (x2 - x0);
  if (area2 == 0) return TriangleStatus::culled_zero_area;
  if ((cull == CullMode::clockwise && area2 > 0) ||
      (cull == CullMode::counter_clockwise && area2 < 0)) {
    return TriangleStatus::culled_winding;
  }
  // floor((min + 127) / 256) and floor((max - 128) / 256) + 1 as setup_triangles takes them:
  // an arithmetic shift is the floor of an exact division by 256.
  const std::int32_t min_x = std::min({fixed[0], fixed[2], fixed[4]});
  const std::int32_t max_x = std::max({fixed[0], fixed[2], fixed[4]});
  const std::int32_t min_y = std::min({fixed[1], fixed[3], fixed[5]});
  const std::int32_t max_y = std::max({fixed[1], fixed[3], fixed[5]});
  // Samples up to sample_reach from the centre widen it both ways.
  box.x0 = std::max((min_x + 127 - sample_reach) >> kSubpixelBits, clip.x0);
  box.y0 = std::max((min_y + 127 - sample_reach) >> kSubpixelBits, clip.y0);
  box.x1 = std::min(((max_x - 128 + sample_reach) >> kSubpixelBits) + 1, clip.x1);
  box.y1 = std::min(((max_y - 128 + sample_reach) >> kSubpixelBits) + 1, clip.y1);
  return TriangleStatus::drawn;
}

void CornerList::grow() {
  const std::size_t capacity = 2 * capacity_ + 96;
  std::unique_ptr<std::uint32_t[]> data(new std::uint32_t[capacity]);
  std::copy(data_.get(), data_.get() + size_, data.get());
  data_ = std::move(data);
  capacity_ = capacity;
}

BinLists::BinLists(std::size_t ranges, std::size_t bins) : bins_(bins) {
  ListPool& pool = list_pool();
  {
    const std::lock_guard lock(pool.mutex);
    if (!pool.free.empty()) {
      storage_ = std::move(pool.free.back());
      pool.free.pop_back();
    }
  }
  if (!storage_) storage_ = std::make_unique<Storage>();
  if (storage_->lists.size() < ranges * bins) {
    storage_->lists.resize(ranges * bins);
    storage_->counts.resize(ranges * bins);
  }
}

CornerList* BinLists::start_range(std::size_t range) {
  CornerList* lists = storage_->lists.data() + range * bins_;
  for (std::size_t bin = 0; bin < bins_; ++bin)
    lists[bin].clear();
  return lists;
}

void BinLists::count_range(std::size_t range) {
  const CornerList* lists = storage_->lists.data() + range * bins_;
  std::size_t* counts = storage_->counts.data() + range * bins_;
  for (std::size_t bin = 0; bin < bins_; ++bin)
    counts[bin] = lists[bin].triangles();
}

BinLists::~BinLists() {
  ListPool& pool = list_pool();
  const std::lock_guard lock(pool.mutex);
  pool.free.push_back(std::move(storage_));
}

namespace {

// Appends a triangle to the lists of every bin its box (clipped, not empty) overlaps.
void append_to_bins(const BinGrid& grid, CornerList* lists, const PixelRect& box,
                    const std::uint32_t corner[3]) {
  // The box lies in the clip rectangle, so its coordinates are not negative.
  const std::int32_t column0 = (box.x0 >> grid.width_shift) - grid.first_column;
  const std::int32_t column1 = ((box.x1 - 1) >> grid.width_shift) - grid.first_column;
  const std::int32_t row0 = (box.y0 >> grid.height_shift) - grid.first_row;
  const std::int32_t row1 = ((box.y1 - 1) >> grid.height_shift) - grid.first_row;
  for (std::int32_t row = row0; row <= row1; ++row) {
    CornerList* row_lists = lists + static_cast<std::size_t>(row) * grid.columns;
    for (std::int32_t column = column0; column <= column1; ++column)
      row_lists[column].append(corner);
  }
}

// The triangle's corners, or false for an index past the end of the vertex array.
bool fetch_corners(const TriangleBatch& batch, std::size_t t, std::uint32_t corner[3]) {
  for (int i = 0; i < 3; ++i) {
    const std::size_t c = 3 * t + static_cast<std::size_t>(i);
    corner[i] = batch.indices != nullptr ? batch.indices[c] : static_cast<std::uint32_t>(c);
  }
  return corner[0] < batch.vertex_count && corner[1] < batch.vertex_count &&
         corner[2] < batch.vertex_count;
}

// The one bin that holds every sample the triangle can cover, judged from its vertices before
// snapping, or -1 when that takes its exact box (it may reach several bins, or its coordinates
// are too large, or not finite, for this estimate). Snapping moves a vertex by at most 1/512 px,
// and pixel i is covered only when i + 0.5 lies within the snapped vertices' range, so only
// pixels from floor(min) to floor(max) can be; one more on each side absorbs the float
// rounding. Samples of a multisample pattern, up to half a pixel from their centres
// (`multisample`), reach one pixel further each way. A triangle wholly outside the clip rectangle
// is given the nearest bin: it covers nothing there, but the bin's kernel call decides and counts
// its status.
std::ptrdiff_t single_bin(const BinGrid& grid, const Vec2 v[3], bool multisample) {
  const float min_x = std::min({v[0].x, v[1].x, v[2].x});
  const float max_x = std::max({v[0].x, v[1].x, v[2].x});
  const float min_y = std::min({v[0].y, v[1].y, v[2].y});
  const float max_y = std::max({v[0].y, v[1].y, v[2].y});
  constexpr float kLimit = kGuardBand;
  if (!(min_x > -kLimit && max_x < kLimit && min_y > -kLimit && max_y < kLimit)) return -1;
  // Truncating a positive double is its floor; the offset keeps it positive.
  constexpr double kOffset = kGuardBand + 2;
  const auto floor_of = [](float value) {
    return static_cast<std::int32_t>(static_cast<double>(value) + kOffset) -
           static_cast<std::int32_t>(kOffset);
  };
  const PixelRect& clip = grid.clip;
  const auto clamp_x = [&](std::int32_t x) { return std::clamp(x, clip.x0, clip.x1 - 1); };
  const auto clamp_y = [&](std::int32_t y) { return std::clamp(y, clip.y0, clip.y1 - 1); };
  const std::int32_t margin = multisample ? 2 : 1;
  const std::int32_t column0 = clamp_x(floor_of(min_x) - margin) >> grid.width_shift;
  const std::int32_t column1 = clamp_x(floor_of(max_x) + margin) >> grid.width_shift;
  const std::int32_t row0 = clamp_y(floor_of(min_y) - margin) >> grid.height_shift;
  const std::int32_t row1 = clamp_y(floor_of(max_y) + margin) >> grid.height_shift;
  if (column0 != column1 || row0 != row1) return -1;
  return static_cast<std::ptrdiff_t>(row0 - grid.first_row) * grid.columns +
         (column0 - grid.first_column);
}

// How far the batch's samples reach from their pixel centres, in fixed-point units: a
// multisample pattern's at most 8/16 px, 128 units.
std::int32_t sample_reach(const TriangleBatch& batch) {
  return batch.samples.size() > 1 ? 128 : 0;
}

}  // namespace

void bin_triangles(const TriangleBatch& batch, std::size_t first, std::size_t last,
                   const BinGrid& grid, CornerList* lists, RasterReport& report) {
  report.triangles += last - first;
  for (std::size_t t = first; t < last; ++t) {
    std::uint32_t corner[3];
    TriangleStatus status = TriangleStatus::error_bad_index;
    PixelRect box{};
    if (fetch_corners(batch, t, corner)) {
      const Vec2 v[3] = {batch.vertices[corner[0]], batch.vertices[corner[1]],
                         batch.vertices[corner[2]]};
      status = classify_triangle(v, batch.cull, grid.clip, box, sample_reach(batch));
    }
    if (batch.statuses != nullptr) batch.statuses[t] = status;
    if (status != TriangleStatus::drawn) {
      count_not_drawn(report, t, status);
      continue;
    }
    ++report.drawn;
    if (!box.empty()) append_to_bins(grid, lists, box, corner);
  }
}

// Triangle t of bin_screen_triangles().
[[gnu::always_inline]] inline void bin_screen_triangle(const TriangleBatch& batch, std::size_t t,
                                                       const BinGrid& grid, CornerList* lists,
                                                       RasterReport& report) {
  std::uint32_t corner[3];
  if (!fetch_corners(batch, t, corner)) {
    count_not_drawn(report, t, TriangleStatus::error_bad_index);
    return;
  }
  const Vec2 v[3] = {batch.vertices[corner[0]], batch.vertices[corner[1]],
                     batch.vertices[corner[2]]};
  const std::ptrdiff_t bin = single_bin(grid, v, batch.samples.size() > 1);
  if (bin >= 0) {  // its status is counted by the bin's kernel call
    lists[bin].append(corner);
    return;
  }
  PixelRect box{};
  const TriangleStatus status =
      classify_triangle(v, batch.cull, grid.clip, box, sample_reach(batch));
  if (status != TriangleStatus::drawn) {
    count_not_drawn(report, t, status);
    return;
  }
  ++report.drawn;
  if (!box.empty()) append_to_bins(grid, lists, box, corner);
}

void bin_screen_triangles(const TriangleBatch& batch, std::size_t first, std::size_t last,
                          const BinGrid& grid, CornerList* lists, RasterReport& report) {
  report.triangles += last - first;
  for (std::size_t t = first; t < last; ++t)
    bin_screen_triangle(batch, t, grid, lists, report);
}

void bin_screen_triangles(const TriangleBatch& batch, std::size_t first, std::size_t last,
                          const BinGrid& grid, const std::uint32_t* bins, CornerList* lists,
                          RasterReport& report) {
  report.triangles += last - first;
  for (std::size_t t = first; t < last; ++t) {
    if (bins[t] == kSeveralBins) {
      bin_screen_triangle(batch, t, grid, lists, report);
      continue;
    }
    // Drawn (drop_culled_triangles() decided it): the bin's kernel call counts it.
    lists[bins[t]].append(batch.indices + 3 * t);
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
  const std::size_t most =
      std::max(threads, std::min(kRangesPerThread * threads, triangles / kTrianglesPerExtraRange));
  return std::max<std::size_t>(1, std::min(most, by_size));
}

}  // namespace edgewise::detail
