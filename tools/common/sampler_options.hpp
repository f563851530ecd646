// The sampler's options, named and checked alike in every tool that samples a texture
// (edgewise-render, edgewise-sample, edgewise-texture-quality): --filter, --wrap, --lod,
// --lod-bias, --max-aniso, --taps, --pyramid. Each adds one option to `app` and returns it.
#pragma once

#include <CLI/CLI.hpp>

#include <string>

#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"

namespace edgewise::tools {

// --filter NAME, one of the TextureFilter names.
CLI::Option* add_filter_option(CLI::App& app, TextureFilter& filter,
                               const std::string& description);
// --wrap W: repeat, clamp or mirror, on both axes.
CLI::Option* add_wrap_option(CLI::App& app, SamplerOptions& sampler);
// --lod exact|max_axis, the level-of-detail formula.
CLI::Option* add_lod_option(CLI::App& app, LodFormula& lod);
// --lod-bias F, a finite number.
CLI::Option* add_lod_bias_option(CLI::App& app, float& bias, const std::string& description);
// --max-aniso N in 1..kMaxAnisotropyLimit.
CLI::Option* add_max_aniso_option(CLI::App& app, int& max_anisotropy);
// --taps N in 1..kMaxSupersampleTaps.
CLI::Option* add_taps_option(CLI::App& app, int& taps);
// --pyramid box|lanczos3, how coarser levels are made.
CLI::Option* add_pyramid_option(CLI::App& app, PyramidFilter& pyramid,
                                const std::string& description);

// --wrap, --lod, --lod-bias, --max-aniso and --taps into `sampler`.
void add_sampler_options(CLI::App& app, SamplerOptions& sampler);

}  // namespace edgewise::tools
