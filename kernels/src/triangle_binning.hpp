// Sort-middle binning (docs/DESIGN.md, "Threads"): the clip rectangle cut into screen bins, each
// triangle's status decided once, and its corner indices appended to the lists of the bins its
// box overlaps, one set of lists per range of triangles.
#pragma once

#include <cstddef>
#include <cstdint>
#include <memory>
#include <vector>

#include "edgewise/coverage.hpp"
#include "kernel_table.hpp"

namespace edgewise::detail {

// Bins are kBinWidth x kBinHeight pixels, aligned to multiples of their size, so every 8x8 tile
// (and its depth bound) lies in exactly one bin. Measured on AMD Zen 5 with the Shading
// benchmarks: see docs/DESIGN.md, "Threads".
inline constexpr std::int32_t kBinWidth = 128;
inline constexpr std::int32_t kBinHeight = 64;
static_assert(kBinWidth % kTileSize == 0 && kBinHeight % kTileSize == 0);

// The bins over a clip rectangle: bin (column, row) is the clip rectangle within
// [(first_column + column) * kBinWidth, ... + kBinWidth) x (likewise in y).
struct BinGrid {
  PixelRect clip;
  std::int32_t first_column = 0, first_row = 0, columns = 0, rows = 0;

  explicit BinGrid(const PixelRect& clip_rect);
  std::size_t count() const { return static_cast<std::size_t>(columns) * rows; }
  PixelRect rect(std::size_t bin) const;
};

// The status the kernels' setup gives a triangle with these (unsnapped) vertices, computed the
// same way in double (kernels/generic/triangle_setup-inl.hpp, setup_triangles), and for a drawn
// triangle its box: the pixels whose samples lie within its snapped bounding box, clipped to
// `clip` (possibly empty).
TriangleStatus classify_triangle(const Vec2 vertices[3], CullMode cull, const PixelRect& clip,
                                 PixelRect& box);

// One list of corner indices (three per triangle, as TriangleBatch::indices) per range and bin.
// The lists' storage is kept from call to call: a call borrows a set from a process-wide pool
// (a lock taken once per call) and gives it back when done.
class BinLists {
 public:
  using Lists = std::vector<std::vector<std::uint32_t>>;
  // ranges x bins empty lists.
  BinLists(std::size_t ranges, std::size_t bins);
  ~BinLists();
  BinLists(const BinLists&) = delete;
  BinLists& operator=(const BinLists&) = delete;

  // The grid.count() lists of one range, for bin_triangles().
  std::vector<std::uint32_t>* range_lists(std::size_t range) {
    return lists_->data() + range * bins_;
  }
  const std::vector<std::uint32_t>& list(std::size_t range, std::size_t bin) const {
    return (*lists_)[range * bins_ + bin];
  }

 private:
  std::unique_ptr<Lists> lists_;
  std::size_t bins_;
};

// Triangles [first, last) of `batch` (its clip rectangle is the grid's): each gets the status
// run_batch would give it, written to batch.statuses when present and counted into `report`
// (triangles, drawn, culled, errors, the first error by triangle index); drawn triangles whose
// clipped box is not empty are appended to `lists` (grid.count() of them) of every bin their box
// overlaps, as their three corner indices into batch.vertices.
void bin_triangles(const TriangleBatch& batch, std::size_t first, std::size_t last,
                   const BinGrid& grid, std::vector<std::uint32_t>* lists, RasterReport& report);

// Adds `part`, the report of a later range of triangles, to `total`.
void add_range_report(RasterReport& total, const RasterReport& part);

// How many ranges to bin `triangles` in with `threads` threads: enough for every thread, but
// no range shorter than kMinTrianglesPerRange (below it, a range costs more to manage than to
// bin).
inline constexpr std::size_t kMinTrianglesPerRange = 2048;
std::size_t binning_ranges(std::size_t triangles, std::size_t threads);

}  // namespace edgewise::detail
