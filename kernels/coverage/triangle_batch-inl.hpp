// The triangle loop every coverage and drawing kernel shares: fetch, set up and walk every
// triangle of a batch, a group of setup lanes at a time, delivering its tiles to an inlined
// visitor (begin_group and begin_triangle(t, lane), or begin_triangle(t); tile, full_tiles).
#pragma once

#include <cstddef>
#include <cstdint>
#include <concepts>
#include <type_traits>

#include "edgewise/coverage.hpp"
#include "triangle_batch.hpp"
#include "../simd/lane_arch-inl.hpp"
#include "block_setup-inl.hpp"
#include "multisample_walk-inl.hpp"
#include "span_walk-inl.hpp"
#include "tile_walk-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

using Arch = RowArch<EDGEWISE_ARCH>;

// Which walk a triangle takes when masks are wanted: the span walk from the box area where it
// overtakes the per-tile walk, never on SSE2, which has no double rounding instruction
// (docs/design/rasterization.md, "Tiles and masks", says where the threshold was measured).
inline constexpr std::int64_t kSpanWalkMinBoxArea =
    std::is_same_v<Arch, xsimd::sse2> ? INT64_MAX : 576;

// A visitor that only counts (add_pixels) takes the span walk's counts above this extent: an 8x8
// box counts faster by the block walk, which makes one mask, larger ones by the spans' lengths.
// SSE2 emulates the span walk's double floor and int32 multiplies and minima, so there only
// boxes of 576 pixels or more count by spans (docs/design/rasterization.md, "Tiles and masks").
inline constexpr std::int32_t kCountSpansMinExtent = 8;
inline constexpr std::int64_t kCountSpansMinBoxArea = std::is_same_v<Arch, xsimd::sse2> ? 576 : 0;

inline bool prefers_span_count(const TriangleSetup& setup) {
  if constexpr (kCountSpansMinBoxArea > 0) {
    if (std::int64_t{setup.box.x1 - setup.box.x0} * (setup.box.y1 - setup.box.y0) <
        kCountSpansMinBoxArea) {
      return false;
    }
  }
  return setup.extent > kCountSpansMinExtent;
}

inline bool prefers_span_walk(const PixelRect& box) {
  return std::int64_t{box.x1 - box.x0} * (box.y1 - box.y0) >= kSpanWalkMinBoxArea;
}

// The block walks for boxes up to 16x16 pixels, else the tile walk: every walk but the spans.
template <class Visitor>
inline void walk_block_or_tiles(const TriangleSetup& setup, Visitor& visitor) {
  if (setup.narrow && setup.extent <= kTileSize) {
    walk_block<Arch>(setup, visitor);
  } else if (setup.narrow && setup.extent <= 2 * kTileSize) {
    walk_block_16<Arch>(setup, visitor);
  } else if (setup.narrow) {
    walk_tiles<Arch, std::int32_t>(setup, visitor);
  } else {
    walk_tiles<Arch, std::int64_t>(setup, visitor);
  }
}

// The walk a drawn, visible triangle takes. The block walks are chosen by the unclipped box
// (setup.extent), which holds the clipped one: a triangle takes the same walk whichever bin it is
// drawn in.
template <class Visitor>
inline void walk_triangle(const TriangleSetup& setup, Visitor& visitor) {
  if constexpr (requires { visitor.add_pixels(std::uint64_t{}); }) {
    if (prefers_span_count(setup) && span_walk_fits(setup)) {
      walk_spans<Arch>(setup, visitor);
      return;
    }
  }
  const bool block = setup.narrow && setup.extent <= 2 * kTileSize;
  if (!block && prefers_span_walk(setup.box) && span_walk_fits(setup)) {
    walk_spans<Arch>(setup, visitor);
    return;
  }
  walk_block_or_tiles(setup, visitor);
}

// A visitor of every sample of the batch's pattern (multisample_tile), rather than of pixel
// centres.
template <class Visitor>
concept MultisampleVisitor = requires {
  Visitor::kMultisample;
};

// A visitor with a walk of its own (walk(setup)), set up with the box of every pixel whose
// square the triangle's box touches.
template <class Visitor>
concept SelfWalkingVisitor = requires {
  Visitor::kWalksItself;
};

// A visitor of a target that may be reduced (reduction(): 1, or the k of block_setup-inl.hpp).
template <class Visitor>
concept ReducingVisitor = requires(const Visitor& visitor) {
  { visitor.reduction() } -> std::same_as<std::int32_t>;
};

// A triangle's blocks on a reduced target (reduce_setup(); not by spans, block_setup-inl.hpp
// says why): those it covers whole, then, for a visitor that takes them (partial_block, when
// merges_partial_blocks()), those it covers in part.
template <class Visitor>
inline void walk_blocks(const TriangleSetup& view, std::int32_t reduction, Visitor& visitor) {
  TriangleSetup whole;
  if (!reduce_setup(view, reduction, BlockRule::all_samples, whole)) return;
  walk_block_or_tiles(whole, visitor);
  if constexpr (requires { visitor.partial_block(0, 0, 0u); }) {
    if (!visitor.merges_partial_blocks()) return;
    TriangleSetup touched;
    if (!reduce_setup(view, reduction, BlockRule::each_edge_some, touched)) return;
    PartialBlocks<Arch, Visitor> partial(whole, reduction, visitor);
    walk_block_or_tiles(touched, partial);
  }
}

// walk_triangle(), or the multisample walk for a multisample visitor, or the visitor's own, or
// the blocks' walk on a reduced target.
template <class Visitor>
inline void walk_visible(const detail::TriangleBatch& batch, const TriangleSetup& setup,
                         Visitor& visitor) {
  if constexpr (ReducingVisitor<Visitor>) {
    if (visitor.reduction() > 1) {
      walk_blocks(setup, visitor.reduction(), visitor);
      return;
    }
  }
  if constexpr (SelfWalkingVisitor<Visitor>) {
    visitor.walk(setup);
  } else if constexpr (MultisampleVisitor<Visitor>) {
    if (setup.narrow) {
      walk_multisample_tiles<Arch, std::int32_t>(setup, batch.samples, visitor);
    } else {
      walk_multisample_tiles<Arch, std::int64_t>(setup, batch.samples, visitor);
    }
  } else {
    walk_triangle(setup, visitor);
  }
}

// Visible triangles gathered into whole groups for a visitor that sets up per-triangle state a
// group at a time (begin_group): culled, empty and clipped-away triangles (half of a closed
// mesh's, its back faces) then cost that set-up nothing.
template <class A>
struct VisibleGroup {
  static constexpr std::size_t kLanes = kSetupLanes<A>;
  TriangleGroup<A> positions;
  GroupCorners<A> corners;
  TriangleSetup setups[kLanes];
  std::uint32_t triangles[kLanes];
  std::size_t count = 0;

  void add(std::uint32_t t, const TriangleGroup<A>& from_positions,
           const GroupCorners<A>& from_corners, std::size_t lane, const TriangleSetup& setup) {
    for (int i = 0; i < 3; ++i) {
      positions.x[i][count] = from_positions.x[i][lane];
      positions.y[i][count] = from_positions.y[i][lane];
      corners.vertex[count][i] = from_corners.vertex[lane][i];
    }
    corners.valid[count] = true;
    setups[count] = setup;
    triangles[count] = t;
    ++count;
  }

  // begin_group() on the gathered lanes (the others marked invalid: they read no vertex), then
  // each triangle's begin_triangle() and walk, in submission order.
  template <class Visitor>
  void draw(const detail::TriangleBatch& batch, Visitor& visitor) {
    if (count == 0) return;
    for (std::size_t l = count; l < kLanes; ++l) {
      corners.valid[l] = false;
      for (int i = 0; i < 3; ++i) {
        positions.x[i][l] = 0.0f;
        positions.y[i][l] = 0.0f;
      }
    }
    visitor.begin_group(corners, positions);
    for (std::size_t l = 0; l < count; ++l) {
      visitor.begin_triangle(triangles[l], l);
      walk_visible(batch, setups[l], visitor);
    }
    count = 0;
  }
};

// How many groups ahead of the one set up run_batch() prefetches a mesh's vertices, and, for
// visitors that can, the target's storage under the vertices (by then in cache).
inline constexpr std::size_t kPrefetchGroups = 4;
inline constexpr std::size_t kPrefetchTargetGroups = 2;

// The corners and positions of triangles [first, first + count) into the setup lanes, lanes past
// the end repeating the last triangle (their results are ignored); whether every lane is a
// triangle whose indices are in range.
[[gnu::always_inline]] inline bool fetch_group(const detail::TriangleBatch& batch,
                                               std::size_t first, std::size_t count,
                                               GroupCorners<Arch>& corners,
                                               TriangleGroup<Arch>& group) {
  constexpr std::size_t kLanes = kSetupLanes<Arch>;
  bool all_valid = count == kLanes;
  for (std::size_t l = 0; l < kLanes; ++l) {
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
        all_valid = false;
      }
      group.x[i][l] = v.x;
      group.y[i][l] = v.y;
    }
  }
  return all_valid;
}

// A mesh's vertices are read in the order of its indices, which the hardware prefetcher cannot
// follow: the vertices of the group kPrefetchGroups on are fetched while the group at `first` is
// set up and drawn, by visitors that can.
template <class Visitor>
[[gnu::always_inline]] inline void prefetch_ahead(const detail::TriangleBatch& batch,
                                                  std::size_t first, Visitor& visitor) {
  if constexpr (requires(const std::uint32_t* v) { visitor.prefetch_vertices(v, 0); }) {
    constexpr std::size_t kLanes = kSetupLanes<Arch>;
    constexpr std::size_t kAhead = kPrefetchGroups * kLanes;
    if (batch.indices != nullptr && first + kAhead + kLanes <= batch.triangle_count)
      visitor.prefetch_vertices(batch.indices + 3 * (first + kAhead), 3 * kLanes);
  }
  if constexpr (requires(const std::uint32_t* v) { visitor.prefetch_targets(v, 0); }) {
    constexpr std::size_t kLanes = kSetupLanes<Arch>;
    constexpr std::size_t kAhead = kPrefetchTargetGroups * kLanes;
    if (batch.indices != nullptr && first + kAhead + kLanes <= batch.triangle_count)
      visitor.prefetch_targets(batch.indices + 3 * (first + kAhead), 3 * kLanes);
  }
}

// Fetches, sets up and walks every triangle of the batch, a group of setup lanes at a time.
// The walks (walk_block, walk_spans, walk_tiles) are kept out of line: inlined into this loop
// (the compiler's choice with one visitor per translation unit) they ran fewer instructions but
// slower (docs/design/rasterization.md, "Tiles and masks").
template <class Visitor>
void run_batch(const detail::TriangleBatch& batch, Visitor& visitor, RasterReport& report) {
  constexpr std::size_t kLanes = kSetupLanes<Arch>;
  constexpr bool kGrouped = requires(GroupCorners<Arch> c, TriangleGroup<Arch> g) {
    visitor.begin_group(c, g);
  };
  report.triangles += batch.triangle_count;
  TriangleGroup<Arch> group;
  GroupCorners<Arch> corners;
  TriangleSetup setups[kLanes];
  TriangleStatus statuses[kLanes];
  bool visible[kLanes];
  VisibleGroup<Arch> gathered;
  SampleReach reach;
  if constexpr (MultisampleVisitor<Visitor>) reach = sample_reach(batch.samples);
  // Pixel squares reach half a pixel (128 fixed-point units) from their centres.
  if constexpr (SelfWalkingVisitor<Visitor>) reach = {-128, 128, -128, 128};
  for (std::size_t first = 0; first < batch.triangle_count; first += kLanes) {
    const std::size_t count =
        batch.triangle_count - first < kLanes ? batch.triangle_count - first : kLanes;
    prefetch_ahead(batch, first, visitor);
    const bool all_valid = fetch_group(batch, first, count, corners, group);
    const std::uint32_t visible_lanes =
        setup_triangles<Arch>(group, batch.clip, batch.cull, setups, statuses, visible, reach);
    // A whole group of visible triangles with none waiting is set up and drawn where it is:
    // gathering pays only where some lanes drop out.
    if constexpr (kGrouped) {
      if (gathered.count == 0 && all_valid && visible_lanes == (1u << kLanes) - 1) {
        visitor.begin_group(corners, group);
        report.drawn += kLanes;
        for (std::size_t l = 0; l < kLanes; ++l) {
          if (batch.statuses != nullptr) batch.statuses[first + l] = TriangleStatus::drawn;
          visitor.begin_triangle(static_cast<std::uint32_t>(first + l), l);
          walk_visible(batch, setups[l], visitor);
        }
        continue;
      }
    }
    for (std::size_t l = 0; l < count; ++l) {
      const std::size_t t = first + l;
      const TriangleStatus status =
          corners.valid[l] ? statuses[l] : TriangleStatus::error_bad_index;
      if (batch.statuses != nullptr) batch.statuses[t] = status;
      if (status != TriangleStatus::drawn) {
        detail::count_not_drawn(report, t, status);
        continue;
      }
      ++report.drawn;
      if (!visible[l]) continue;
      if constexpr (kGrouped) {
        gathered.add(static_cast<std::uint32_t>(t), group, corners, l, setups[l]);
        if (gathered.count == kLanes) gathered.draw(batch, visitor);
      } else {
        visitor.begin_triangle(static_cast<std::uint32_t>(t));
        walk_visible(batch, setups[l], visitor);
      }
    }
  }
  if constexpr (kGrouped) gathered.draw(batch, visitor);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
