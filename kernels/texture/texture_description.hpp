// A Texture and SamplerOptions made ready for the sampling kernels: the option checks sample()
// and draw() share, and the texture flattened into the plain arrays the kernels read.
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <string_view>
#include <vector>

#include "edgewise/isa.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "sample_kernels.hpp"

namespace edgewise::detail {

// Throws std::invalid_argument, the message starting with `caller`, for an option out of range
// or a filter that needs ripmaps or a summed-area table the texture was built without.
void validate_sampler(const Texture& texture, const SamplerOptions& options,
                      std::string_view caller);

// The kernels' view of a texture; it points into the texture and into itself, so it is neither
// copied nor moved, and lives no longer than the texture.
class FlatTexture {
 public:
  explicit FlatTexture(const Texture& texture);
  FlatTexture(const FlatTexture&) = delete;
  FlatTexture& operator=(const FlatTexture&) = delete;

  const TextureDescription& description() const { return description_; }

 private:
  // Level sizes and starts (in texels) as the kernels read them.
  struct LevelArrays {
    std::vector<std::int32_t> width, height, start;
    std::int32_t count = 0;
    LevelTable table() const;
  };
  static LevelArrays level_arrays(std::span<const TextureLevel> levels, std::size_t texel_bytes);

  LevelArrays mips_, rips_;
  TextureDescription description_;
};

}  // namespace edgewise::detail
