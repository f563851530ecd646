// sample(): option checks, the Texture flattened for the kernels, and the choice of kernel.
#include "edgewise/sample.hpp"

#include <cmath>
#include <stdexcept>
#include <string>

#include "kernel_table.hpp"
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
  detail::kernel_table(chosen).sample(flat.description(), options.sampler, queries.data(),
                                      queries.size(), out.data());
}

}  // namespace edgewise
