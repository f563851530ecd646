// Exact-area coverage: for each pixel, how much of its square [i, i + 1) x [j, j + 1) a snapped
// triangle covers, in square pixels. It is the ground truth of every anti-aliasing mode, and a
// rendering mode of its own for shapes whose triangles do not overlap or share pixels (coverage-
// weighted blending); docs/design/anti-aliasing.md, says where it is wrong (conflation at
// shared edges).
//
// Accuracy: every ISA's area lies within kPixelAreaTolerance of the exact area of the pixel's
// square inside the snapped triangle (docs/design/exact-area.md says how it is derived).
//
// Thread safety: as rasterize() (coverage.hpp): no state is kept between calls; the sink sees
// tiles on the calling thread, in the order stated below.
#pragma once

#include <cstdint>
#include <span>

#include "edgewise/coverage.hpp"

namespace edgewise {

// |area - exact area| never exceeds this, in square pixels, on any ISA.
inline constexpr double kPixelAreaTolerance = 1e-6;

struct AreaTile {
  std::uint32_t triangle;  // index of the triangle in the call
  std::uint16_t tile_x, tile_y;
  std::uint64_t mask;  // pixels with a nonzero area, bit (y * 8 + x); never 0
  float area[64];  // pixel (tile_x * 8 + x, tile_y * 8 + y)'s area at [y * 8 + x]; 0 off the mask
};

// Receives the tiles of each triangle in triangle order; within a triangle, tiles come row by
// row (tile_y ascending, then tile_x ascending). Batches are at most a few dozen tiles.
class AreaSink {
 public:
  virtual ~AreaSink() = default;
  virtual void consume(std::span<const AreaTile> tiles) = 0;
};

// The area of every pixel each triangle touches, clipped to the target and scissor. Triangles,
// statuses, culling and errors as rasterize(); RasterOptions::samples and threads are ignored.
// Throws std::invalid_argument for a bad target, scissor, index count or options.
RasterReport rasterize_areas(std::span<const Vec2> vertices, std::span<const std::uint32_t> indices,
                             const RasterTarget& target, const RasterOptions& options,
                             AreaSink& sink);

}  // namespace edgewise
