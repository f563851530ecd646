// What the per-ISA sampling kernels take: a Texture flattened into plain arrays (no batches cross
// translation units), and the entry point each ISA defines.
#pragma once

#include <cstddef>
#include <cstdint>

#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "edgewise/vector.hpp"

namespace edgewise::detail {

// Every LevelTable array can be read up to this many entries (those past `count` repeat the
// last), so that kernels can hold a whole mip chain (at most 16 levels) in registers.
inline constexpr int kLevelTableReadable = 16;

// Sizes and starts of a set of levels, in texels from the start of the texture's storage.
// Starts fit int32: a texture has at most 2^30 texels in level 0 and 4/3 of that in all levels.
struct LevelTable {
  const std::int32_t* width = nullptr;
  const std::int32_t* height = nullptr;
  const std::int32_t* start = nullptr;
  std::int32_t count = 0;
};

inline constexpr int kEwaWeights = 129;

struct TextureDescription {
  const Texture* texture = nullptr;   // what was flattened (the reference samples it directly)
  const std::byte* texels = nullptr;  // Texture::storage()
  TexelFormat format = TexelFormat::rgba8;
  const float* srgb_table = nullptr;  // 256 decoded values; null for linear textures
  // Linear value = fetched value * channel_scale: 1 / 255 for 8-bit codes, 1 for decoded sRGB
  // channels and float texels.
  float channel_scale[4] = {1.0f, 1.0f, 1.0f, 1.0f};
  float width = 0.0f, height = 0.0f;  // of level 0
  // The EWA Gaussian: kEwaWeights entries, entry i the weight at Q = i / (kEwaWeights - 2), and
  // a last 0 so that interpolating at Q = 1 reads no further.
  const float* ewa_weights = nullptr;
  LevelTable mips;
  LevelTable rips;
  const SummedAreaTable* summed_area_table =
      nullptr;  // column-major in width: (i, j) at j * rip_columns + i
  std::int32_t rip_columns = 0;
  std::int32_t rip_rows = 0;
};

// Whether the kernels filter in fixed point: `options` as the callers pass them, with
// effective_precision() (sample.hpp) already applied.
inline bool fixed_point_taps(const TextureDescription& texture, const SamplerOptions& options) {
  return options.precision == FilterPrecision::fixed16 && texture.format == TexelFormat::rgba8 &&
         texture.srgb_table == nullptr && edgewise::reads_bilinear_taps(options.filter);
}

// out[i] = the filtered linear RGBA at queries[i]: each ISA's `sample` kernel (kernel_table.hpp).
using SampleKernel = void (*)(const TextureDescription& texture, const SamplerOptions& options,
                              const TextureQuery* queries, std::size_t count, Vec4* out);

// Queries as one array per field and results as one array per channel, for callers that
// compute queries a batch of lanes at a time (the shading kernels).
struct QueryFields {
  const float* s;
  const float* t;
  const float* dsdx;
  const float* dtdx;
  const float* dsdy;
  const float* dtdy;
};

struct ResultChannels {
  float* c[4];  // R, G, B, A
};

// The same as SampleKernel over QueryFields and ResultChannels: each ISA's `sample_fields`.
using SampleFieldsKernel = void (*)(const TextureDescription& texture,
                                    const SamplerOptions& options, const QueryFields& queries,
                                    std::size_t count, const ResultChannels& out);

}  // namespace edgewise::detail
