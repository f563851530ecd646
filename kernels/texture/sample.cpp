// sample(): option checks, the Texture flattened for the kernels, and the choice of kernel.
#include "edgewise/sample.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "../core/kernel_table.hpp"
#include "sample_kernels.hpp"
#include "texture_description.hpp"

namespace edgewise {

void sample(const Texture& texture, const SampleOptions& options,
            std::span<const TextureQuery> queries, std::span<Vec4> out) {
  if (queries.size() != out.size()) {
    throw std::invalid_argument("sample: " + std::to_string(queries.size()) + " queries but " +
                                std::to_string(out.size()) + " results");
  }
  detail::validate_sampler(texture, options.sampler, "sample");
  const Isa chosen = resolve_isa(options.isa);
  if (queries.empty()) return;
  const detail::FlatTexture flat(texture);
  SamplerOptions resolved = options.sampler;
  resolved.precision = effective_precision(texture, resolved);
  detail::kernel_table(chosen).sample(flat.description(), resolved, queries.data(), queries.size(),
                                      out.data());
}

bool reads_bilinear_taps(TextureFilter filter) {
  switch (filter) {
    case TextureFilter::bilinear:
    case TextureFilter::mip_nearest:
    case TextureFilter::trilinear:
    case TextureFilter::supersample:
    case TextureFilter::ripmap:
    case TextureFilter::anisotropic:
      return true;
    default:
      return false;
  }
}

// fixed16 matches float32 on minified views, but its weights' rounding shows in the magnification
// views, where float32 comes closest to ground truth: beyond the 0.05 dB allowed, for every tap
// filter (docs/texture-filtering.md, "Fixed-point taps").
FilterPrecision default_precision(TextureFilter) {
  return FilterPrecision::float32;
}

FilterPrecision effective_precision(const Texture& texture, const SamplerOptions& options) {
  const bool applies = texture.format() == TexelFormat::rgba8 &&
                       texture.encoding() == ColorEncoding::linear &&
                       reads_bilinear_taps(options.filter);
  if (!applies) return FilterPrecision::float32;
  return options.precision == FilterPrecision::automatic ? default_precision(options.filter)
                                                         : options.precision;
}

}  // namespace edgewise
