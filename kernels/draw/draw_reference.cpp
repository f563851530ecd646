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

#include "shading/depth_plane.hpp"
#include "../core/framebuffer_access.hpp"
#include "shading/shade_batch.hpp"
#include "shading/shading_budget.hpp"
#include "shading/texture_planes.hpp"
#include "../coverage/coverage_reference.hpp"
#include "../core/reference_kernels.hpp"
#include "../interpolation/interpolation_reference.hpp"
#include "../texture/sample_reference.hpp"

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

// A drawn triangle's corners and the planes every path evaluates: depth, and the texture
// coordinates' when textured.
struct PlanarTriangle {
  Corner c[3];
  detail::DepthPlane depth;
  detail::TexturePlanes texture;
};

PlanarTriangle planar_triangle(const detail::ShadeBatch& batch, std::size_t t) {
  PlanarTriangle tri;
  Vec2 p[3];
  float z[3];
  for (int i = 0; i < 3; ++i) {
    const std::size_t v = batch.coverage.indices ? batch.coverage.indices[3 * t + i] : 3 * t + i;
    tri.c[i] = {batch.coverage.vertices[v],
                batch.depth[v],
                batch.clip_w[v],
                batch.colors[v],
                batch.normals ? batch.normals[v] : Vec3{0, 0, 0},
                batch.uvs ? batch.uvs[v] : Vec2{0, 0}};
    p[i] = tri.c[i].position;
    z[i] = tri.c[i].depth;
  }
  tri.depth = detail::make_depth_plane(p, z);
  if (batch.texture != nullptr) {
    const Vec2 uv[3] = {tri.c[0].uv, tri.c[1].uv, tri.c[2].uv};
    const double w[3] = {tri.c[0].w, tri.c[1].w, tri.c[2].w};
    tri.texture = detail::make_texture_planes(p, uv, w, batch.perspective);
  }
  return tri;
}

// The error budget's choices for a triangle (shading_budget.hpp), made from the same inputs as
// the kernels': one colour for all of it, or (`tiles`) a choice per tile.
struct BudgetChoice {
  detail::ShadeInterval interval;
  std::optional<std::uint32_t> constant;
  bool tiles = false;
};

BudgetChoice budget_choice(const detail::ShadeBatch& batch, const PlanarTriangle& tri) {
  BudgetChoice choice;
  if (!detail::budget_shades(batch)) return choice;
  detail::BudgetTriangle budget_triangle;
  for (int i = 0; i < 3; ++i) {
    budget_triangle.position[i] = tri.c[i].position;
    budget_triangle.w[i] = tri.c[i].w;
    budget_triangle.colour[i] = tri.c[i].color;
    budget_triangle.normal[i] = tri.c[i].normal;
  }
  choice.interval = detail::shade_interval(budget_triangle, batch);
  if (batch.texture == nullptr) {
    choice.constant = detail::constant_colour(choice.interval, batch.budget_codes);
  } else {
    const Vec2 position[3] = {tri.c[0].position, tri.c[1].position, tri.c[2].position};
    const detail::TexturePlan plan =
        detail::texture_plan(choice.interval, tri.texture, batch, position);
    choice.constant = plan.colour;
    choice.tiles = plan.tiles;
  }
  return choice;
}

// The pixels [x0, x1) x [y0, y1) of one tile, and which of their samples passed the depth test.
struct TileSamples {
  std::int32_t x0, x1, y0, y1;
  bool passed[64][kMaxSamples] = {};
  bool any_passed[64] = {};
};

// Each covered sample of the tile's pixels depth-tested and, with depth writes, written.
void test_tile_depth(const detail::ShadeBatch& batch, const SnappedTriangle& snapped,
                     const detail::DepthPlane& plane, std::span<const SampleOffset> pattern,
                     TileSamples& tile, detail::ShadeCounts& counts) {
  for (std::int32_t py = tile.y0; py < tile.y1; ++py) {
    for (std::int32_t px = tile.x0; px < tile.x1; ++px) {
      const int at = (py & 7) * 8 + (px & 7);
      for (std::size_t k = 0; k < pattern.size(); ++k) {
        const SampleOffset offset = pattern[k];
        if (!covers_sample(snapped, px, py, offset)) continue;
        ++counts.fragments;
        const std::size_t index = sample_index(batch, px, py, k);
        const float depth = detail::depth_at(plane, px, py, offset.x, offset.y);
        if (!passes(batch.depth_test, depth, batch.depth_tiles[index])) continue;
        ++counts.passed;
        if (batch.depth_write) batch.depth_tiles[index] = depth;
        tile.passed[at][k] = tile.any_passed[at] = true;
      }
    }
  }
}

// The budget's choice for a tile, from the texture queries of the pixels written there.
detail::TileTexture tile_texture_choice(const detail::ShadeBatch& batch, const PlanarTriangle& tri,
                                        const BudgetChoice& budget, const TileSamples& tile) {
  detail::TileQueries queries;
  for (int f = 0; f < 6; ++f) {
    queries.low[f] = std::numeric_limits<float>::infinity();
    queries.high[f] = -std::numeric_limits<float>::infinity();
  }
  bool any = false;
  for (std::int32_t py = tile.y0; py < tile.y1; ++py) {
    for (std::int32_t px = tile.x0; px < tile.x1; ++px) {
      if (!tile.any_passed[(py & 7) * 8 + (px & 7)]) continue;
      any = true;
      const TextureQuery q = detail::texture_query(tri.texture, batch.derivatives, px, py);
      const float fields[6] = {q.s, q.t, q.dsdx, q.dtdx, q.dsdy, q.dtdy};
      for (int f = 0; f < 6; ++f) {
        queries.finite = queries.finite && std::isfinite(fields[f]);
        queries.low[f] = std::min(queries.low[f], fields[f]);
        queries.high[f] = std::max(queries.high[f], fields[f]);
      }
    }
  }
  if (!any) return {};
  return detail::measured_texture_tile(budget.interval, queries, batch);
}

// Each pixel of the tile with a passed sample shaded once, at its centre, and its colour written
// to those samples.
void write_tile_colours(const detail::ShadeBatch& batch, const PlanarTriangle& tri,
                        std::optional<std::uint32_t> budget_colour,
                        const detail::TileTexture& choice, std::size_t samples,
                        const TileSamples& tile, detail::ShadeCounts& counts) {
  for (std::int32_t py = tile.y0; py < tile.y1; ++py) {
    for (std::int32_t px = tile.x0; px < tile.x1; ++px) {
      const int at = (py & 7) * 8 + (px & 7);
      if (!tile.any_passed[at]) continue;
      std::array<double, 4> rgba = shaded_colour(batch, tri.c, px + 0.5, py + 0.5);
      if (batch.texture != nullptr && !budget_colour) {
        Rgba texel;
        if (choice.one_texel) {
          for (int k = 0; k < 4; ++k)
            texel[k] = choice.texel[k];
        } else {
          const TextureQuery query = detail::texture_query(tri.texture, batch.derivatives, px, py);
          texel = sample(*batch.texture, batch.sampler, query);
        }
        for (int k = 0; k < 4; ++k)
          rgba[k] *= texel[k];
      }
      const std::uint32_t packed = budget_colour ? *budget_colour : pack(rgba);
      for (std::size_t k = 0; k < samples; ++k) {
        if (!tile.passed[at][k]) continue;
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

// One triangle, tile by tile, as the kernels choose per tile: every pixel's depth first, then
// the choice from the pixels written, then their colour (a pixel's depth is tested once per
// triangle, so the order changes nothing else).
void shade_triangle(const detail::ShadeBatch& batch, std::size_t t, const SnappedTriangle& snapped,
                    std::span<const SampleOffset> pattern, detail::ShadeCounts& counts) {
  const PlanarTriangle tri = planar_triangle(batch, t);
  const BudgetChoice budget = budget_choice(batch, tri);
  const PixelRect box = candidate_pixels(snapped, batch.coverage.clip);
  if (box.empty()) return;
  for (std::int32_t ty = box.y0 >> 3; ty <= (box.y1 - 1) >> 3; ++ty) {
    for (std::int32_t tx = box.x0 >> 3; tx <= (box.x1 - 1) >> 3; ++tx) {
      TileSamples tile;
      tile.x0 = std::max(box.x0, tx * 8);
      tile.x1 = std::min(box.x1, tx * 8 + 8);
      tile.y0 = std::max(box.y0, ty * 8);
      tile.y1 = std::min(box.y1, ty * 8 + 8);
      test_tile_depth(batch, snapped, tri.depth, pattern, tile, counts);
      const detail::TileTexture choice =
          budget.tiles ? tile_texture_choice(batch, tri, budget, tile) : detail::TileTexture{};
      const std::optional<std::uint32_t> budget_colour =
          budget.constant ? budget.constant : choice.colour;
      write_tile_colours(batch, tri, budget_colour, choice, pattern.size(), tile, counts);
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
  for_each_drawn_triangle(batch.coverage, report,
                          [&](std::size_t t, const SnappedTriangle& snapped) {
                            shade_triangle(batch, t, snapped, pattern, counts);
                          });
  if (batch.depth_write && batch.tile_max_depth != nullptr) rebuild_depth_bounds(batch);
}

}  // namespace edgewise::reference
