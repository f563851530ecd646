// What the occlusion kernels read: the buffer's tiled depths with their exact per-tile maxima,
// and rectangles already turned into ranges of samples.
#pragma once

#include <cstddef>
#include <cstdint>

namespace edgewise::detail {

// Entries of OcclusionDepth::tile_max past the last tile, none above any depth (-inf): a kernel
// may read that many past a row's end.
inline constexpr std::int32_t kTileMaximaPadding = 16;

// The depth of an OcclusionBuffer, in the Framebuffer's tiled layout (framebuffer.hpp).
struct OcclusionDepth {
  const float* tiles = nullptr;     // 64 per 8x8 tile, row by row
  const float* tile_max = nullptr;  // the largest of each tile's 64 depths, then the padding
  std::int32_t tiles_x = 0;
};

// The samples (x, y) with x0 <= x <= x1 and y0 <= y <= y1, all in the view, and a depth that
// occludes them when it is at least every stored depth among them. An empty range (x0 > x1)
// holds no sample of the view: outside.
struct SampleRect {
  std::int32_t x0 = 0, y0 = 0, x1 = -1, y1 = -1;
  float depth = 0.0f;
};

}  // namespace edgewise::detail
