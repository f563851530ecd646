#include "common/sampler_options.hpp"

#include <span>
#include <vector>

#include "common/choice_options.hpp"
#include "common/value_options.hpp"

namespace edgewise::tools {

Option add_filter_option(CommandLine& line, TextureFilter& filter, const std::string& description) {
  return add_enum_option(line, "--filter", filter, description);
}

Option add_wrap_option(CommandLine& line, SamplerOptions& sampler) {
  const std::span<const WrapMode> modes = values_of<WrapMode>();
  std::vector<std::string> names;
  for (WrapMode mode : modes)
    names.emplace_back(name_of(mode));
  return add_choice_option(
      line, "--wrap", std::move(names),
      [&sampler, modes](std::size_t i) { sampler.wrap_s = sampler.wrap_t = modes[i]; },
      "on both axes (default repeat)");
}

Option add_lod_option(CommandLine& line, LodFormula& lod) {
  return add_enum_option(line, "--lod", lod, "level-of-detail formula (default exact)");
}

Option add_lod_bias_option(CommandLine& line, float& bias, const std::string& description) {
  return add_number_option(line, "--lod-bias", bias, description);
}

Option add_max_aniso_option(CommandLine& line, int& max_anisotropy) {
  return add_integer_option(line, "--max-aniso", max_anisotropy, 1, kMaxAnisotropyLimit,
                            "anisotropic probes, EWA eccentricity: 1.." +
                                std::to_string(kMaxAnisotropyLimit) + " (default 16)");
}

Option add_taps_option(CommandLine& line, int& taps) {
  return add_integer_option(
      line, "--taps", taps, 1, kMaxSupersampleTaps,
      "supersample: N x N taps, 1.." + std::to_string(kMaxSupersampleTaps) + " (default 4)");
}

Option add_pyramid_option(CommandLine& line, PyramidFilter& pyramid,
                          const std::string& description) {
  return add_enum_option(line, "--pyramid", pyramid, description);
}

Option add_precision_option(CommandLine& line, FilterPrecision& precision) {
  return add_enum_option(
      line, "--precision", precision,
      "the bilinear taps' arithmetic on linear 8-bit textures: float32, or\n"
      "fixed16 (16-bit integer weights, as GPUs filter); default automatic, the\n"
      "one measured best for the filter");
}

void add_sampler_options(CommandLine& line, SamplerOptions& sampler) {
  add_wrap_option(line, sampler);
  add_precision_option(line, sampler.precision);
  add_lod_option(line, sampler.lod);
  add_lod_bias_option(line, sampler.lod_bias, "added to log2 of the footprint (default 0)");
  add_max_aniso_option(line, sampler.max_anisotropy);
  add_taps_option(line, sampler.supersample_taps);
}

}  // namespace edgewise::tools
