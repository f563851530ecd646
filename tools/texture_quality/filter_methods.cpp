#include "texture_quality/filter_methods.hpp"

#include <string_view>

namespace edgewise::texture_quality {

std::vector<FilterMethod> filter_methods(int max_anisotropy) {
  const auto grid_name = [](int taps) {
    return "supersample_" + std::to_string(taps) + "x" + std::to_string(taps);
  };
  std::vector<FilterMethod> methods;
  for (int f = 0; f <= static_cast<int>(TextureFilter::ewa); ++f) {
    FilterMethod method;
    method.options.filter = static_cast<TextureFilter>(f);
    method.options.max_anisotropy = max_anisotropy;
    const std::string_view name = texture_filter_name(method.options.filter);
    switch (method.options.filter) {
      case TextureFilter::supersample:
        method.name = grid_name(method.options.supersample_taps);
        methods.push_back(method);
        method.options.supersample_taps = kDenseSupersampleTaps;
        method.name = grid_name(kDenseSupersampleTaps);
        break;
      case TextureFilter::anisotropic:
      case TextureFilter::ewa:
        method.name = std::string(name) + "_" + std::to_string(max_anisotropy) + "x";
        break;
      default:
        method.name = std::string(name);
        break;
    }
    methods.push_back(method);
  }
  return methods;
}

}  // namespace edgewise::texture_quality
