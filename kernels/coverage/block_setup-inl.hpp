// A triangle set up in a view, walked on a target reduced k times on each axis (k = 2 or 4),
// whose pixel (X, Y) stands for the view's k x k samples (kX + i, kY + j), 0 <= i, j < k: the
// block is covered when every one of its samples is (docs/design/occlusion.md, "Reduced
// resolution"). Included by each per-ISA translation unit inside its own namespace.
//
// Exactness: the view's G is exact and affine, G(kX + i, kY + j) = G(kX, kY) + A i + B j, so
// over a block it is least at i = (k - 1) [A < 0], j = (k - 1) [B < 0]; that least value, taken
// as the block's G, steps by exactly k A and k B from block to block, and is at least 0 for all
// three edges exactly when the view's rule covers all k x k samples.
//
// Overflow (triangle_setup-inl.hpp's analysis, steps k times larger): |A|, |B| < 2^24, so the
// steps k A, k B lie below 2^26 for k <= 4. Inside a tile G varies by at most
// 7 (|kA| + |kB|) < 7 * 2^27 < 2^30, within the walk's per-tile clamp to +-2^30 (so a clamped
// value keeps its sign over the tile) and keeping lanes within +-(2^30 + 7 * 2^27) < 2^31;
// a tile step 8 k A < 2^29 and the division of the tile walk's
// ranges (quotients within 2^-40 of exact, non-integers at least 2^-29 from an integer) stay
// exact. The narrow test is set-up's own, on the blocks' origin and reach. The span walk's
// analysis assumes |B| < 2^25, so reduced triangles take the block and tile walks only.
#pragma once

#include <cstdint>

#include "triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

inline constexpr std::int32_t kMaxReduction = 4;

// `view`'s set-up (a drawn, visible triangle, its box clipped to a rectangle of samples whose
// edges are multiples of 8 k, or the view's) for blocks of k x k samples; false when no block
// can be covered.
inline bool reduce_setup(const TriangleSetup& view, std::int32_t k, TriangleSetup& out) {
  // Boxes lie at non-negative samples: plain division rounds down.
  out.box = {view.box.x0 / k, view.box.y0 / k, (view.box.x1 + k - 1) / k,
             (view.box.y1 + k - 1) / k};
  out.origin_x = out.box.x0 & ~(kTileSize - 1);
  out.origin_y = out.box.y0 & ~(kTileSize - 1);
  // The blocks of the view's box before clipping: at most (extent - 1) / k + 2 on a side.
  out.extent = view.extent >= kMaxExtent ? kMaxExtent : (view.extent - 1) / k + 2;
  const std::int64_t reach_x = (out.box.x1 - 1 - out.origin_x) / kTileSize * kTileSize + 15;
  const std::int64_t reach_y = (out.box.y1 - 1 - out.origin_y) / kTileSize * kTileSize + 15;
  const std::int64_t dx = std::int64_t{k} * out.origin_x - view.origin_x;
  const std::int64_t dy = std::int64_t{k} * out.origin_y - view.origin_y;
  bool narrow = true;
  for (int e = 0; e < 3; ++e) {
    const EdgeSetup& edge = view.edge[e];
    const std::int64_t a = edge.a, b = edge.b;
    const std::int64_t g =
        edge.g + a * dx + b * dy + (k - 1) * (a < 0 ? a : 0) + (k - 1) * (b < 0 ? b : 0);
    const std::int64_t magnitude =
        (g < 0 ? -g : g) + (a < 0 ? -a : a) * k * reach_x + (b < 0 ? -b : b) * k * reach_y;
    narrow = narrow && magnitude <= INT32_MAX;
    out.edge[e] = {static_cast<std::int32_t>(k * a), static_cast<std::int32_t>(k * b), g, 0};
  }
  out.narrow = narrow;
  return out.box.x0 < out.box.x1 && out.box.y0 < out.box.y1;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
