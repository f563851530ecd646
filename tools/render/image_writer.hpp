// Writing a rendered Framebuffer, or a resolved image, to an image file (common/image_file.hpp,
// OpenImageIO).
//
//   .png  8-bit RGBA, the framebuffer's bytes as they are (linear values v / 255).
//   .exr  32-bit float channels R, G, B, A (v / 255) and Z, the depth buffer (z/w in [0, 1],
//         the clear value where nothing was drawn), in one file.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <string_view>

#include "edgewise/framebuffer.hpp"

namespace edgewise::render_tool {

enum class ImageFormat { png, exr };

// By the file's extension, in any letter case. Throws UsageError for any other extension.
ImageFormat image_format_for(std::string_view path);

// `path` with `suffix` inserted before its extension: ("out/a.png", "-ewa") gives "out/a-ewa.png".
std::string path_with_suffix(std::string_view path, std::string_view suffix);

// Throws std::runtime_error("PATH: reason") when the file cannot be written.
void write_image(const std::string& path, const Framebuffer& framebuffer);

// A resolved image (resolve.hpp): row-major RGBA8, `width` x `height`. EXR files get R, G, B and
// A only: a resolved image has no one depth per pixel.
void write_rgba_image(const std::string& path, std::int32_t width, std::int32_t height,
                      std::span<const std::uint8_t> rgba);

}  // namespace edgewise::render_tool
