// Sort-middle binning (docs/design/threads.md): the clip rectangle cut into screen bins, each
// triangle's status decided once, and its corner indices appended to the lists of the bins its
// box overlaps, one set of lists per range of triangles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "edgewise/coverage.hpp"
#include "bin_grid.hpp"
#include "triangle_batch.hpp"

namespace edgewise::detail {

// The status the kernels' setup gives a triangle with these (unsnapped) vertices, computed the
// same way in double (kernels/coverage/triangle_setup-inl.hpp, setup_triangles), and for a drawn
// triangle its box: the pixels whose samples lie within its snapped bounding box, clipped to
// `clip` (possibly empty). Samples up to `sample_reach` fixed-point units (1/256 px) from the
// pixel centre widen the box by that much each way.
TriangleStatus classify_triangle(const Vec2 vertices[3], CullMode cull, const PixelRect& clip,
                                 PixelRect& box, std::int32_t sample_reach = 0);

// The corner indices of one bin's triangles from one range, three per triangle, as
// TriangleBatch::indices takes them. Appending is one capacity check per triangle (binning runs
// once per triangle; see docs/design/threads.md); the storage is kept when emptied.
class CornerList {
 public:
  void append(const std::uint32_t corner[3]) {
    if (capacity_ - size_ < 3) grow();
    std::uint32_t* end = data_.get() + size_;
    end[0] = corner[0];
    end[1] = corner[1];
    end[2] = corner[2];
    size_ += 3;
  }
  void clear() { size_ = 0; }
  bool empty() const { return size_ == 0; }
  std::size_t triangles() const { return size_ / 3; }
  const std::uint32_t* data() const { return data_.get(); }

 private:
  void grow();
  std::unique_ptr<std::uint32_t[]> data_;
  std::size_t size_ = 0, capacity_ = 0;
};

// One CornerList per range and bin, and each list's triangle count once its range is binned.
// The lists' storage is kept from call to call: a call borrows a set from a process-wide pool
// (a lock taken once per call) and gives it back when done. Each range's task empties its own
// lists and records their counts, so that the calling thread, which plans the bins' tasks, reads
// one compact array (a count per range and bin) and never the lists that other cores wrote.
class BinLists {
 public:
  // ranges x bins lists, emptied by start_range().
  BinLists(std::size_t ranges, std::size_t bins);
  ~BinLists();
  BinLists(const BinLists&) = delete;
  BinLists& operator=(const BinLists&) = delete;

  // The grid.count() lists of one range, emptied, for its task to bin into.
  CornerList* start_range(std::size_t range);
  // Records the triangle count of each of the range's lists, for triangles() (its task calls
  // it once the range is binned).
  void count_range(std::size_t range);

  // The lists from `first` on, as they are (a caller with lists laid out its own way).
  CornerList* lists_from(std::size_t first) { return storage_->lists.data() + first; }
  const CornerList& list(std::size_t range, std::size_t bin) const {
    return storage_->lists[range * bins_ + bin];
  }
  // The triangles of range `range` in bin `bin`, as count_range() recorded them.
  std::size_t triangles(std::size_t range, std::size_t bin) const {
    return storage_->counts[range * bins_ + bin];
  }

  struct Storage {
    std::vector<CornerList> lists;
    std::vector<std::size_t> counts;
  };

 private:
  std::unique_ptr<Storage> storage_;
  std::size_t bins_;
};

// Triangles [first, last) of `batch` (its clip rectangle is the grid's): each gets the status
// run_batch would give it, written to batch.statuses when present and counted into `report`
// (triangles, drawn, culled, errors, the first error by triangle index); drawn triangles whose
// clipped box is not empty are appended to `lists` (grid.count() of them) of every bin their box
// overlaps, as their three corner indices into batch.vertices.
void bin_triangles(const TriangleBatch& batch, std::size_t first, std::size_t last,
                   const BinGrid& grid, CornerList* lists, RasterReport& report);

// bin_triangles() for draw(), whose report needs no statuses and counts only culled triangles
// and errors, and whose triangles mostly fall in one bin: a triangle that can only reach one bin
// goes there undecided, and the kernel call of that bin decides and counts its status (the
// caller adds the culled triangles and errors of those calls); any other is decided here as
// bin_triangles() does, and only drawn ones are binned, so every triangle is counted once.
// `report` counts all triangles, and those decided here.
void bin_screen_triangles(const TriangleBatch& batch, std::size_t first, std::size_t last,
                          const BinGrid& grid, CornerList* lists, RasterReport& report);
// bin_screen_triangles() of triangles whose bins drop_culled_triangles() found (BinOutput, one
// per triangle of the batch): each one with a bin goes straight to that bin's list.
void bin_screen_triangles(const TriangleBatch& batch, std::size_t first, std::size_t last,
                          const BinGrid& grid, const std::uint32_t* bins, CornerList* lists,
                          RasterReport& report);

// Adds `part`, the report of a later range of triangles, to `total`.
void add_range_report(RasterReport& total, const RasterReport& part);

// How many ranges to bin `triangles` in with `threads` threads: one per thread, but no range
// shorter than kMinTrianglesPerRange (below it, a range costs more to manage than to bin); and
// up to kRangesPerThread per thread while ranges keep kTrianglesPerExtraRange triangles, so that
// on a mesh of millions of triangles a thread that starts late or runs slow leaves its share to
// the others rather than hold the phase open (docs/design/threads.md says what was measured).
inline constexpr std::size_t kMinTrianglesPerRange = 2048;
inline constexpr std::size_t kRangesPerThread = 4;
inline constexpr std::size_t kTrianglesPerExtraRange = 32768;
std::size_t binning_ranges(std::size_t triangles, std::size_t threads);

}  // namespace edgewise::detail
