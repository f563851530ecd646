// Depth kept as planes: an 8x8 tile of an occlusion buffer's depth held as up to eight depth
// planes (depth_plane.hpp), each with the mask of the pixels it owns, in place of 64 values.
// Occluders drawn front to back cover whole tiles or parts of tiles that lie wholly in front of
// what a tile holds; such a draw then changes a few masks and one plane instead of writing every
// pixel, and the values are worked out once, when the buffer is read (docs/design/occlusion.md,
// "Depth kept as planes"). The values are exact: a pixel's depth is its plane's depth_at(), the
// very float operations draw() would have written it with.
#pragma once

#include <cstddef>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "depth_plane.hpp"

namespace edgewise::detail {

inline constexpr int kPlaneTileSlots = 8;

// What holds a tile's depths.
enum class TileKind : std::uint8_t {
  values,  // the 64 values of the Framebuffer's tile, as draw() keeps them
  plane,   // plane PlaneTile::plane, at every pixel
  slots,   // the tile's PlaneSlots
};

// One tile, 16 bytes, so that the drawing of whole tiles, the common case, reads and writes
// little (half a megabyte at 1920x1080). Planes are named by their index in the buffer's array
// of planes. `lowest` and `highest` bound every depth of the tile, whatever holds them; they
// need not be tight.
struct alignas(16) PlaneTile {
  std::uint32_t plane;
  float lowest, highest;
  TileKind kind;
  bool unresolved;  // planes whose values the Framebuffer's tile does not hold yet
};
static_assert(sizeof(PlaneTile) == 16);

// The planes of a tile of kind slots: the masks are disjoint and together hold all 64 pixels
// (bit y * 8 + x); a slot with an empty mask is free. Two cache lines per tile, read only for
// tiles of that kind. Eight slots ran faster than four and than sixteen (docs/design/occlusion.md).
struct alignas(64) PlaneSlots {
  std::uint64_t mask[kPlaneTileSlots];
  std::uint32_t plane[kPlaneTileSlots];
};

// The far plane, depth 1 at every pixel: always plane 0 of a buffer.
inline constexpr DepthPlane kFarPlane{1.0f, 0.0f, 0.0f, 0.0f, 0.0f};

// A cleared tile, whose values the Framebuffer's cleared tile already holds.
inline PlaneTile far_plane_tile() {
  PlaneTile tile{};
  tile.plane = 0;
  tile.lowest = tile.highest = 1.0f;
  tile.kind = TileKind::plane;
  tile.unresolved = false;
  return tile;
}

// What a block of a reduced buffer knows of the samples that triangles have covered in part:
// each sample of `samples` (bit j k + i for sample (i, j)) has a depth at most `depth`. Useful
// while `depth` lies below the block's value; once `samples` holds every sample, the block's
// value falls to `depth` (block_layer_merge()).
struct BlockLayer {
  float depth = 1.0f;
  std::uint32_t samples = 0;
};

// A triangle that covers `samples` of a block in part (some, not all of `all`), at depths at
// most `depth`, merged into the block's layer; the block's value is `value`. Returns the value
// the block falls to (below `value`) when the samples of the layer and the triangle together
// make up all of the block's, else `value`. Conservative: every sample the layer names keeps a
// depth at most the layer's.
inline float block_layer_merge(BlockLayer& layer, std::uint32_t samples, float depth, float value,
                               std::uint32_t all) {
  if (!(depth < value)) return value;  // no nearer than the block already is
  if (layer.samples == 0 || !(layer.depth < value)) {
    layer = {depth, samples};
    return value;
  }
  const BlockLayer merged{depth > layer.depth ? depth : layer.depth, layer.samples | samples};
  if (merged.samples == all) {
    layer = BlockLayer{};
    return merged.depth;
  }
  layer = merged;
  return value;
}

// What one kernel call draws occluders into: a buffer's tiles and their slots, in the
// Framebuffer's tile order, and its planes, where the call's triangle t writes its own as plane
// first_plane + t. On a reduced buffer (`reduction` 2 or 4), a pixel of the tiles stands for a
// block of reduction x reduction samples of the view (docs/design/occlusion.md, "Reduced
// resolution"); the triangles are the view's.
struct PlaneTiles {
  PlaneTile* tiles = nullptr;
  PlaneSlots* slots = nullptr;
  DepthPlane* planes = nullptr;
  std::uint32_t first_plane = 0;
  std::int32_t reduction = 1;
  BlockLayer* layers = nullptr;  // per pixel of a reduced buffer, in the tiles' order
};

// What draw() is given to draw occluders with: the tiles, and the planes, which it grows by
// each kernel call's triangles before the calls run (reserve()), then hands each call its part
// (view()).
struct PlaneStore {
  PlaneTile* tiles = nullptr;
  PlaneSlots* slots = nullptr;
  std::vector<DepthPlane>* planes = nullptr;
  std::int32_t reduction = 1;
  BlockLayer* layers = nullptr;

  // Room for `count` more planes; returns the first. Throws std::length_error past 2^32 planes.
  std::uint32_t reserve(std::size_t count) const {
    const std::size_t first = planes->size();
    if (count > std::size_t{UINT32_MAX} - first)
      throw std::length_error("draw_occluders: more than 2^32 planes in one buffer");
    planes->resize(first + count);
    return static_cast<std::uint32_t>(first);
  }
  PlaneTiles view(std::uint32_t first_plane) const {
    return {tiles, slots, planes->data(), first_plane, reduction, layers};
  }
};

}  // namespace edgewise::detail
