#include "texture_io/texture_loader.hpp"

#include <OpenImageIO/imageio.h>

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <vector>

#include "common/input_file.hpp"

namespace edgewise::texture_io {
namespace {

// Texture::from_rgba8 / from_rgba32f refuse larger sides (texture.hpp).
constexpr int kMaxTextureSide = 1 << 15;
// Rows decoded at a time (rounded up to whole tiles): the band's buffer stays small beside the
// texture.
constexpr int kBandRows = 64;

[[noreturn]] void fail(const std::string& path, const std::string& reason) {
  // OpenImageIO's messages may span lines; the tool reports one.
  std::string line = reason;
  std::replace(line.begin(), line.end(), '\n', ' ');
  throw std::runtime_error(path + ": " + line);
}

std::string mebibytes(std::uint64_t bytes) {
  return std::to_string((bytes + (std::uint64_t{1} << 20) - 1) >> 20) + " MiB";
}

// Channel c of the RGBA texel made from one pixel's `channels` values (at most four read), in
// the file's type T; `one` is T's value for an opaque alpha.
template <class T>
T expanded_channel(const T* pixel, int channels, int c, T one) {
  if (channels >= 3) return c < 3 || channels >= 4 ? pixel[c] : one;
  // Grey, or grey and alpha.
  if (c < 3) return pixel[0];
  return channels == 2 ? pixel[1] : one;
}

// Level 0 as RGBA values of type T, read band by band: the file's first min(channels, 4)
// channels converted to T, then expanded.
template <class T>
std::vector<T> read_rgba(OIIO::ImageInput& in, const std::string& path, OIIO::TypeDesc type,
                         T one) {
  const OIIO::ImageSpec& spec = in.spec();
  const int channels = std::min(spec.nchannels, 4);
  const auto width = static_cast<std::size_t>(spec.width);
  const int band_rows = spec.tile_height > 0 ? (kBandRows + spec.tile_height - 1) /
                                                   spec.tile_height * spec.tile_height
                                             : kBandRows;
  std::vector<T> rgba(4 * width * static_cast<std::size_t>(spec.height));
  std::vector<T> band(width * static_cast<std::size_t>(band_rows) *
                      static_cast<std::size_t>(channels));
  for (int y0 = 0; y0 < spec.height; y0 += band_rows) {
    const int y1 = std::min(spec.height, y0 + band_rows);
    const bool read =
        spec.tile_width > 0
            ? in.read_tiles(0, 0, spec.x, spec.x + spec.width, spec.y + y0, spec.y + y1, spec.z,
                            spec.z + 1, 0, channels, type, band.data())
            : in.read_scanlines(0, 0, spec.y + y0, spec.y + y1, spec.z, 0, channels, type,
                                band.data());
    if (!read) fail(path, "cannot read image: " + in.geterror());
    const std::size_t texels = width * static_cast<std::size_t>(y1 - y0);
    T* out = rgba.data() + 4 * width * static_cast<std::size_t>(y0);
    for (std::size_t i = 0; i < texels; ++i) {
      const T* pixel = band.data() + i * static_cast<std::size_t>(channels);
      for (int c = 0; c < 4; ++c)
        out[4 * i + static_cast<std::size_t>(c)] = expanded_channel(pixel, channels, c, one);
    }
  }
  return rgba;
}

// Refuses, from the header alone, an image that is not a texture of a size this load allows.
void check_size(const std::string& path, const OIIO::ImageSpec& spec, const LoadLimits& limits) {
  if (spec.depth > 1) fail(path, "a volume image (depth " + std::to_string(spec.depth) + ")");
  if (spec.width < 1 || spec.height < 1 || spec.width > kMaxTextureSide ||
      spec.height > kMaxTextureSide) {
    fail(path, std::to_string(spec.width) + "x" + std::to_string(spec.height) +
                   " is not a texture size (1.." + std::to_string(kMaxTextureSide) +
                   " texels a side)");
  }
  if (spec.nchannels < 1) fail(path, "no channels");
  const std::uint64_t texel_bytes = spec.format == OIIO::TypeDesc::UINT8 ? 4 : 16;
  const std::uint64_t bytes = static_cast<std::uint64_t>(spec.width) *
                              static_cast<std::uint64_t>(spec.height) * texel_bytes;
  if (bytes > limits.max_texture_bytes) {
    fail(path, std::to_string(spec.width) + "x" + std::to_string(spec.height) + " " +
                   spec.format.c_str() + " texels need " + mebibytes(bytes) +
                   " as a texture, over the limit of " + mebibytes(limits.max_texture_bytes) +
                   " (--max-texture-mb raises it)");
  }
}

}  // namespace

LoadedTexture load_texture(const std::string& path, bool srgb, const TextureBuild& build,
                           const LoadLimits& limits) {
  // Devices and pipes could feed OpenImageIO's format probes forever.
  tools::require_regular_file(path);
  // Keep texels as stored: OpenImageIO would otherwise premultiply an unassociated alpha.
  OIIO::ImageSpec config;
  config.attribute("oiio:UnassociatedAlpha", 1);
  std::unique_ptr<OIIO::ImageInput> in = OIIO::ImageInput::open(path, &config);
  if (!in) fail(path, "cannot read image: " + OIIO::geterror());
  const OIIO::ImageSpec spec = in->spec();
  check_size(path, spec, limits);

  LoadedTexture loaded{Texture(), spec.nchannels, spec.format.c_str()};
  if (spec.format == OIIO::TypeDesc::UINT8) {
    const std::vector<std::uint8_t> rgba =
        read_rgba<std::uint8_t>(*in, path, spec.format, std::uint8_t{255});
    loaded.texture = Texture::from_rgba8(spec.width, spec.height, rgba,
                                         srgb ? ColorEncoding::srgb : ColorEncoding::linear, build);
  } else {
    std::vector<float> rgba = read_rgba<float>(*in, path, OIIO::TypeDesc::FLOAT, 1.0f);
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
