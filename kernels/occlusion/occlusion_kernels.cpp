// The occlusion kernels (occlusion.hpp's rectangle and box queries, and the values of depth kept
// as planes), compiled once per ISA.
#include "../core/isa_build.hpp"

#include "../draw/shading/plane_tile_depths-inl.hpp"
#include "box_ranges-inl.hpp"
#include "rect_ranges-inl.hpp"
#include "rect_test-inl.hpp"
#include "../core/isa_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

using Arch = RowArch<EDGEWISE_ARCH>;

std::size_t rect_sample_ranges(const OcclusionRect* rects, std::size_t count, std::int32_t width,
                               std::int32_t height, std::int32_t reduction,
                               detail::SampleRect* out) {
  return rect_ranges<Arch>(rects, count, width, height, reduction, out);
}

std::size_t box_sample_ranges(const OcclusionBox* boxes, std::size_t count, const Mat4& to_clip,
                              const Viewport& viewport, const GuardBandPlanes& planes,
                              detail::BoxSamples* out) {
  return box_ranges<Arch>(boxes, count, to_clip, viewport, planes, out);
}

void test_sample_rects(const detail::OcclusionDepth& depth, const detail::SampleRect* rects,
                       std::size_t count, Visibility* out) {
  for (std::size_t i = 0; i < count; ++i)
    out[i] = test_rect<Arch>(depth, rects[i]);
}

void occlusion_tile_maxima(const float* tiles, std::size_t first, std::size_t last, float* out) {
  tile_maxima<Arch>(tiles, first, last, out);
}

void resolve_plane_tiles(const detail::PlaneTiles& planes, float* depth_tiles, std::int32_t tiles_x,
                         std::size_t first, std::size_t last) {
  const auto columns = static_cast<std::size_t>(tiles_x);
  for (std::size_t t = first; t < last; ++t) {
    detail::PlaneTile& tile = planes.tiles[t];
    if (tile.kind == detail::TileKind::values || !tile.unresolved) continue;
    write_plane_tile<Arch>(
        tile, planes.slots[t], planes.planes, static_cast<std::int32_t>(t % columns) * kTileSize,
        static_cast<std::int32_t>(t / columns) * kTileSize, depth_tiles + t * 64);
    tile.unresolved = false;
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
