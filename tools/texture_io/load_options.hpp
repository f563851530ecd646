// The options of a tool that loads a texture file (edgewise-render, edgewise-sample): how its
// coarser levels are made, whether its colour is sRGB-encoded, and the size it may take.
#pragma once

#include "common/command_line.hpp"
#include "edgewise/texture.hpp"
#include "texture_io/texture_loader.hpp"

namespace edgewise::texture_io {

// --pyramid box|lanczos3, --srgb and --max-texture-mb MB, into `pyramid`, `srgb` and `limits`.
void add_texture_load_options(tools::CommandLine& line, PyramidFilter& pyramid, bool& srgb,
                              LoadLimits& limits);

}  // namespace edgewise::texture_io
