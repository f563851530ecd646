// Writing pixels to an image file, the format given by the file's extension (.png, .exr, ...):
// 8-bit PNG files through libpng (png_encoder.hpp), the rest through OpenImageIO. Every image a
// tool writes goes through here: edgewise-render's frames, edgewise-demo's picture,
// edgewise-texture-quality's results and errors.
#pragma once

#include <cstdint>
#include <span>
#include <string>
#include <vector>

namespace edgewise::tools {

// Interleaved pixels, row-major from the top row, `channels` values each: 8-bit or float.
struct ImagePixels {
  int width = 0, height = 0, channels = 0;
  std::span<const std::uint8_t> bytes;  // width * height * channels values, or
  std::span<const float> floats;        // these, when `bytes` is empty
  // The channels' names ("R", "G", "B", "A", "Z"); empty: the format's default. A channel named
  // A is the alpha channel, one named Z the depth channel.
  std::vector<std::string> channel_names;
  bool srgb = false;  // the values are sRGB-encoded (says so in the file's colour space)
};

// Throws std::invalid_argument when the pixels do not fill width x height x channels, and
// std::runtime_error("PATH: cannot write: reason"), on one line, when the file cannot be
// written: the image is encoded in memory and written through OutputFile (output_file.hpp), so
// every failed write, flush or close is reported and no partial file is left behind.
void write_image_file(const std::string& path, const ImagePixels& image);

}  // namespace edgewise::tools
