// Reduced occlusion depth, scalar (reduced_depth.hpp): written for clarity from the definitions,
// sharing nothing with the kernels' block walk but the depth formula and the reference's
// coverage test.
#include "reduced_depth.hpp"

#include <algorithm>
#include <cmath>

#include "../coverage/coverage_reference.hpp"
#include "../draw/shading/depth_plane.hpp"

namespace edgewise::detail {
namespace {

float& depth_of(const ReducedDepth& depth, std::int32_t x, std::int32_t y) {
  const std::size_t tile = static_cast<std::size_t>(y / kTileSize) * depth.tiles_x + x / kTileSize;
  return depth.tiles[tile * 64 + (y % kTileSize) * kTileSize + x % kTileSize];
}

BlockLayer& layer_of(const ReducedDepth& depth, std::int32_t x, std::int32_t y) {
  const std::size_t tile = static_cast<std::size_t>(y / kTileSize) * depth.tiles_x + x / kTileSize;
  return depth.layers[tile * 64 + (y % kTileSize) * kTileSize + x % kTileSize];
}

DepthPlane plane_of(const TriangleBatch& batch, const float* vertex_depth, std::size_t t) {
  Vec2 p[3];
  float z[3];
  for (int i = 0; i < 3; ++i) {
    const std::size_t v = batch.indices != nullptr ? batch.indices[3 * t + i] : 3 * t + i;
    p[i] = batch.vertices[v];
    z[i] = vertex_depth[v];
  }
  return make_depth_plane(p, z);
}

// The blocks that may hold a sample of `pixels` (pixels of the view).
PixelRect blocks_of(const PixelRect& pixels, std::int32_t k) {
  return {pixels.x0 / k, pixels.y0 / k, (pixels.x1 + k - 1) / k, (pixels.y1 + k - 1) / k};
}

// Slopes that k times over are not finite: the kernels draw such a triangle at depth 1
// (block_depth_plane()).
bool block_slopes_overflow(const DepthPlane& plane, std::int32_t k) {
  const float kf = static_cast<float>(k);
  return std::isfinite(plane.dzdx) && std::isfinite(plane.dzdy) &&
         !(std::isfinite(plane.dzdx * kf) && std::isfinite(plane.dzdy * kf));
}

}  // namespace

void draw_block_occluders_reference(const TriangleBatch& batch, const float* vertex_depth,
                                    const ReducedDepth& depth, RasterReport& report,
                                    ShadeCounts& counts) {
  const std::int32_t k = depth.reduction;
  reference::for_each_drawn_triangle(
      batch, report, [&](std::size_t t, const reference::SnappedTriangle& snapped) {
        const DepthPlane plane = plane_of(batch, vertex_depth, t);
        const PixelRect blocks = blocks_of(reference::candidate_pixels(snapped, batch.clip), k);
        for (std::int32_t y = blocks.y0; y < blocks.y1; ++y) {
          for (std::int32_t x = blocks.x0; x < blocks.x1; ++x) {
            std::uint32_t samples = 0;
            float farthest = 0.0f;  // over the covered samples
            for (std::int32_t j = 0; j < k; ++j) {
              for (std::int32_t i = 0; i < k; ++i) {
                if (!reference::covers(snapped, k * x + i, k * y + j)) continue;
                samples |= 1u << (j * k + i);
                farthest = std::max(farthest, depth_at(plane, k * x + i, k * y + j));
              }
            }
            if (samples == 0) continue;
            float& stored = depth_of(depth, x, y);
            const std::uint32_t all = (1u << (k * k)) - 1u;
            if (samples != all) {
              if (depth.layers != nullptr)
                stored = block_layer_merge(layer_of(depth, x, y), samples, farthest, stored, all);
              continue;
            }
            if (block_slopes_overflow(plane, k)) farthest = 1.0f;
            ++counts.fragments;
            if (farthest < stored) {
              stored = farthest;
              ++counts.passed;
            }
          }
        }
      });
}

bool some_sample_passes(const TriangleBatch& batch, const float* vertex_depth,
                        const ReducedDepth& depth, RasterReport& report, ShadeCounts& counts) {
  const std::int32_t k = depth.reduction;
  bool passes = false;
  reference::for_each_drawn_triangle(
      batch, report, [&](std::size_t t, const reference::SnappedTriangle& snapped) {
        if (passes) return;
        const DepthPlane plane = plane_of(batch, vertex_depth, t);
        const PixelRect pixels = reference::candidate_pixels(snapped, batch.clip);
        for (std::int32_t y = pixels.y0; y < pixels.y1 && !passes; ++y) {
          for (std::int32_t x = pixels.x0; x < pixels.x1 && !passes; ++x) {
            if (!reference::covers(snapped, x, y)) continue;
            ++counts.fragments;
            passes = depth_at(plane, x, y) < depth_of(depth, x / k, y / k);
          }
        }
      });
  counts.passed = passes ? 1 : 0;
  return passes;
}

namespace {

// copy_block_maxima() for blocks of K x K.
template <std::int32_t K>
void copy_maxima(const Framebuffer& frame, const ReducedDepth& depth) {
  const std::int32_t width = frame.width(), height = frame.height();
  const std::int32_t tiles_x = frame.tiles_x(), tiles_y = (height + kTileSize - 1) / kTileSize;
  constexpr std::int32_t kBlocks = kTileSize / K;  // per side of a tile
  // K divides the tile's side, so each block lies in one tile of the frame: a tile at a time,
  // its values read in order, each block's maximum written once.
  for (std::int32_t ty = 0; ty < tiles_y; ++ty) {
    for (std::int32_t tx = 0; tx < tiles_x; ++tx) {
      const float* tile = frame.depth_tiles() + (static_cast<std::size_t>(ty) * tiles_x + tx) * 64;
      const std::int32_t rows = std::min(kTileSize, height - ty * kTileSize);
      const std::int32_t columns = std::min(kTileSize, width - tx * kTileSize);
      float farthest[kBlocks][kBlocks] = {};
      for (std::int32_t r = 0; r < rows; ++r) {
        for (std::int32_t c = 0; c < columns; ++c)
          farthest[r / K][c / K] = std::max(farthest[r / K][c / K], tile[r * kTileSize + c]);
      }
      for (std::int32_t by = 0; by < (rows + K - 1) / K; ++by) {
        for (std::int32_t bx = 0; bx < (columns + K - 1) / K; ++bx)
          depth_of(depth, tx * kBlocks + bx, ty * kBlocks + by) = farthest[by][bx];
      }
    }
  }
}

}  // namespace

void copy_block_maxima(const Framebuffer& frame, const ReducedDepth& depth) {
  if (depth.reduction == 2) {
    copy_maxima<2>(frame, depth);
  } else {
    copy_maxima<4>(frame, depth);
  }
}

}  // namespace edgewise::detail
