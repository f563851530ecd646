// The multisample tile walk: every sample of a pattern (edgewise/multisample.hpp) decided by the
// same exact edge functions as the pixel centre, an 8x8 mask per sample per tile.
//
// A sample moved from the centre by (sx, sy) fixed-point units has the edge function
// E + A sx + B sy. The centre's E + bias is 256 G + r with r in [0, 255] the same at every
// pixel (E steps by 256 A and 256 B), so the sample's G is
//     floor((E + A sx + B sy + bias) / 256) = G + floor((r + A sx + B sy) / 256) = G + delta,
// one integer per edge and sample for the whole triangle: each sample's mask is the centre
// evaluator's at G + delta, and stepping stays exact. |A sx + B sy| < 2^24 * 128 * 2 = 2^32:
// delta is computed in int64; |delta| <= (|A| |sx| + |B| |sy|) / 256 + 1, which
// setup_triangles adds to the narrow bound when the call has samples off the centre.
//
// The walk visits every tile of the (sample-widened) box, row by row, skips a tile that an edge
// rejects for every sample (G + delta_max at the tile's extreme sample below zero) and takes
// whole a tile that every edge accepts for every sample (G + delta_min at its other extreme at
// least zero).
#pragma once

#include <algorithm>
#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

#include "edgewise/multisample.hpp"
#include "tile_masks-inl.hpp"
#include "tile_walk-inl.hpp"
#include "triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

inline constexpr std::size_t kMaxSamples = 16;

// The reach in fixed-point units of a sample pattern (its offsets are in 1/16 px).
inline SampleReach sample_reach(std::span<const SampleOffset> pattern) {
  SampleReach reach;
  for (const SampleOffset& offset : pattern) {
    reach.x_min = std::min(reach.x_min, 16 * std::int32_t{offset.x});
    reach.x_max = std::max(reach.x_max, 16 * std::int32_t{offset.x});
    reach.y_min = std::min(reach.y_min, 16 * std::int32_t{offset.y});
    reach.y_max = std::max(reach.y_max, 16 * std::int32_t{offset.y});
  }
  return reach;
}

// Per edge: each sample's offset of G from the pixel centre's (delta), G's steps per tile, and
// the offsets from a tile's G to its extreme samples, for rejecting and accepting whole tiles.
template <class Int>
struct MultisampleEdgeSteps {
  Int delta[3][kMaxSamples];
  Int step_x[3], step_y[3], reject_offset[3], accept_offset[3];
};

template <class Int>
[[gnu::always_inline]] inline MultisampleEdgeSteps<Int> multisample_edge_steps(
    const TriangleSetup& setup, std::span<const SampleOffset> pattern) {
  MultisampleEdgeSteps<Int> steps;
  for (int e = 0; e < 3; ++e) {
    const EdgeSetup& edge = setup.edge[e];
    Int most = 0, least = 0;
    for (std::size_t k = 0; k < pattern.size(); ++k) {
      const std::int64_t moved = std::int64_t{edge.remainder} +
                                 std::int64_t{edge.a} * 16 * pattern[k].x +
                                 std::int64_t{edge.b} * 16 * pattern[k].y;
      steps.delta[e][k] = static_cast<Int>(moved >> 8);  // floor division by 256
      most = k == 0 || steps.delta[e][k] > most ? steps.delta[e][k] : most;
      least = k == 0 || steps.delta[e][k] < least ? steps.delta[e][k] : least;
    }
    steps.step_x[e] = static_cast<Int>(edge.a) * kTileSize;
    steps.step_y[e] = static_cast<Int>(edge.b) * kTileSize;
    // The tile's extreme sample for this edge, moved by the sample that gains the most.
    steps.reject_offset[e] =
        (kTileSize - 1) * ((edge.a > 0 ? edge.a : 0) + (edge.b > 0 ? edge.b : 0)) + most;
    // The sample least inside: the other extreme, moved by the sample that loses the most.
    steps.accept_offset[e] =
        (kTileSize - 1) * ((edge.a < 0 ? edge.a : 0) + (edge.b < 0 ? edge.b : 0)) + least;
  }
  return steps;
}

// Calls visitor.multisample_tile(tile_x, tile_y, masks) for every tile with a covered sample, in
// row order; masks[k] holds sample k's coverage (bit y * 8 + x), masks.size() the pattern's count.
// Int is the type G steps in: int32 when setup.narrow (set up with the pattern's reach), else
// int64 with each tile's values clamped as walk_tiles() clamps them.
template <class Arch, class Int, class Visitor>
[[gnu::noinline]] void walk_multisample_tiles(const TriangleSetup& setup,
                                              std::span<const SampleOffset> pattern,
                                              Visitor& visitor) {
  const std::size_t samples = pattern.size();
  const TileEvaluator<WideArch<Arch>> evaluator(setup);
  const MultisampleEdgeSteps<Int> steps = multisample_edge_steps<Int>(setup, pattern);
  const auto& delta = steps.delta;
  const auto& step_x = steps.step_x;
  const auto& step_y = steps.step_y;
  const auto& reject_offset = steps.reject_offset;
  const auto& accept_offset = steps.accept_offset;
  const PixelRect& box = setup.box;
  const std::uint32_t first_tile_x = static_cast<std::uint32_t>(setup.origin_x / kTileSize);
  Int row_g[3];
  for (int e = 0; e < 3; ++e)
    row_g[e] = static_cast<Int>(setup.edge[e].g);
  std::uint64_t masks[kMaxSamples];
  for (std::int32_t ty = setup.origin_y; ty < box.y1; ty += kTileSize) {
    const std::uint64_t rows =
        row_bits(box.y0 > ty ? box.y0 - ty : 0, box.y1 - ty < kTileSize ? box.y1 - ty : kTileSize);
    Int g[3] = {row_g[0], row_g[1], row_g[2]};
    std::uint32_t column = 0;
    for (std::int32_t tx = setup.origin_x; tx < box.x1; tx += kTileSize, ++column) {
      const bool rejected = (g[0] + reject_offset[0] < 0) | (g[1] + reject_offset[1] < 0) |
                            (g[2] + reject_offset[2] < 0);
      if (!rejected) {
        const std::uint64_t clip =
            rows & column_bits(box.x0 > tx ? box.x0 - tx : 0,
                               box.x1 - tx < kTileSize ? box.x1 - tx : kTileSize);
        // The edges that may exclude a sample of the tile; one alone is evaluated alone.
        const unsigned crossing = (g[0] + accept_offset[0] < 0 ? 1u : 0u) |
                                  (g[1] + accept_offset[1] < 0 ? 2u : 0u) |
                                  (g[2] + accept_offset[2] < 0 ? 4u : 0u);
        std::uint64_t any = 0;
        if (crossing == 0) {
          for (std::size_t k = 0; k < samples; ++k)
            masks[k] = clip;
          any = clip;
        } else if ((crossing & (crossing - 1)) == 0) {
          const int e = std::countr_zero(crossing);
          for (std::size_t k = 0; k < samples; ++k) {
            masks[k] =
                evaluator.coverage_of_edge(e, clamp_to_tile_range(g[e] + delta[e][k])) & clip;
            any |= masks[k];
          }
        } else {
          for (std::size_t k = 0; k < samples; ++k) {
            const std::int32_t tile_g[3] = {clamp_to_tile_range(g[0] + delta[0][k]),
                                            clamp_to_tile_range(g[1] + delta[1][k]),
                                            clamp_to_tile_range(g[2] + delta[2][k])};
            masks[k] = evaluator.coverage(tile_g) & clip;
            any |= masks[k];
          }
        }
        if (any != 0) {
          visitor.multisample_tile(first_tile_x + column,
                                   static_cast<std::uint32_t>(ty / kTileSize),
                                   std::span<const std::uint64_t>(masks, samples));
        }
      }
      for (int e = 0; e < 3; ++e)
        g[e] += step_x[e];
    }
    for (int e = 0; e < 3; ++e)
      row_g[e] += step_y[e];
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
