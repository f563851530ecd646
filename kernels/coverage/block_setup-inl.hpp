// A triangle set up in a view, walked on a target reduced k times on each axis (k = 2 or 4),
// whose pixel (X, Y) stands for the view's k x k samples (kX + i, kY + j), 0 <= i, j < k: the
// block is covered when every one of its samples is (docs/design/occlusion.md, "Reduced
// resolution"). Included by each per-ISA translation unit inside its own namespace.
//
// Exactness: the view's G is exact and affine, G(kX + i, kY + j) = G(kX, kY) + A i + B j, so
// over a block it is least at i = (k - 1) [A < 0], j = (k - 1) [B < 0]; that least value, taken
// as the block's G, steps by exactly k A and k B from block to block, and is at least 0 for all
// three edges exactly when the view's rule covers all k x k samples. Its largest value, at the
// opposite corner, finds the blocks where each edge holds some sample: every block with a
// covered sample among them.
//
// Overflow (triangle_setup-inl.hpp's analysis, steps k times larger): |A|, |B| < 2^24, so the
// steps k A, k B lie below 2^26 for k <= 4. Inside a tile G varies by at most
// 7 (|kA| + |kB|) < 7 * 2^27 < 2^30, within the walk's per-tile clamp to +-2^30 (so a clamped
// value keeps its sign over the tile), and lanes stay within +-(2^30 + 7 * 2^27) < 2^31. A tile
// step 8 k A is below 2^29, and the tile walk's ranges stay exact (its quotients lie within
// 2^-40 of exact, non-integers at least 2^-29 from an integer). The narrow test is set-up's own,
// on the blocks' origin and reach. The span walk's analysis assumes |B| < 2^25, so reduced
// triangles take the block and tile walks only.
#pragma once

#include <bit>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "tile_walk-inl.hpp"
#include "../simd/lane_arch-inl.hpp"
#include "../simd/simd_ops-inl.hpp"
#include "triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

inline constexpr std::int32_t kMaxReduction = 4;

// Which blocks a reduced set-up's walk finds.
enum class BlockRule : std::uint8_t {
  all_samples,     // the blocks whose k x k samples the triangle all covers
  each_edge_some,  // the blocks where each edge holds some sample (a superset of those with one)
};

// `view`'s set-up (a drawn, visible triangle, its box clipped to a rectangle of samples whose
// edges are multiples of 8 k, or the view's) for blocks of k x k samples; false when no block
// can be found.
inline bool reduce_setup(const TriangleSetup& view, std::int32_t k, BlockRule rule,
                         TriangleSetup& out) {
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
    const bool least = rule == BlockRule::all_samples;
    const std::int64_t corner_a = least ? (a < 0 ? a : 0) : (a > 0 ? a : 0);
    const std::int64_t corner_b = least ? (b < 0 ? b : 0) : (b > 0 ? b : 0);
    const std::int64_t g = edge.g + a * dx + b * dy + (k - 1) * (corner_a + corner_b);
    const std::int64_t magnitude =
        (g < 0 ? -g : g) + (a < 0 ? -a : a) * k * reach_x + (b < 0 ? -b : b) * k * reach_y;
    narrow = narrow && magnitude <= INT32_MAX;
    out.edge[e] = {static_cast<std::int32_t>(k * a), static_cast<std::int32_t>(k * b), g, 0};
  }
  out.narrow = narrow;
  return out.box.x0 < out.box.x1 && out.box.y0 < out.box.y1;
}

// Which of a block's k x k samples a triangle covers, bit j k + i for sample (i, j), in lanes:
// each edge's G at the samples is its value at the block's first sample plus A i + B j. That
// first value is clamped to +-2^30, which keeps its sign at every sample (|A i + B j| <=
// 3 (|A| + |B|) < 2^27) and every lane within int32.
template <class Arch>
class BlockSampleCoverage {
 public:
  using Ints = xsimd::batch<std::int32_t, Arch>;
  static constexpr std::size_t kLanes = Ints::size;
  static constexpr std::size_t kBatches = (kMaxReduction * kMaxReduction + kLanes - 1) / kLanes;

  // `blocks`: a BlockRule::all_samples set-up, whose G at a block is the view's at the corner
  // sample chosen by the steps' signs.
  BlockSampleCoverage(const TriangleSetup& blocks, std::int32_t k)
      : blocks_(blocks),
        k_(k),
        batches_((k * k + kLanes - 1) / kLanes),
        all_((1u << (k * k)) - 1u) {
    for (int e = 0; e < 3; ++e) {
      a_[e] = blocks.edge[e].a / k;
      b_[e] = blocks.edge[e].b / k;
      alignas(64) std::int32_t offset[kBatches * kLanes] = {};
      for (std::int32_t s = 0; s < k * k; ++s)
        offset[s] = static_cast<std::int32_t>(a_[e] * (s % k) + b_[e] * (s / k));
      for (std::size_t h = 0; h < kBatches; ++h)
        offset_[e][h] = Ints::load_aligned(offset + h * kLanes);
    }
  }

  // The covered samples of block (x, y).
  [[gnu::always_inline]] std::uint32_t covered(std::int32_t x, std::int32_t y) const {
    Ints first[3];
    for (int e = 0; e < 3; ++e) {
      const EdgeSetup& edge = blocks_.edge[e];
      first[e] =
          Ints(clamp_to_tile_range(edge.g + std::int64_t{edge.a} * (x - blocks_.origin_x) +
                                   std::int64_t{edge.b} * (y - blocks_.origin_y) -
                                   (k_ - 1) * ((a_[e] < 0 ? a_[e] : 0) + (b_[e] < 0 ? b_[e] : 0))));
    }
    std::uint32_t outside = 0;
    for (std::size_t h = 0; h < batches_; ++h) {
      const Ints any_outside =
          (first[0] + offset_[0][h]) | (first[1] + offset_[1][h]) | (first[2] + offset_[2][h]);
      outside |= sign_bits<Arch>(any_outside) << (h * kLanes);
    }
    return ~outside & all_;
  }

 private:
  const TriangleSetup& blocks_;
  const std::int32_t k_;
  const std::size_t batches_;
  const std::uint32_t all_;
  std::int64_t a_[3], b_[3];  // the view's steps
  Ints offset_[3][kBatches];
};

// The walk of a triangle's BlockRule::each_edge_some blocks, handing on to the visitor's
// partial_block(x, y, samples) those of them that hold some covered sample but not all
// (`whole`: the BlockRule::all_samples set-up; Arch: a row's lanes, RowArch).
template <class Arch, class Visitor>
class PartialBlocks {
 public:
  PartialBlocks(const TriangleSetup& whole, std::int32_t k, Visitor& visitor)
      : whole_(whole), samples_(whole, k), evaluator_(whole), visitor_(visitor) {}

  void tile(std::uint32_t tile_x, std::uint32_t tile_y, std::uint64_t mask) {
    const std::int32_t px = static_cast<std::int32_t>(tile_x) * kTileSize;
    const std::int32_t py = static_cast<std::int32_t>(tile_y) * kTileSize;
    // Leaves out the tile's blocks covered whole, which the walk of whole blocks has drawn.
    std::int32_t g[3];
    for (int e = 0; e < 3; ++e) {
      const EdgeSetup& edge = whole_.edge[e];
      g[e] = clamp_to_tile_range(edge.g + std::int64_t{edge.a} * (px - whole_.origin_x) +
                                 std::int64_t{edge.b} * (py - whole_.origin_y));
    }
    for (std::uint64_t left = mask & ~evaluator_.coverage(g); left != 0; left &= left - 1) {
      const int bit = std::countr_zero(left);
      const std::int32_t x = px + (bit & 7), y = py + (bit >> 3);
      const std::uint32_t samples = samples_.covered(x, y);
      if (samples != 0) visitor_.partial_block(x, y, samples);
    }
  }

  void full_tiles(std::uint32_t begin, std::uint32_t end, std::uint32_t tile_y,
                  std::uint64_t mask) {
    for (std::uint32_t tile_x = begin; tile_x < end; ++tile_x)
      tile(tile_x, tile_y, mask);
  }

 private:
  const TriangleSetup& whole_;
  const BlockSampleCoverage<Arch> samples_;
  const TileEvaluator<WideArch<Arch>> evaluator_;
  Visitor& visitor_;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
