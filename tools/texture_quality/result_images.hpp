// Pictures of a filter's result and of its error, for looking at where a filter fails.
//
// PNG files, 8-bit RGB. The values are linear; each is clamped to [0, 1] and sRGB-encoded
// (linear_to_srgb), so that the picture looks right on a screen: a linear 0.5 shows as mid-grey.
// The error picture is |result - truth| per channel, times kErrorImageGain, encoded the same way
// (the sRGB curve lifts small errors further into view).
#pragma once

#include <filesystem>

#include "texture_scene/linear_image.hpp"

namespace edgewise::texture_quality {

inline constexpr float kErrorImageGain = 8.0f;

// Throws std::runtime_error("PATH: cannot write: reason") when the file cannot be written.
void write_srgb_png(const std::filesystem::path& path, const texture_scene::LinearImage& image);

// |result - truth| * kErrorImageGain per channel (alpha 1). Throws std::invalid_argument when
// the sizes differ.
texture_scene::LinearImage error_image(const texture_scene::LinearImage& result,
                                       const texture_scene::LinearImage& truth);

}  // namespace edgewise::texture_quality
