#include "render/image_writer.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cctype>
#include <cstdint>
#include <memory>
#include <stdexcept>
#include <vector>

#include "render/usage_error.hpp"

namespace edgewise::render_tool {
namespace {

// Where the extension starts in `path` (at its last '.' after the last '/'); path.size() if none.
std::size_t extension_start(std::string_view path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) {
    return path.size();
  }
  return dot;
}

std::string lower_case_extension(std::string_view path) {
  std::string extension(path.substr(extension_start(path)));
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

// The interleaved pixels and the description of one of the two formats.
struct EncodedImage {
  OIIO::ImageSpec spec;
  OIIO::TypeDesc pixel_type;
  std::vector<std::uint8_t> rgba8;
  std::vector<float> rgbaz;
  const void* pixels() const {
    return rgba8.empty() ? static_cast<const void*>(rgbaz.data()) : rgba8.data();
  }
};

EncodedImage encode_png(const Framebuffer& framebuffer) {
  EncodedImage image;
  image.pixel_type = OIIO::TypeDesc::UINT8;
  image.spec = OIIO::ImageSpec(framebuffer.width(), framebuffer.height(), 4, image.pixel_type);
  image.rgba8.resize(static_cast<std::size_t>(framebuffer.width()) * framebuffer.height() * 4);
  framebuffer.read_rgba8(image.rgba8);
  return image;
}

EncodedImage encode_exr(const Framebuffer& framebuffer) {
  const std::size_t pixels = static_cast<std::size_t>(framebuffer.width()) * framebuffer.height();
  std::vector<std::uint8_t> rgba(pixels * 4);
  std::vector<float> depth(pixels);
  framebuffer.read_rgba8(rgba);
  framebuffer.read_depth(depth);

  EncodedImage image;
  image.pixel_type = OIIO::TypeDesc::FLOAT;
  image.spec = OIIO::ImageSpec(framebuffer.width(), framebuffer.height(), 5, image.pixel_type);
  image.spec.channelnames = {"R", "G", "B", "A", "Z"};
  image.spec.alpha_channel = 3;
  image.spec.z_channel = 4;
  image.rgbaz.resize(pixels * 5);
  for (std::size_t i = 0; i < pixels; ++i) {
    for (std::size_t c = 0; c < 4; ++c)
      image.rgbaz[i * 5 + c] = static_cast<float>(rgba[i * 4 + c]) / 255.0f;
    image.rgbaz[i * 5 + 4] = depth[i];
  }
  return image;
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
  throw UsageError(std::string(path) + ": unsupported image format; the file name must end in " +
                   ".png or .exr");
}

void write_image(const std::string& path, const Framebuffer& framebuffer) {
  const EncodedImage image = image_format_for(path) == ImageFormat::png ? encode_png(framebuffer)
                                                                        : encode_exr(framebuffer);
  const auto fail = [&path](const std::string& reason) {
    // OpenImageIO's messages may span lines; the tool reports one.
    std::string line = reason;
    std::replace(line.begin(), line.end(), '\n', ' ');
    throw std::runtime_error(path + ": cannot write: " + line);
  };
  std::unique_ptr<OIIO::ImageOutput> out = OIIO::ImageOutput::create(path);
  if (!out) fail(OIIO::geterror());
  if (!out->open(path, image.spec)) fail(out->geterror());
  if (!out->write_image(image.pixel_type, image.pixels())) fail(out->geterror());
  if (!out->close()) fail(out->geterror());
}

}  // namespace edgewise::render_tool
