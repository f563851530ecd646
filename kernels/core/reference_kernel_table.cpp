// The scalar reference as a kernel table, like every ISA's: coverage, drawing and sampling by
// the reference's plain loops (raster_reference, vertex_stage_reference, shade_reference,
// sample_reference), in exact integers or double precision where the result allows it (the
// vertex stage's float32 results are defined by its scalar operations); sampled values are
// rounded to float only on the way out.
#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "kernel_table.hpp"
#include "../coverage/coverage_reference.hpp"
#include "../draw/draw_reference.hpp"
#include "../antialiasing/pixel_area_reference.hpp"
#include "../antialiasing/resolve_reference.hpp"
#include "../texture/sample_reference.hpp"
#include "../draw/vertex_stage/vertex_stage_reference.hpp"

namespace edgewise::isa_reference {
namespace {

// Runs the reference over a batch; `tile` receives (triangle, tile_x, tile_y, mask, sample):
// pixel centres (sample 0) or, with a multisample pattern, every sample of it.
template <class TileFn>
void run_batch(const detail::TriangleBatch& batch, RasterReport& report, TileFn&& tile) {
  reference::for_each_drawn_triangle(
      batch, report, [&](std::size_t t, const reference::SnappedTriangle& snapped) {
        const auto triangle = static_cast<std::uint32_t>(t);
        if (batch.samples.size() > 1) {
          reference::for_each_multisample_tile(
              snapped, batch.clip, batch.samples,
              [&](std::uint32_t tx, std::uint32_t ty, std::uint8_t sample, std::uint64_t mask) {
                tile(triangle, tx, ty, mask, sample);
              });
          return;
        }
        reference::for_each_tile(snapped, batch.clip,
                                 [&](std::uint32_t tx, std::uint32_t ty, std::uint64_t mask) {
                                   tile(triangle, tx, ty, mask, std::uint8_t{0});
                                 });
      });
}

void rasterize(const detail::TriangleBatch& batch, CoverageSink& sink, RasterReport& report) {
  std::vector<TileCoverage> tiles;
  run_batch(batch, report,
            [&](std::uint32_t t, std::uint32_t tx, std::uint32_t ty, std::uint64_t mask,
                std::uint8_t sample) {
              tiles.push_back({t, static_cast<std::uint16_t>(tx), static_cast<std::uint16_t>(ty),
                               mask, sample});
            });
  if (!tiles.empty()) sink.consume(tiles);
}

void transform_vertices(const Mat4& m, const Vec3* in, std::size_t count, Vec4* out) {
  for (std::size_t i = 0; i < count; ++i)
    out[i] = transform(m, in[i]);
}

void count_coverage(const detail::TriangleBatch& batch, RasterReport& report,
                    std::uint64_t& pixels) {
  run_batch(batch, report,
            [&](std::uint32_t, std::uint32_t, std::uint32_t, std::uint64_t mask, std::uint8_t) {
              for (; mask != 0; mask &= mask - 1)
                ++pixels;  // plain bit counting, no intrinsics
            });
}

// Every pixel of the triangle's candidate box (widened by a pixel: squares reach half a pixel
// past their centres) by the exact-area reference, tile by tile in row order.
void rasterize_areas(const detail::TriangleBatch& batch, AreaSink& sink, RasterReport& report) {
  std::vector<AreaTile> tiles;
  reference::for_each_drawn_triangle(
      batch, report, [&](std::size_t t, const reference::SnappedTriangle& snapped) {
        PixelRect box = reference::candidate_pixels(snapped, batch.clip);
        box = {std::max(box.x0 - 1, batch.clip.x0), std::max(box.y0 - 1, batch.clip.y0),
               std::min(box.x1 + 1, batch.clip.x1), std::min(box.y1 + 1, batch.clip.y1)};
        if (box.empty()) return;
        for (std::int32_t ty = box.y0 / kTileSize; ty <= (box.y1 - 1) / kTileSize; ++ty) {
          for (std::int32_t tx = box.x0 / kTileSize; tx <= (box.x1 - 1) / kTileSize; ++tx) {
            AreaTile tile{static_cast<std::uint32_t>(t),
                          static_cast<std::uint16_t>(tx),
                          static_cast<std::uint16_t>(ty),
                          0,
                          {}};
            for (int bit = 0; bit < kTileSize * kTileSize; ++bit) {
              const std::int32_t px = tx * kTileSize + bit % kTileSize;
              const std::int32_t py = ty * kTileSize + bit / kTileSize;
              if (px < box.x0 || px >= box.x1 || py < box.y0 || py >= box.y1) continue;
              const double area = reference::pixel_area(snapped, px, py);
              if (area > 0.0) {
                tile.mask |= std::uint64_t{1} << bit;
                tile.area[bit] = static_cast<float>(area);
              }
            }
            if (tile.mask != 0) tiles.push_back(tile);
          }
        }
      });
  if (!tiles.empty()) sink.consume(tiles);
}

Vec4 to_float(const reference::Rgba& rgba) {
  return {static_cast<float>(rgba[0]), static_cast<float>(rgba[1]), static_cast<float>(rgba[2]),
          static_cast<float>(rgba[3])};
}

void sample(const detail::TextureDescription& texture, const SamplerOptions& options,
            const TextureQuery* queries, std::size_t count, Vec4* out) {
  for (std::size_t i = 0; i < count; ++i)
    out[i] = to_float(reference::sample(*texture.texture, options, queries[i]));
}

void sample_fields(const detail::TextureDescription& texture, const SamplerOptions& options,
                   const detail::QueryFields& queries, std::size_t count,
                   const detail::ResultChannels& out) {
  for (std::size_t i = 0; i < count; ++i) {
    const TextureQuery query{queries.s[i],    queries.t[i],    queries.dsdx[i],
                             queries.dtdx[i], queries.dsdy[i], queries.dtdy[i]};
    const Vec4 rgba = to_float(reference::sample(*texture.texture, options, query));
    out.c[0][i] = rgba.x;
    out.c[1][i] = rgba.y;
    out.c[2][i] = rgba.z;
    out.c[3][i] = rgba.w;
  }
}

}  // namespace

const detail::KernelTable& kernel_table() {
  static constexpr detail::KernelTable table{
      .isa = Isa::reference,
      .rasterize = &rasterize,
      .count_coverage = &count_coverage,
      .transform_vertices = &transform_vertices,
      .map_vertices = &reference::map_vertices,
      .assemble_triangles = &reference::assemble_triangles,
      .drop_culled_triangles = &reference::drop_culled_triangles,
      .shade = &reference::shade,
      .resolve_box = &reference::resolve_box,
      .resolve_taps = &reference::resolve_taps,
      .sample = &sample,
      .sample_fields = &sample_fields,
      .rasterize_areas = &rasterize_areas};
  return table;
}

}  // namespace edgewise::isa_reference
