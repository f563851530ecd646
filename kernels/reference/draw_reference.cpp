// The shading reference: every sample of every candidate pixel of every drawn triangle tested for
// coverage by the reference rasterizer, depth from the shared formula at the sample (so outcomes
// are the fast paths' exactly), and colour, once per pixel at its centre, from the
// double-precision interpolation references; textured, times the double-precision sampling
// reference at the shared queries (texture_planes.hpp).
#include <algorithm>
#include <array>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <limits>
#include <optional>
#include <span>

#include "../src/depth_plane.hpp"
#include "../src/framebuffer_access.hpp"
#include "../src/shade_batch.hpp"
#include "../src/shading_budget.hpp"
#include "../src/texture_planes.hpp"
#include "coverage_reference.hpp"
#include "draw_reference.hpp"
#include "interpolation_reference.hpp"
#include "sample_reference.hpp"

namespace edgewise::reference {
namespace {

bool passes(DepthTest test, float z, float stored) {
  switch (test) {
    case DepthTest::less:
      return z < stored;
    case DepthTest::less_equal:
      return z <= stored;
    case DepthTest::greater:
      return z > stored;
    case DepthTest::always:
      return true;
    case DepthTest::never:
      return false;
  }
  return false;
}

std::uint32_t to_byte(double v) {
  const double clamped = v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;  // NaN: 0
  return static_cast<std::uint32_t>(std::lrint(clamped * 255.0));
}

struct Corner {
  Vec2 position;
  float depth;
  double w;
  Vec4 color;
  Vec3 normal;
  Vec2 uv;
};

// The shaded colour at pixel center (px, py), before any texture.
std::array<double, 4> shaded_colour(const detail::ShadeBatch& batch, const Corner c[3], double px,
                                    double py) {
  if (batch.shading == Shading::flat)
    return {c[0].color.x, c[0].color.y, c[0].color.z, c[0].color.w};
  ScreenTriangle screen;
  for (int i = 0; i < 3; ++i) {
    screen.x[i] = c[i].position.x;
    screen.y[i] = c[i].position.y;
    screen.w[i] = c[i].w;
  }
  const Weights w = interpolation_weights(batch.method, batch.perspective, screen, px, py);
  std::array<double, 4> rgba = {0, 0, 0, 0};
  for (int i = 0; i < 3; ++i) {
    rgba[0] += w.b[i] * c[i].color.x;
    rgba[1] += w.b[i] * c[i].color.y;
    rgba[2] += w.b[i] * c[i].color.z;
    rgba[3] += w.b[i] * c[i].color.w;
  }
  if (batch.shading == Shading::diffuse) {
    double n[3] = {0, 0, 0};
    for (int i = 0; i < 3; ++i) {
      n[0] += w.b[i] * c[i].normal.x;
      n[1] += w.b[i] * c[i].normal.y;
      n[2] += w.b[i] * c[i].normal.z;
    }
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double facing = n[0] * batch.light.x + n[1] * batch.light.y + n[2] * batch.light.z;
    const double lambert = length > 0.0 ? std::fmax(facing / length, 0.0) : 0.0;
    const double light = batch.ambient + (1.0 - static_cast<double>(batch.ambient)) * lambert;
    for (int k = 0; k < 3; ++k)
      rgba[k] *= light;
  }
  return rgba;
}

std::uint32_t pack(const std::array<double, 4>& rgba) {
  return to_byte(rgba[0]) | to_byte(rgba[1]) << 8 | to_byte(rgba[2]) << 16 | to_byte(rgba[3]) << 24;
}

constexpr std::size_t kMaxSamples = 16;

// Where sample k of pixel (px, py) is in the tiled storage (framebuffer.hpp).
std::size_t sample_index(const detail::ShadeBatch& batch, std::int32_t px, std::int32_t py,
                         std::size_t k) {
  const std::size_t tile =
      static_cast<std::size_t>(py >> 3) * static_cast<std::size_t>(batch.tiles_x) +
      static_cast<std::size_t>(px >> 3);
  return (tile * batch.sample_count() + k) * 64 + static_cast<std::size_t>((py & 7) * 8 + (px & 7));
}

// Keeps the framebuffer's per-tile depth bounds valid after writing depth: every tile of the clip
// rectangle gets its bound anew from its values (the reference does not use the bounds itself).
void rebuild_depth_bounds(const detail::ShadeBatch& batch) {
  const PixelRect& clip = batch.coverage.clip;
  if (clip.empty()) return;
  for (std::int32_t ty = clip.y0 / 8; ty <= (clip.y1 - 1) / 8; ++ty) {
    for (std::int32_t tx = clip.x0 / 8; tx <= (clip.x1 - 1) / 8; ++tx) {
      const std::size_t tile =
          static_cast<std::size_t>(ty) * static_cast<std::size_t>(batch.tiles_x) +
          static_cast<std::size_t>(tx);
      const int samples = static_cast<int>(batch.sample_count());
      batch.tile_max_depth[tile] =
          detail::tile_depth_bound(&batch.depth_tiles[tile * 64 * batch.sample_count()], samples);
    }
  }
}

}  // namespace

void shade(const detail::ShadeBatch& batch, RasterReport& report, detail::ShadeCounts& counts) {
  // One sample is the pixel centre.
  constexpr SampleOffset kCentre[] = {{0, 0}};
  const std::span<const SampleOffset> pattern = batch.coverage.samples.empty()
                                                    ? std::span<const SampleOffset>(kCentre)
                                                    : batch.coverage.samples;
  const std::size_t samples = pattern.size();
  for_each_drawn_triangle(batch.coverage, report, [&](std::size_t t, const SnappedTriangle& tri) {
    Corner c[3];
    Vec2 p[3];
    float z[3];
    for (int i = 0; i < 3; ++i) {
      const std::size_t v = batch.coverage.indices ? batch.coverage.indices[3 * t + i] : 3 * t + i;
      c[i] = {batch.coverage.vertices[v],
              batch.depth[v],
              batch.clip_w[v],
              batch.colors[v],
              batch.normals ? batch.normals[v] : Vec3{0, 0, 0},
              batch.uvs ? batch.uvs[v] : Vec2{0, 0}};
      p[i] = c[i].position;
      z[i] = c[i].depth;
    }
    const detail::DepthPlane plane = detail::make_depth_plane(p, z);
    detail::TexturePlanes texture_planes;
    if (batch.texture != nullptr) {
      const Vec2 uv[3] = {c[0].uv, c[1].uv, c[2].uv};
      const double w[3] = {c[0].w, c[1].w, c[2].w};
      texture_planes = detail::make_texture_planes(p, uv, w, batch.perspective);
    }
    // The error budget's choices (shading_budget.hpp), made from the same inputs as the kernels'.
    detail::ShadeInterval interval;
    std::optional<std::uint32_t> constant;
    if (detail::budget_shades(batch)) {
      detail::BudgetTriangle budget_triangle;
      for (int i = 0; i < 3; ++i) {
        budget_triangle.position[i] = c[i].position;
        budget_triangle.w[i] = c[i].w;
        budget_triangle.colour[i] = c[i].color;
        budget_triangle.normal[i] = c[i].normal;
      }
      interval = detail::shade_interval(budget_triangle, batch);
    }
    bool budget_tiles = false;
    if (detail::budget_shades(batch) && batch.texture == nullptr) {
      constant = detail::constant_colour(interval, batch.budget_codes);
    } else if (detail::budget_shades(batch)) {
      const Vec2 position[3] = {c[0].position, c[1].position, c[2].position};
      const detail::TexturePlan plan =
          detail::texture_plan(interval, texture_planes, batch, position);
      constant = plan.colour;
      budget_tiles = plan.tiles;
    }
    const PixelRect box = candidate_pixels(tri, batch.coverage.clip);
    if (box.empty()) return;
    // Tile by tile, as the kernels choose per tile: every pixel's depth first, then the choice
    // from the pixels written, then their colour (a pixel's depth is tested once per triangle,
    // so the order changes nothing else).
    for (std::int32_t ty = box.y0 >> 3; ty <= (box.y1 - 1) >> 3; ++ty) {
      for (std::int32_t tx = box.x0 >> 3; tx <= (box.x1 - 1) >> 3; ++tx) {
        const std::int32_t x0 = std::max(box.x0, tx * 8), x1 = std::min(box.x1, tx * 8 + 8);
        const std::int32_t y0 = std::max(box.y0, ty * 8), y1 = std::min(box.y1, ty * 8 + 8);
        // Each covered sample's depth tested and written.
        bool passed[64][kMaxSamples] = {};
        bool any_passed[64] = {};
        for (std::int32_t py = y0; py < y1; ++py) {
          for (std::int32_t px = x0; px < x1; ++px) {
            const int at = (py & 7) * 8 + (px & 7);
            for (std::size_t k = 0; k < samples; ++k) {
              const SampleOffset offset = pattern[k];
              if (!covers_sample(tri, px, py, offset)) continue;
              ++counts.fragments;
              const std::size_t index = sample_index(batch, px, py, k);
              const float depth = detail::depth_at(plane, px, py, offset.x, offset.y);
              if (!passes(batch.depth_test, depth, batch.depth_tiles[index])) continue;
              ++counts.passed;
              if (batch.depth_write) batch.depth_tiles[index] = depth;
              passed[at][k] = any_passed[at] = true;
            }
          }
        }
        // The budget's choice for the tile, from the queries of the pixels written.
        detail::TileTexture choice;
        if (budget_tiles) {
          detail::TileQueries queries;
          for (int f = 0; f < 6; ++f) {
            queries.low[f] = std::numeric_limits<float>::infinity();
            queries.high[f] = -std::numeric_limits<float>::infinity();
          }
          bool any = false;
          for (std::int32_t py = y0; py < y1; ++py) {
            for (std::int32_t px = x0; px < x1; ++px) {
              if (!any_passed[(py & 7) * 8 + (px & 7)]) continue;
              any = true;
              const TextureQuery q =
                  detail::texture_query(texture_planes, batch.derivatives, px, py);
              const float fields[6] = {q.s, q.t, q.dsdx, q.dtdx, q.dsdy, q.dtdy};
              for (int f = 0; f < 6; ++f) {
                queries.finite = queries.finite && std::isfinite(fields[f]);
                queries.low[f] = std::min(queries.low[f], fields[f]);
                queries.high[f] = std::max(queries.high[f], fields[f]);
              }
            }
          }
          if (any) choice = detail::measured_texture_tile(interval, queries, batch);
        }
        const std::optional<std::uint32_t> budget_colour = constant ? constant : choice.colour;
        // Each pixel with a passed sample shaded once, at its centre, and its colour written to
        // those samples.
        for (std::int32_t py = y0; py < y1; ++py) {
          for (std::int32_t px = x0; px < x1; ++px) {
            const int at = (py & 7) * 8 + (px & 7);
            if (!any_passed[at]) continue;
            std::array<double, 4> rgba = shaded_colour(batch, c, px + 0.5, py + 0.5);
            if (batch.texture != nullptr && !budget_colour) {
              Rgba texel;
              if (choice.one_texel) {
                for (int k = 0; k < 4; ++k)
                  texel[k] = choice.texel[k];
              } else {
                const TextureQuery query =
                    detail::texture_query(texture_planes, batch.derivatives, px, py);
                texel = sample(*batch.texture, batch.sampler, query);
              }
              for (int k = 0; k < 4; ++k)
                rgba[k] *= texel[k];
            }
            const std::uint32_t packed = budget_colour ? *budget_colour : pack(rgba);
            for (std::size_t k = 0; k < samples; ++k) {
              if (!passed[at][k]) continue;
              batch.color_tiles[sample_index(batch, px, py, k)] = packed;
              if (budget_colour) {
                ++counts.constant;
              } else if (choice.one_texel) {
                ++counts.one_texel;
              }
            }
          }
        }
      }
    }
  });
  if (batch.depth_write && batch.tile_max_depth != nullptr) rebuild_depth_bounds(batch);
}

}  // namespace edgewise::reference
