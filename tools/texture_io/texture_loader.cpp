#include "texture_io/texture_loader.hpp"

#include <OpenImageIO/imageio.h>
#include <sys/stat.h>

#include <algorithm>
#include <cerrno>
#include <cstring>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

namespace edgewise::texture_io {
namespace {

// Texture::from_rgba8 / from_rgba32f refuse larger sides (texture.hpp).
constexpr int kMaxTextureSide = 1 << 15;

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  // OpenImageIO's messages may span lines; the tool reports one.
  std::string line = reason;
  std::replace(line.begin(), line.end(), '\n', ' ');
  throw std::runtime_error(path + ": " + line);
}

// OpenImageIO's own message for a missing file names no cause; the system's does.
void require_readable_file(const std::string& path) {
  struct stat status {};
  const int error = ::stat(path.c_str(), &status) != 0 ? errno
                    : S_ISDIR(status.st_mode)          ? EISDIR
                                                       : 0;
  if (error != 0) fail(path, std::string("cannot open: ") + std::strerror(error));
}

// Channel c of the RGBA texel made from one pixel's `channels` values, in the file's type T;
// `one` is T's value for an opaque alpha.
template <class T>
T expanded_channel(const T* pixel, int channels, int c, T one) {
  if (channels >= 3) return c < 3 || channels >= 4 ? pixel[c] : one;
  // Grey, or grey and alpha.
  if (c < 3) return pixel[0];
  return channels == 2 ? pixel[1] : one;
}

template <class T>
std::vector<T> expand_to_rgba(std::span<const T> pixels, int channels, T one) {
  const std::size_t count = pixels.size() / static_cast<std::size_t>(channels);
  std::vector<T> rgba(4 * count);
  for (std::size_t i = 0; i < count; ++i) {
    const T* pixel = pixels.data() + i * static_cast<std::size_t>(channels);
    for (int c = 0; c < 4; ++c)
      rgba[4 * i + static_cast<std::size_t>(c)] = expanded_channel(pixel, channels, c, one);
  }
  return rgba;
}

template <class T>
std::vector<T> read_pixels(OIIO::ImageInput& in, const std::string& path, OIIO::TypeDesc type) {
  const OIIO::ImageSpec& spec = in.spec();
  std::vector<T> pixels(static_cast<std::size_t>(spec.width) *
                        static_cast<std::size_t>(spec.height) *
                        static_cast<std::size_t>(spec.nchannels));
  if (!in.read_image(0, 0, 0, spec.nchannels, type, pixels.data())) {
    fail(path, "cannot read image: " + in.geterror());
  }
  return pixels;
}

}  // namespace

LoadedTexture load_texture(const std::string& path, bool srgb, const TextureBuild& build) {
  require_readable_file(path);
  // Keep texels as stored: OpenImageIO would otherwise premultiply an unassociated alpha.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
  if (!in) fail(path, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec spec = in->spec();
  if (spec.depth > 1) fail(path, "a volume image (depth " + std::to_string(spec.depth) + ")");
  if (spec.width < 1 || spec.height < 1 || spec.width > kMaxTextureSide ||
      spec.height > kMaxTextureSide) {
    fail(path, std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                   " is not a texture size (1.." + std::to_string(kMaxTextureSide) +
                   " texels a side)");
  }
  if (spec.nchannels < 1) fail(path, "no channels");

  LoadedTexture loaded{Texture(), spec.nchannels, spec.format.c_str()};
  if (spec.format == OIIO::TypeDesc::UINT8) {
    const std::vector<std::uint8_t> pixels = read_pixels<std::uint8_t>(*in, path, spec.format);
    const std::vector<std::uint8_t> rgba =
        expand_to_rgba<std::uint8_t>(pixels, spec.nchannels, 255);
    loaded.texture = Texture::from_rgba8(spec.width, spec.height, rgba,
                                         srgb ? ColorEncoding::srgb : ColorEncoding::linear, build);
  } else {
    const std::vector<float> pixels = read_pixels<float>(*in, path, OIIO::TypeDesc::FLOAT);
    std::vector<float> rgba = expand_to_rgba<float>(pixels, spec.nchannels, 1.0f);
    if (srgb) {
      for (std::size_t i = 0; i < rgba.size(); ++i) {
        if (i % 4 != 3) rgba[i] = static_cast<float>(srgb_to_linear(rgba[i]));
      }
    }
    loaded.texture = Texture::from_rgba32f(spec.width, spec.height, rgba, build);
  }
  return loaded;
}

}  // namespace edgewise::texture_io
