// An occlusion buffer at reduced resolution, scalar: its depth pixel (X, Y) stands for the view's
// k x k samples (kX + i, kY + j) and holds at least every depth a full-resolution buffer would
// hold at them (docs/design/occlusion.md, "Reduced resolution"). The occluders' reference (the
// oracle of the kernels' blocks), the exact triangle query, and the copy of a frame's depth.
#pragma once

#include <cstdint>

#include "edgewise/coverage.hpp"
#include "edgewise/framebuffer.hpp"
#include "../coverage/triangle_batch.hpp"
#include "../draw/shading/plane_tiles.hpp"
#include "../draw/shading/shade_batch.hpp"

namespace edgewise::detail {

// A reduced buffer's depth in the Framebuffer's tiled layout: `reduction` samples of the view per
// pixel on each axis.
struct ReducedDepth {
  float* tiles = nullptr;
  std::int32_t tiles_x = 0;
  std::int32_t reduction = 2;
  BlockLayer* layers = nullptr;  // one per pixel, in the tiles' order; null: partial coverage
                                 // ignored
};

// Occluders `batch` (the view's screen triangles, `vertex_depth` per vertex), depth test less
// with writes, block by block: a block that the triangle covers whole (all its samples, by the
// view's rule) takes the largest of draw()'s depths at its samples where that is below the stored
// one; one it covers in part merges those samples, at the largest depth among them, into its
// layer (block_layer_merge()), when there are layers. Counts blocks covered whole and written as
// fragments and passed.
void draw_block_occluders_reference(const TriangleBatch& batch, const float* vertex_depth,
                                    const ReducedDepth& depth, RasterReport& report,
                                    ShadeCounts& counts);

// Whether some sample that a triangle of `batch` covers has a depth (draw()'s) below its block's.
// Counts the covered samples as fragments and the passing ones as passed, stopping at the first.
bool some_sample_passes(const TriangleBatch& batch, const float* vertex_depth,
                        const ReducedDepth& depth, RasterReport& report, ShadeCounts& counts);

// Each block of `depth` set to the largest depth of `frame` (of the view's size) over its samples
// that lie in the frame.
void copy_block_maxima(const Framebuffer& frame, const ReducedDepth& depth);

}  // namespace edgewise::detail
