// The screen bins of a binned call (docs/design/threads.md): the clip rectangle cut into
// aligned rectangles of a power-of-two size, and the one bin that holds a box, when one does.
#pragma once

#include <cstddef>
#include <cstdint>

#include "edgewise/coverage.hpp"

namespace edgewise::detail {

// The bins over a clip rectangle. Bins are 2^width_shift x 2^height_shift pixels, at least 8x8
// and aligned to multiples of their size, so every 8x8 tile (and its depth bound) lies in
// exactly one bin; bin (column, row) is the clip rectangle within
// [(first_column + column) << width_shift, ...) x [(first_row + row) << height_shift, ...).
struct BinGrid {
  PixelRect clip;
  int width_shift = 0, height_shift = 0;
  std::int32_t first_column = 0, first_row = 0, columns = 0, rows = 0;

  // The largest bins of kBinSizes that still give every thread kBinsPerThread of them (the
  // smallest when none does); measured in docs/design/threads.md. For a multisampled target
  // (`samples` > 1), also no larger than keeps a bin's colour and depth within
  // kMultisampleBinBytes, so that a bin's samples stay in the core's cache while it is drawn.
  BinGrid(const PixelRect& clip_rect, std::size_t threads, int samples = 1);
  BinGrid(const PixelRect& clip_rect, int width_shift, int height_shift);
  std::size_t count() const { return static_cast<std::size_t>(columns) * rows; }
  PixelRect rect(std::size_t bin) const;
};

// Bin sizes as (log2 width, log2 height), largest first.
inline constexpr int kBinSizes[][2] = {{9, 8}, {8, 7}, {7, 7}, {7, 6}, {6, 6}};
inline constexpr std::size_t kBinsPerThread = 8;
// A bin holding over a thread's share of the triangles, and at least kMinSplitTriangles,
// is crowded: it is cut into sub-bins of about a task's share each (kTasksPerThread tasks to a
// thread), no smaller than 2^kMinSplitBinShift px a side (kernels/draw/shading_plan.cpp,
// plan_shading()).
inline constexpr std::size_t kTasksPerThread = 4;
inline constexpr std::size_t kMinSplitTriangles = 256;
inline constexpr int kMinSplitBinShift = 4;
// Half the 1 MiB L2 cache of a Zen 4 or Zen 5 core: 128 x 128 px at 4 samples of 8 bytes.
inline constexpr std::size_t kMultisampleBinBytes = std::size_t{1} << 19;

// The bin of a box that lies in one bin, else kSeveralBins (as for an empty box).
inline constexpr std::uint32_t kSeveralBins = UINT32_MAX;
inline std::uint32_t single_bin_of(const BinGrid& grid, const PixelRect& box) {
  if (box.empty()) return kSeveralBins;
  // The box lies in the clip rectangle, so its coordinates are not negative.
  const std::int32_t column = box.x0 >> grid.width_shift, row = box.y0 >> grid.height_shift;
  if (column != (box.x1 - 1) >> grid.width_shift || row != (box.y1 - 1) >> grid.height_shift)
    return kSeveralBins;
  return static_cast<std::uint32_t>(row - grid.first_row) *
             static_cast<std::uint32_t>(grid.columns) +
         static_cast<std::uint32_t>(column - grid.first_column);
}

// Where drop_culled_triangles() writes, for a binned call, the bin of each triangle it keeps:
// bins[k] for the k-th kept triangle, single_bin_of() its box when set-up would draw it (the
// pixels with a sample within its snapped vertices' bounds, in the clip rectangle), else
// kSeveralBins. No output when `grid` is null.
struct BinOutput {
  const BinGrid* grid = nullptr;
  std::uint32_t* bins = nullptr;
};

}  // namespace edgewise::detail
