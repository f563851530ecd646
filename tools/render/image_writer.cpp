#include "render/image_writer.hpp"

#include <cstdint>
#include <vector>

#include "common/file_extension.hpp"
#include "common/image_file.hpp"
#include "common/usage_error.hpp"

namespace edgewise::render_tool {
namespace {

using tools::extension_start;
using tools::lower_case_extension;

void write_png(const std::string& path, const Framebuffer& framebuffer) {
  std::vector<std::uint8_t> rgba(static_cast<std::size_t>(framebuffer.width()) *
                                 framebuffer.height() * 4);
  framebuffer.read_rgba8(rgba);
  tools::ImagePixels image;
  image.width = framebuffer.width();
  image.height = framebuffer.height();
  image.channels = 4;
  image.bytes = rgba;
  tools::write_image_file(path, image);
}

void write_exr(const std::string& path, const Framebuffer& framebuffer) {
  const std::size_t pixels = static_cast<std::size_t>(framebuffer.width()) * framebuffer.height();
  std::vector<std::uint8_t> rgba(pixels * 4);
  std::vector<float> depth(pixels);
  framebuffer.read_rgba8(rgba);
  framebuffer.read_depth(depth);
  std::vector<float> rgbaz(pixels * 5);
  for (std::size_t i = 0; i < pixels; ++i) {
    for (std::size_t c = 0; c < 4; ++c)
      rgbaz[i * 5 + c] = static_cast<float>(rgba[i * 4 + c]) / 255.0f;
    rgbaz[i * 5 + 4] = depth[i];
  }
  tools::ImagePixels image;
  image.width = framebuffer.width();
  image.height = framebuffer.height();
  image.channels = 5;
  image.floats = rgbaz;
  image.channel_names = {"R", "G", "B", "A", "Z"};
  tools::write_image_file(path, image);
}

}  // namespace

std::string path_with_suffix(std::string_view path, std::string_view suffix) {
  const std::size_t dot = extension_start(path);
  return std::string(path.substr(0, dot)) + std::string(suffix) + std::string(path.substr(dot));
}

ImageFormat image_format_for(std::string_view path) {
  const std::string extension = lower_case_extension(path);
  if (extension == ".png") return ImageFormat::png;
  if (extension == ".exr") return ImageFormat::exr;
  throw tools::UsageError(std::string(path) +
                          ": unsupported image format; the file name must end in .png or .exr");
}

void write_image(const std::string& path, const Framebuffer& framebuffer) {
  if (image_format_for(path) == ImageFormat::png) {
    write_png(path, framebuffer);
  } else {
    write_exr(path, framebuffer);
  }
}

void write_rgba_image(const std::string& path, std::int32_t width, std::int32_t height,
                      std::span<const std::uint8_t> rgba) {
  tools::ImagePixels image;
  image.width = width;
  image.height = height;
  image.channels = 4;
  if (image_format_for(path) == ImageFormat::png) {
    image.bytes = rgba;
    tools::write_image_file(path, image);
    return;
  }
  std::vector<float> floats(rgba.size());
  for (std::size_t i = 0; i < rgba.size(); ++i)
    floats[i] = static_cast<float>(rgba[i]) / 255.0f;
  image.floats = floats;
  image.channel_names = {"R", "G", "B", "A"};
  tools::write_image_file(path, image);
}

}  // namespace edgewise::render_tool
