// The triangle loop every coverage and drawing kernel shares: fetch, set up and walk every
// triangle of a batch, a group of setup lanes at a time, delivering its tiles to an inlined
// visitor (begin_triangle, tile, full_tiles).
#pragma once

#include <cstddef>
#include <cstdint>
#include <type_traits>

#include "../src/kernel_table.hpp"
#include "lane_arch-inl.hpp"
#include "span_walk-inl.hpp"
#include "tile_walk-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

using Arch = RowArch<EDGEWISE_ARCH>;

// Which walk a triangle takes, measured with the coverage benchmark on AMD Zen 3: the span walk
// overtakes the per-tile walk once the clipped box holds roughly 500 pixels (triangles of about
// 150 px) on AVX2 and SSE4.1; on SSE2, which has no double rounding instruction, it never does.
inline constexpr std::int64_t kSpanWalkMinBoxArea =
    std::is_same_v<Arch, xsimd::sse2> ? INT64_MAX : 576;

inline bool prefers_span_walk(const PixelRect& box) {
  return std::int64_t{box.x1 - box.x0} * (box.y1 - box.y0) >= kSpanWalkMinBoxArea;
}

// Fetches, sets up and walks every triangle of the batch, a group of setup lanes at a time.
// The walks (walk_block, walk_spans, walk_tiles) are kept out of line: with one visitor per
// translation unit the compiler inlined them into this loop, which ran the coverage benchmark's
// 8-px triangles 9% slower on AVX2 (AMD Zen 4) with fewer instructions.
template <class Visitor>
void run_batch(const detail::TriangleBatch& batch, Visitor& visitor, RasterReport& report) {
  constexpr std::size_t kLanes = kSetupLanes<Arch>;
  report.triangles += batch.triangle_count;
  TriangleGroup<Arch> group;
  GroupCorners<Arch> corners;
  TriangleSetup setups[kLanes];
  TriangleStatus statuses[kLanes];
  bool visible[kLanes];
  for (std::size_t first = 0; first < batch.triangle_count; first += kLanes) {
    const std::size_t count =
        batch.triangle_count - first < kLanes ? batch.triangle_count - first : kLanes;
    corners.first = first;
    for (std::size_t l = 0; l < kLanes; ++l) {
      // Lanes past the end repeat the last triangle; their results are ignored.
      const std::size_t t = first + (l < count ? l : count - 1);
      std::size_t* corner = corners.vertex[l];
      for (int i = 0; i < 3; ++i) {
        corner[i] = batch.indices != nullptr ? batch.indices[3 * t + i] : 3 * t + i;
      }
      corners.valid[l] = true;
      for (int i = 0; i < 3; ++i) {
        Vec2 v{0.0f, 0.0f};
        if (corner[i] < batch.vertex_count) {
          v = batch.vertices[corner[i]];
        } else {
          corners.valid[l] = false;
        }
        group.x[i][l] = v.x;
        group.y[i][l] = v.y;
      }
    }
    setup_triangles<Arch>(group, batch.clip, batch.cull, setups, statuses, visible);
    // Visitors that set up per-triangle state for a whole group do it here.
    if constexpr (requires { visitor.begin_group(corners, group); }) {
      visitor.begin_group(corners, group);
    }
    for (std::size_t l = 0; l < count; ++l) {
      const std::size_t t = first + l;
      const TriangleStatus status =
          corners.valid[l] ? statuses[l] : TriangleStatus::error_bad_index;
      if (batch.statuses != nullptr) batch.statuses[t] = status;
      if (status == TriangleStatus::drawn) {
        ++report.drawn;
        if (!visible[l]) continue;
        visitor.begin_triangle(static_cast<std::uint32_t>(t));
        const TriangleSetup& setup = setups[l];
        const PixelRect& box = setup.box;
        // The block walks are chosen by the unclipped box (setup.extent), which holds the
        // clipped one: a triangle takes the same walk whichever bin it is drawn in.
        if (setup.narrow && setup.extent <= kTileSize) {
          walk_block<Arch>(setup, visitor);
        } else if (setup.narrow && setup.extent <= 2 * kTileSize) {
          walk_block_16<Arch>(setup, visitor);
        } else if (prefers_span_walk(box) && span_walk_is_exact(setup)) {
          walk_spans<Arch>(setup, visitor);
        } else if (setup.narrow) {
          walk_tiles<Arch, std::int32_t>(setup, visitor);
        } else {
          walk_tiles<Arch, std::int64_t>(setup, visitor);
        }
      } else {
        detail::count_not_drawn(report, t, status);
      }
    }
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
