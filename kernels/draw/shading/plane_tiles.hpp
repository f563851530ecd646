// Depth kept as planes: an 8x8 tile of an occlusion buffer's depth held as up to four depth
// planes (depth_plane.hpp), each with the mask of the pixels it owns, in place of 64 values.
// Occluders drawn front to back cover whole tiles or parts of tiles that lie wholly in front of
// what a tile holds; such a draw then changes a few masks and one plane instead of writing every
// pixel, and the values are worked out once, when the buffer is read (docs/design/occlusion.md,
// "Depth kept as planes"). The values are exact: a pixel's depth is its plane's depth_at(), the
// very float operations draw() would have written it with.
#pragma once

#include <cstdint>

#include "depth_plane.hpp"

namespace edgewise::detail {

inline constexpr int kPlaneTileSlots = 4;

// What holds a tile's depths.
enum class TileKind : std::uint8_t {
  values,  // the 64 values of the Framebuffer's tile, as draw() keeps them
  plane,   // PlaneTile::plane, at every pixel
  slots,   // the tile's PlaneSlots
};

// One tile: 32 bytes, so that the drawing of whole tiles, the common case, reads and writes
// little. `lowest` and `highest` bound every depth of the tile, whatever holds them; they need
// not be tight.
struct alignas(32) PlaneTile {
  DepthPlane plane;
  float lowest, highest;
  TileKind kind;
  bool unresolved;  // planes whose values the Framebuffer's tile does not hold yet
};
static_assert(sizeof(PlaneTile) == 32);

// The planes of a tile of kind slots: the masks are disjoint and together hold all 64 pixels
// (bit y * 8 + x); a slot with an empty mask is free. One per tile, read only for tiles of that
// kind.
struct alignas(64) PlaneSlots {
  std::uint64_t mask[kPlaneTileSlots];
  DepthPlane plane[kPlaneTileSlots];
};

// A buffer's tiles and their slots, in the Framebuffer's tile order.
struct PlaneTiles {
  PlaneTile* tiles = nullptr;
  PlaneSlots* slots = nullptr;
};

// The far plane alone, depth 1 at every pixel: a cleared tile, whose values the Framebuffer's
// cleared tile already holds.
inline PlaneTile far_plane_tile() {
  PlaneTile tile{};
  tile.plane = DepthPlane{1.0f, 0.0f, 0.0f, 0.0f, 0.0f};
  tile.lowest = tile.highest = 1.0f;
  tile.kind = TileKind::plane;
  tile.unresolved = false;
  return tile;
}

}  // namespace edgewise::detail
