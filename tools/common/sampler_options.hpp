// The sampler's options, named and checked alike in every tool that samples a texture
// (edgewise-render, edgewise-sample, edgewise-texture-quality): --filter, --wrap, --lod,
// --lod-bias, --max-aniso, --taps, --pyramid. Each adds one option to `line` and returns it.
#pragma once

#include <string>

#include "common/command_line.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"

namespace edgewise::tools {

// --filter NAME, one of the TextureFilter names.
Option add_filter_option(CommandLine& line, TextureFilter& filter, const std::string& description);
// --wrap W: repeat, clamp or mirror, on both axes.
Option add_wrap_option(CommandLine& line, SamplerOptions& sampler);
// --lod exact|max_axis, the level-of-detail formula.
Option add_lod_option(CommandLine& line, LodFormula& lod);
// --lod-bias F, a finite number.
Option add_lod_bias_option(CommandLine& line, float& bias, const std::string& description);
// --max-aniso N in 1..kMaxAnisotropyLimit.
Option add_max_aniso_option(CommandLine& line, int& max_anisotropy);
// --taps N in 1..kMaxSupersampleTaps.
Option add_taps_option(CommandLine& line, int& taps);
// --pyramid box|lanczos3, how coarser levels are made.
Option add_pyramid_option(CommandLine& line, PyramidFilter& pyramid,
                          const std::string& description);
// --precision automatic|float32|fixed16.
Option add_precision_option(CommandLine& line, FilterPrecision& precision);
// --wrap, --precision, --lod, --lod-bias, --max-aniso and --taps into `sampler`.
void add_sampler_options(CommandLine& line, SamplerOptions& sampler);

}  // namespace edgewise::tools
