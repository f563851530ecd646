// What the shading kernels receive: screen-space triangles with their attributes, already
// transformed, clipped, mapped to the screen and snapped to 1/256 px, and the render state.
#pragma once

#include <cstddef>
#include <cstdint>

#include "edgewise/draw.hpp"
#include "../../coverage/triangle_batch.hpp"
#include "../../texture/sample_kernels.hpp"
#include "plane_tiles.hpp"

namespace edgewise::detail {

struct ShadeBatch {
  // Snapped screen positions, indices, clip rectangle, cull mode, and the target's sample
  // pattern (empty for one sample per pixel).
  TriangleBatch coverage;
  const float* depth;   // z/w per vertex, in [0, 1]
  const float* clip_w;  // clip-space w per vertex, > 0
  const Vec4* colors;   // per vertex
  const Vec3* normals;  // per vertex; null unless shading is diffuse
  Shading shading;
  InterpolationMethod method;
  Perspective perspective;
  DepthTest depth_test;
  bool depth_write;
  Vec3 light;  // unit length
  float ambient;
  std::uint32_t* color_tiles;  // Framebuffer's tiled storage
  float* depth_tiles;
  std::int32_t tiles_x;
  // Per-tile upper bounds on depth (framebuffer_access.hpp), or null. Kernels given them keep
  // them valid as they write depth, and with hierarchical_depth skip tiles a less or less_equal
  // test would fail everywhere.
  float* tile_max_depth;
  bool hierarchical_depth;
  // Texturing (texture_planes.hpp gives the queries); all null without a texture.
  const Vec2* uvs = nullptr;  // per vertex
  const Texture* texture = nullptr;
  const TextureDescription* texture_description = nullptr;  // the texture, flattened
  SamplerOptions sampler{};
  TextureDerivatives derivatives = TextureDerivatives::quad;
  // The codes DrawOptions::error_budget allows (shading_budget.hpp); 0: the exact methods.
  int budget_codes = 0;
  // An occlusion buffer's depth kept as planes (plane_tiles.hpp), or none. Given them, a kernel
  // draws occluders: depth test less with writes into the planes and depth_tiles, no colour
  // (shade_occluder-inl.hpp).
  PlaneTiles plane_tiles{};

  // Samples per pixel of the target (framebuffer.hpp gives the layout).
  std::size_t sample_count() const {
    return coverage.samples.empty() ? std::size_t{1} : coverage.samples.size();
  }
};

struct ShadeCounts {
  std::uint64_t fragments = 0;      // covered samples
  std::uint64_t passed = 0;         // samples that passed the depth test
  std::uint64_t tiles_skipped = 0;  // tiles rejected whole by their depth bound
  std::uint64_t constant = 0;       // passed samples written with a budget's constant colour
  std::uint64_t one_texel = 0;      // passed samples given a budget's one texel value per tile
};

}  // namespace edgewise::detail
