#include "common/sampler_options.hpp"

#include <span>
#include <vector>

#include "common/choice_options.hpp"
#include "common/value_options.hpp"

namespace edgewise::tools {

CLI::Option* add_filter_option(CLI::App& app, TextureFilter& filter,
                               const std::string& description) {
  return add_enum_option(app, "--filter", filter, description);
}

CLI::Option* add_wrap_option(CLI::App& app, SamplerOptions& sampler) {
  const std::span<const WrapMode> modes = values_of<WrapMode>();
  std::vector<std::string> names;
  for (WrapMode mode : modes)
    names.emplace_back(name_of(mode));
  return add_choice_option(
      app, "--wrap", std::move(names),
      [&sampler, modes](std::size_t i) { sampler.wrap_s = sampler.wrap_t = modes[i]; },
      "on both axes (default repeat)");
}

CLI::Option* add_lod_option(CLI::App& app, LodFormula& lod) {
  return add_enum_option(app, "--lod", lod, "level-of-detail formula (default exact)");
}

CLI::Option* add_lod_bias_option(CLI::App& app, float& bias, const std::string& description) {
  return add_number_option(app, "--lod-bias", bias, description);
}

CLI::Option* add_max_aniso_option(CLI::App& app, int& max_anisotropy) {
  return add_integer_option(app, "--max-aniso", max_anisotropy, 1, kMaxAnisotropyLimit,
                            "anisotropic probes, EWA eccentricity: 1.." +
                                std::to_string(kMaxAnisotropyLimit) + " (default 16)");
}

CLI::Option* add_taps_option(CLI::App& app, int& taps) {
  return add_integer_option(
      app, "--taps", taps, 1, kMaxSupersampleTaps,
      "supersample: N x N taps, 1.." + std::to_string(kMaxSupersampleTaps) + " (default 4)");
}

CLI::Option* add_pyramid_option(CLI::App& app, PyramidFilter& pyramid,
                                const std::string& description) {
  return add_enum_option(app, "--pyramid", pyramid, description);
}

void add_sampler_options(CLI::App& app, SamplerOptions& sampler) {
  add_wrap_option(app, sampler);
  add_lod_option(app, sampler.lod);
  add_lod_bias_option(app, sampler.lod_bias, "added to log2 of the footprint (default 0)");
  add_max_aniso_option(app, sampler.max_anisotropy);
  add_taps_option(app, sampler.supersample_taps);
}

}  // namespace edgewise::tools
