#include "texture_description.hpp"

#include <array>
#include <cmath>
#include <stdexcept>
#include <string>

namespace edgewise::detail {
namespace {

// The EWA weights as the kernels read them (sample.hpp; the reference builds the same table in
// double): exp(-2 r2) - exp(-2) at r2 = i / 127, rounded once to float, and a trailing 0.
const float* ewa_weights() {
  static const auto table = [] {
    std::array<float, kEwaWeights> weights{};
    for (int i = 0; i + 1 < kEwaWeights; ++i) {
      const double r2 = static_cast<double>(i) / (kEwaWeights - 2);
      weights[static_cast<std::size_t>(i)] =
          static_cast<float>(std::exp(-2.0 * r2) - std::exp(-2.0));
    }
    return weights;
  }();
  return table.data();
}

}  // namespace

void validate_sampler(const Texture& texture, const SamplerOptions& options,
                      std::string_view caller) {
  const std::string prefix = std::string(caller) + ": ";
  if (options.max_anisotropy < 1 || options.max_anisotropy > kMaxAnisotropyLimit) {
    throw std::invalid_argument(prefix + "max_anisotropy " +
                                std::to_string(options.max_anisotropy) + " is outside 1 .. " +
                                std::to_string(kMaxAnisotropyLimit));
  }
  if (options.supersample_taps < 1 || options.supersample_taps > kMaxSupersampleTaps) {
    throw std::invalid_argument(prefix + "supersample_taps " +
                                std::to_string(options.supersample_taps) + " is outside 1 .. " +
                                std::to_string(kMaxSupersampleTaps));
  }
  if (static_cast<int>(options.precision) > static_cast<int>(FilterPrecision::fixed16)) {
    throw std::invalid_argument(prefix + "precision " +
                                std::to_string(static_cast<int>(options.precision)) +
                                " is not a FilterPrecision");
  }
  if (!std::isfinite(options.lod_bias))
    throw std::invalid_argument(prefix + "lod_bias is not finite");
  if (options.filter == TextureFilter::ripmap && texture.ripmap_levels().empty()) {
    throw std::invalid_argument(prefix + "the ripmap filter needs a texture built with ripmaps");
  }
  if (options.filter == TextureFilter::summed_area && texture.summed_area_table() == nullptr) {
    throw std::invalid_argument(
        prefix + "the summed_area filter needs a texture built with a summed-area table");
  }
}

FlatTexture::LevelArrays FlatTexture::level_arrays(std::span<const TextureLevel> levels,
                                                   std::size_t texel_bytes) {
  LevelArrays arrays;
  for (const TextureLevel& level : levels) {
    arrays.width.push_back(level.width);
    arrays.height.push_back(level.height);
    arrays.start.push_back(static_cast<std::int32_t>(level.offset / texel_bytes));
  }
  // Readable to kLevelTableReadable entries; table() keeps the true count.
  arrays.count = static_cast<std::int32_t>(levels.size());
  for (std::vector<std::int32_t>* array : {&arrays.width, &arrays.height, &arrays.start}) {
    const std::int32_t last = array->empty() ? 0 : array->back();
    if (array->size() < kLevelTableReadable) array->resize(kLevelTableReadable, last);
  }
  return arrays;
}

LevelTable FlatTexture::LevelArrays::table() const {
  return {width.data(), height.data(), start.data(), count};
}

FlatTexture::FlatTexture(const Texture& texture) {
  const std::size_t texel_bytes = texture.format() == TexelFormat::rgba8 ? 4 : 16;
  mips_ = level_arrays(texture.mip_levels(), texel_bytes);
  rips_ = level_arrays(texture.ripmap_levels(), texel_bytes);
  TextureDescription& d = description_;
  d.texture = &texture;
  d.texels = texture.storage();
  d.format = texture.format();
  d.srgb_table = texture.format() == TexelFormat::rgba8 && texture.encoding() == ColorEncoding::srgb
                     ? srgb_decode_table().data()
                     : nullptr;
  if (texture.format() == TexelFormat::rgba8) {
    for (int k = 0; k < 4; ++k)
      d.channel_scale[k] = k < 3 && d.srgb_table != nullptr ? 1.0f : 1.0f / 255.0f;
  }
  d.ewa_weights = ewa_weights();
  d.width = static_cast<float>(texture.width());
  d.height = static_cast<float>(texture.height());
  d.mips = mips_.table();
  d.rips = rips_.table();
  d.summed_area_table = texture.summed_area_table();
  d.rip_columns = texture.ripmap_columns();
  d.rip_rows =
      texture.ripmap_columns() > 0
          ? static_cast<std::int32_t>(texture.ripmap_levels().size()) / texture.ripmap_columns()
          : 0;
}

}  // namespace edgewise::detail
