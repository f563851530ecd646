#include "texture_quality/filter_methods.hpp"

#include <algorithm>
#include <charconv>
#include <span>
#include <string_view>

namespace edgewise::texture_quality {

bool reads_lod_bias(TextureFilter filter) {
  switch (filter) {
    case TextureFilter::mip_nearest:
    case TextureFilter::trilinear:
    case TextureFilter::ripmap:
    case TextureFilter::anisotropic:
    case TextureFilter::ewa:
      return true;
    default:
      return false;
  }
}

bool reads_lod_formula(TextureFilter filter) {
  return filter == TextureFilter::mip_nearest || filter == TextureFilter::trilinear ||
         filter == TextureFilter::anisotropic;
}

namespace {

// The shortest decimal that reads back as `value` ("-0.5", "0.25").
std::string shortest(float value) {
  char text[32];
  const std::to_chars_result end = std::to_chars(std::begin(text), std::end(text), value);
  return std::string(text, end.ptr);
}

// Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "_" + std::string inlined.
std::string level_of_detail_suffix(const SamplerOptions& options) {
  std::string suffix;
  if (reads_lod_formula(options.filter) && options.lod != LodFormula::exact) {
    suffix += '_';
    suffix += name_of(options.lod);
  }
  if (reads_lod_bias(options.filter) && options.lod_bias != 0.0f) {
    suffix += "_bias";
    suffix += shortest(options.lod_bias);
  }
  return suffix;
}

// `method` in float32 and, where its filter has bilinear taps, in each precision asked for.
void push_precisions(FilterMethod method, const MethodSettings& settings,
                     std::vector<FilterMethod>& methods) {
  if (!reads_bilinear_taps(method.options.filter)) {
    method.options.precision = FilterPrecision::float32;
    methods.push_back(method);
    return;
  }
  static constexpr FilterPrecision kBoth[] = {FilterPrecision::float32, FilterPrecision::fixed16};
  const std::span<const FilterPrecision> precisions =
      settings.precisions.empty() ? std::span<const FilterPrecision>(kBoth) : settings.precisions;
  for (FilterPrecision precision : precisions) {
    FilterMethod variant = method;
    variant.options.precision = precision;
    if (precision == FilterPrecision::fixed16) variant.name += "_fixed16";
    methods.push_back(variant);
  }
}

}  // namespace

std::vector<FilterMethod> filter_methods(const MethodSettings& settings) {
  const auto grid_name = [](int taps) {
    return "supersample_" + std::to_string(taps) + "x" + std::to_string(taps);
  };
  const auto wanted = [&settings](TextureFilter filter) {
    return settings.filters.empty() || std::find(settings.filters.begin(), settings.filters.end(),
                                                 filter) != settings.filters.end();
  };
  std::vector<FilterMethod> methods;
  for (int f = 0; f <= static_cast<int>(TextureFilter::ewa); ++f) {
    FilterMethod method;
    method.options.filter = static_cast<TextureFilter>(f);
    if (!wanted(method.options.filter)) continue;
    method.options.max_anisotropy = settings.max_anisotropy;
    method.options.lod = settings.lod;
    method.options.lod_bias = settings.lod_bias;
    const std::string_view name = name_of(method.options.filter);
    switch (method.options.filter) {
      case TextureFilter::supersample:
        method.name = grid_name(method.options.supersample_taps);
        push_precisions(method, settings, methods);
        method.options.supersample_taps = kDenseSupersampleTaps;
        method.name = grid_name(kDenseSupersampleTaps);
        break;
      case TextureFilter::anisotropic:
      case TextureFilter::ewa:
        method.name = std::string(name) + "_" + std::to_string(settings.max_anisotropy) + "x";
        break;
      default:
        method.name = std::string(name);
        break;
    }
    method.name += level_of_detail_suffix(method.options);
    push_precisions(method, settings, methods);
  }
  return methods;
}

}  // namespace edgewise::texture_quality
