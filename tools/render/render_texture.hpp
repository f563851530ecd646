// The texture edgewise-render draws with (--texture): an image file, loaded as edgewise-sample
// loads it, or the built-in checkerboard, built with the pyramids its filters need.
#pragma once

#include <cstddef>
#include <cstdint>
#include <iterator>
#include <string>

#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "render/command_line.hpp"

namespace edgewise::render_tool {

// The built-in checkerboard: 1024 texels a side, so that on the ground plane (one texture
// repeat per 4 units) texels reach about a pixel near the eye and every mip level is used
// towards the horizon; 8 x 8 squares of 128 texels, sharp edges that alias without filtering.
inline constexpr std::int32_t kCheckerSize = 1024;
inline constexpr std::int32_t kCheckerSquares = 8;

struct RenderTexture {
  Texture texture;
  std::string origin;  // where the texels come from: the file and its pixel type, or "checker"
};

// Ripmaps and the summed-area table are built only when the filter (or --each-filter) needs
// them. Throws std::runtime_error("FILE: reason") for a file that cannot be read as an image.
RenderTexture load_render_texture(const TextureSettings& settings);

// One line for the printed report: origin, size, format, levels, sampler and derivatives.
std::string describe_texture(const RenderTexture& texture, const TextureSettings& settings);

}  // namespace edgewise::render_tool
