// The occlusion kernels' reference: every sample of a rectangle read and compared, one at a time;
// each value of a tile kept as planes by depth_at().
#include <algorithm>
#include <cstddef>
#include <cstdint>

#include "../core/reference_kernels.hpp"
#include "../draw/shading/plane_tiles.hpp"
#include "query_bounds.hpp"

namespace edgewise::reference {

std::size_t rect_sample_ranges(const OcclusionRect* rects, std::size_t count, std::int32_t width,
                               std::int32_t height, std::int32_t reduction,
                               detail::SampleRect* out) {
  for (std::size_t i = 0; i < count; ++i) {
    if (!detail::rect_sample_range(rects[i], width, height, out[i])) return i;
    out[i] = detail::sample_blocks(out[i], reduction);
  }
  return count;
}

std::size_t box_sample_ranges(const OcclusionBox* boxes, std::size_t count, const Mat4& to_clip,
                              const Viewport& viewport, const GuardBandPlanes& planes,
                              detail::BoxSamples* out) {
  for (std::size_t i = 0; i < count; ++i) {
    if (!detail::valid_box(boxes[i])) return i;
    out[i] = detail::box_samples(boxes[i], to_clip, viewport, planes, i);
  }
  return count;
}

void test_sample_rects(const detail::OcclusionDepth& depth, const detail::SampleRect* rects,
                       std::size_t count, Visibility* out) {
  for (std::size_t i = 0; i < count; ++i) {
    const detail::SampleRect& r = rects[i];
    Visibility answer = r.x0 > r.x1 || r.y0 > r.y1 ? Visibility::outside : Visibility::occluded;
    for (std::int32_t y = r.y0; y <= r.y1 && answer == Visibility::occluded; ++y) {
      for (std::int32_t x = r.x0; x <= r.x1; ++x) {
        const std::size_t tile = static_cast<std::size_t>(y / 8) * depth.tiles_x + x / 8;
        // Passes the depth test less somewhere: the stored depth lies above the rectangle's.
        if (depth.tiles[tile * 64 + (y % 8) * 8 + x % 8] > r.depth) {
          answer = Visibility::visible;
          break;
        }
      }
    }
    out[i] = answer;
  }
}

void occlusion_tile_maxima(const float* tiles, std::size_t first, std::size_t last, float* out) {
  for (std::size_t t = first; t < last; ++t)
    out[t] = *std::max_element(tiles + t * 64, tiles + t * 64 + 64);
}

void resolve_plane_tiles(const detail::PlaneTiles& planes, float* depth_tiles, std::int32_t tiles_x,
                         std::size_t first, std::size_t last) {
  for (std::size_t t = first; t < last; ++t) {
    detail::PlaneTile& tile = planes.tiles[t];
    if (tile.kind == detail::TileKind::values || !tile.unresolved) continue;
    const detail::PlaneSlots& slots = planes.slots[t];
    const auto px = static_cast<std::int32_t>(t % static_cast<std::size_t>(tiles_x)) * 8;
    const auto py = static_cast<std::int32_t>(t / static_cast<std::size_t>(tiles_x)) * 8;
    for (int bit = 0; bit < 64; ++bit) {
      std::uint32_t plane = tile.plane;
      for (int s = 0; s < detail::kPlaneTileSlots && tile.kind == detail::TileKind::slots; ++s) {
        if ((slots.mask[s] >> bit) & 1) plane = slots.plane[s];
      }
      depth_tiles[t * 64 + bit] =
          detail::depth_at(planes.planes[plane], px + bit % 8, py + bit / 8);
    }
    tile.unresolved = false;
  }
}

}  // namespace edgewise::reference
