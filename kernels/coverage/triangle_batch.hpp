// What the coverage kernels take: a validated batch of 2D triangles, where a draw's samples can
// be, what culling removed, and the rule by which a triangle that is not drawn is counted, shared
// by every ISA and the reference so that their reports agree by construction.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>

#include "edgewise/coverage.hpp"
#include "edgewise/multisample.hpp"

namespace edgewise::detail {

// clip_rect() for the entry point `caller`, which its messages name.
PixelRect checked_clip_rect(const RasterTarget& target, std::string_view caller);

// Where a draw's samples can be: the pixels of `clip`, each with samples up to `reach`
// fixed-point units (1/256 px) from its centre on either axis (0 for one sample per pixel).
struct SampleWindow {
  PixelRect clip;
  std::int32_t reach = 0;
};

// What drop_culled_triangles() removed: the triangles set-up culls, and those it would draw
// but whose box (the snapped vertices' bounds) holds no sample of the window, so that they
// cannot cover one: `unseen`, drawn as far as the report goes. `kept` triangles remain.
struct DroppedTriangles {
  std::size_t kept = 0, culled = 0, unseen = 0;
};

// A validated call: the target is already reduced to one clip rectangle.
struct TriangleBatch {
  const Vec2* vertices;
  std::size_t vertex_count;
  const std::uint32_t* indices;  // null: triangle t is vertices 3t .. 3t+2
  std::size_t triangle_count;
  PixelRect clip;
  CullMode cull;
  TriangleStatus* statuses;  // null or triangle_count entries
  // The multisample pattern (multisample.hpp) of the multisample kernels; the others sample
  // pixel centres.
  std::span<const SampleOffset> samples = {};
};

// Counts a triangle that was not drawn into the report: errors (remembering the first one) or
// culled. Shared by every ISA and the reference, so their reports agree by construction.
inline void count_not_drawn(RasterReport& report, std::size_t triangle, TriangleStatus status) {
  if (is_error(status)) {
    if (report.errors++ == 0) {
      report.first_error_triangle = triangle;
      report.first_error = status;
    }
  } else {
    ++report.culled;
  }
}

}  // namespace edgewise::detail
