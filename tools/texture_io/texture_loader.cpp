#include "texture_io/texture_loader.hpp"

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <memory>
#include <span>
#include <stdexcept>
#include <type_traits>
#include <vector>

#include "common/input_file.hpp"
#include "image_module/image_module.hpp"

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

// Level 0 as RGBA values of type T (8-bit or float), read band by band: the file's first
// min(channels, 4) channels converted to T, then expanded.
template <class T>
std::vector<T> read_rgba(tools::ImageReader& in, const std::string& path, T one) {
  const tools::ImageHeader& header = in.header();
  const int channels = std::min(header.channels, 4);
  const auto width = static_cast<std::size_t>(header.width);
  const int band_rows = header.tile_height > 0 ? (kBandRows + header.tile_height - 1) /
                                                     header.tile_height * header.tile_height
                                               : kBandRows;
  std::vector<T> rgba(4 * width * static_cast<std::size_t>(header.height));
  std::vector<T> band(width * static_cast<std::size_t>(band_rows) *
                      static_cast<std::size_t>(channels));
  for (int y0 = 0; y0 < header.height; y0 += band_rows) {
    const int y1 = std::min(header.height, y0 + band_rows);
    try {
      in.read_rows(y0, y1, channels, std::is_same_v<T, std::uint8_t>, band.data());
    } catch (const std::runtime_error& error) {
      fail(path, error.what());
    }
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
void check_size(const std::string& path, const tools::ImageHeader& header,
                const LoadLimits& limits) {
  if (header.depth > 1) fail(path, "a volume image (depth " + std::to_string(header.depth) + ")");
  if (header.width < 1 || header.height < 1 || header.width > kMaxTextureSide ||
      header.height > kMaxTextureSide) {
    fail(path, std::to_string(header.width) + "x" + std::to_string(header.height) +
                   " is not a texture size (1.." + std::to_string(kMaxTextureSide) +
                   " texels a side)");
  }
  if (header.channels < 1) fail(path, "no channels");
  const std::uint64_t texel_bytes = header.uint8 ? 4 : 16;
  const std::uint64_t bytes = static_cast<std::uint64_t>(header.width) *
                              static_cast<std::uint64_t>(header.height) * texel_bytes;
  if (bytes > limits.max_texture_bytes) {
    fail(path, std::to_string(header.width) + "x" + std::to_string(header.height) + " " +
                   header.pixel_type + " texels need " + mebibytes(bytes) +
                   " as a texture, over the limit of " + mebibytes(limits.max_texture_bytes) +
                   " (--max-texture-mb raises it)");
  }
}

}  // namespace

LoadedTexture load_texture(const std::string& path, bool srgb, const TextureBuild& build,
                           const LoadLimits& limits) {
  // Devices and pipes could feed OpenImageIO's format probes forever.
  tools::require_regular_file(path);
  std::unique_ptr<tools::ImageReader> in;
  try {
    in = tools::image_module().open(path);
  } catch (const std::runtime_error& error) {
    fail(path, error.what());
  }
  const tools::ImageHeader header = in->header();
  check_size(path, header, limits);

  LoadedTexture loaded{Texture(), header.channels, header.pixel_type};
  if (header.uint8) {
    const std::vector<std::uint8_t> rgba = read_rgba<std::uint8_t>(*in, path, std::uint8_t{255});
    loaded.texture = Texture::from_rgba8(header.width, header.height, rgba,
                                         srgb ? ColorEncoding::srgb : ColorEncoding::linear, build);
  } else {
    std::vector<float> rgba = read_rgba<float>(*in, path, 1.0f);
    if (srgb) {
      for (std::size_t i = 0; i < rgba.size(); ++i) {
        if (i % 4 != 3) rgba[i] = static_cast<float>(srgb_to_linear(rgba[i]));
      }
    }
    loaded.texture = Texture::from_rgba32f(header.width, header.height, rgba, build);
  }
  return loaded;
}

}  // namespace edgewise::texture_io
