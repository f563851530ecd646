// The scalar reference rasterizer: the oracle every fast path is compared with.
//
// It is the bounding-box loop of the textbook, made exact: every candidate pixel's sample is
// tested against the three edge functions in 64-bit integers, straight from the snapped
// vertices, with the top-left rule taken literally from its definition. It shares no code with
// the fast kernels.
#pragma once

#include <cstdint>
#include <functional>
#include <span>

#include "edgewise/coverage.hpp"
#include "edgewise/multisample.hpp"
#include "bin_grid.hpp"

namespace edgewise::detail {
struct DroppedTriangles;
struct SampleWindow;
struct TriangleBatch;
}  // namespace edgewise::detail

namespace edgewise::reference {

// A triangle after snapping to 1/256 px, in its input order (not re-wound).
struct SnappedTriangle {
  std::int64_t x[3], y[3];
};

// Validates and snaps; returns drawn, culled_* or error_* exactly as the fast paths must.
TriangleStatus snap_and_classify(const Vec2& p0, const Vec2& p1, const Vec2& p2, CullMode cull,
                                 SnappedTriangle& out);

// Whether the sample of pixel (px, py) is covered (the triangle must have nonzero area).
bool covers(const SnappedTriangle& tri, std::int32_t px, std::int32_t py);

// The same for the pixel's sample at `offset` from its centre (multisample.hpp): the same edge
// functions and top-left rule, at a point of the same 1/256 px grid.
bool covers_sample(const SnappedTriangle& tri, std::int32_t px, std::int32_t py,
                   SampleOffset offset);

// Pixels that may hold a covered sample (a generous box; covers() decides), clipped.
PixelRect candidate_pixels(const SnappedTriangle& tri, const PixelRect& clip);

// Delivers the triangle's tile masks row by row, as the fast paths do.
void for_each_tile(const SnappedTriangle& tri, const PixelRect& clip,
                   const std::function<void(std::uint32_t, std::uint32_t, std::uint64_t)>& tile);

// The same for every sample of `pattern`: tile(tile_x, tile_y, sample, mask) for each tile and
// sample with a covered sample, tiles row by row, samples in pattern order within a tile.
void for_each_multisample_tile(
    const SnappedTriangle& tri, const PixelRect& clip, std::span<const SampleOffset> pattern,
    const std::function<void(std::uint32_t, std::uint32_t, std::uint8_t, std::uint64_t)>& tile);

// Validates every triangle of a batch in order, counting statuses into the report (and the
// batch's status array) as the fast paths do, and calls `triangle` for each drawn one.
void for_each_drawn_triangle(
    const detail::TriangleBatch& batch, RasterReport& report,
    const std::function<void(std::size_t, const SnappedTriangle&)>& triangle);

}  // namespace edgewise::reference
