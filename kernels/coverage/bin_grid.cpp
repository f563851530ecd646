// The screen bins of a binned call (bin_grid.hpp).
#include "bin_grid.hpp"

#include <algorithm>

namespace edgewise::detail {

BinGrid::BinGrid(const PixelRect& clip_rect, int width_bits, int height_bits)
    : clip(clip_rect), width_shift(width_bits), height_shift(height_bits) {
  if (clip.empty()) return;
  // clip_rect() keeps the clip rectangle within the target: no negative coordinates.
  first_column = clip.x0 >> width_shift;
  first_row = clip.y0 >> height_shift;
  columns = ((clip.x1 - 1) >> width_shift) - first_column + 1;
  rows = ((clip.y1 - 1) >> height_shift) - first_row + 1;
}

BinGrid::BinGrid(const PixelRect& clip_rect, std::size_t threads, int samples) : clip(clip_rect) {
  for (const auto& size : kBinSizes) {
    *this = BinGrid(clip_rect, size[0], size[1]);
    const std::size_t bytes = (std::size_t{8} * static_cast<std::size_t>(samples))
                              << (size[0] + size[1]);
    if (samples > 1 && bytes > kMultisampleBinBytes) continue;
    if (count() >= kBinsPerThread * threads) break;
  }
}

PixelRect BinGrid::rect(std::size_t bin) const {
  const std::int32_t column = first_column + static_cast<std::int32_t>(bin % columns);
  const std::int32_t row = first_row + static_cast<std::int32_t>(bin / columns);
  return {std::max(clip.x0, column << width_shift), std::max(clip.y0, row << height_shift),
          std::min(clip.x1, (column + 1) << width_shift),
          std::min(clip.y1, (row + 1) << height_shift)};
}

}  // namespace edgewise::detail
