#include "texture_quality/result_images.hpp"

#include <cmath>
#include <cstdint>
#include <stdexcept>
#include <vector>

#include "common/image_file.hpp"
#include "edgewise/texture.hpp"

namespace edgewise::texture_quality {
namespace {

std::uint8_t srgb_byte(float linear) {
  // NaN shows as black; std::clamp would pass it through.
  const double clamped = linear > 0.0f ? (linear < 1.0f ? double(linear) : 1.0) : 0.0;
  return static_cast<std::uint8_t>(std::lround(linear_to_srgb(clamped) * 255.0));
}

}  // namespace

void write_srgb_png(const std::filesystem::path& path, const texture_scene::LinearImage& image) {
  const std::size_t pixels = static_cast<std::size_t>(image.width) * image.height;
  if (image.width < 1 || image.height < 1 || image.rgba.size() != 4 * pixels) {
    throw std::invalid_argument("write_srgb_png: empty or inconsistent image");
  }
  std::vector<std::uint8_t> rgb(3 * pixels);
  for (std::size_t i = 0; i < pixels; ++i) {
    for (int c = 0; c < 3; ++c)
      rgb[3 * i + c] = srgb_byte(image.rgba[4 * i + c]);
  }
  tools::ImagePixels encoded;
  encoded.width = image.width;
  encoded.height = image.height;
  encoded.channels = 3;
  encoded.bytes = rgb;
  encoded.srgb = true;
  tools::write_image_file(path.string(), encoded);
}

texture_scene::LinearImage error_image(const texture_scene::LinearImage& result,
                                       const texture_scene::LinearImage& truth) {
  if (result.width != truth.width || result.height != truth.height ||
      result.rgba.size() != truth.rgba.size()) {
    throw std::invalid_argument("error_image: the images' sizes differ");
  }
  texture_scene::LinearImage error =
      texture_scene::LinearImage::filled(result.width, result.height, 1.0f);
  for (std::size_t i = 0; i < error.rgba.size(); i += 4) {
    for (std::size_t c = 0; c < 3; ++c) {
      error.rgba[i + c] = std::abs(result.rgba[i + c] - truth.rgba[i + c]) * kErrorImageGain;
    }
  }
  return error;
}

}  // namespace edgewise::texture_quality
