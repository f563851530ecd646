#include "texture_scene/linear_image.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace edgewise::texture_scene {
namespace {

std::size_t value_count(std::int32_t width, std::int32_t height) {
  if (width < 0 || height < 0) throw std::invalid_argument("LinearImage: negative size");
  return 4 * static_cast<std::size_t>(width) * static_cast<std::size_t>(height);
}

}  // namespace

LinearImage LinearImage::filled(std::int32_t width, std::int32_t height, float value) {
  LinearImage image;
  image.rgba.assign(value_count(width, height), value);
  image.width = width;
  image.height = height;
  return image;
}

float round_to_float(double value) {
  if (std::abs(value) > std::numeric_limits<float>::max())
    return value > 0.0 ? std::numeric_limits<float>::infinity()
                       : -std::numeric_limits<float>::infinity();
  return static_cast<float>(value);
}

float unorm8_value(std::uint8_t q) {
  return static_cast<float>(q) / 255.0f;
}

std::vector<std::uint8_t> to_rgba8(const LinearImage& image) {
  if (image.rgba.size() != value_count(image.width, image.height))
    throw std::invalid_argument("to_rgba8: rgba size does not match width x height");
  std::vector<std::uint8_t> bytes(image.rgba.size());
  for (std::size_t i = 0; i < bytes.size(); ++i) {
    const float value = image.rgba[i];
    // Comparisons are false for NaN, so NaN is rejected here too.
    if (!(value >= 0.0f && value <= 1.0f))
      throw std::invalid_argument("to_rgba8: value outside [0, 1]");
    const auto q = static_cast<std::uint8_t>(std::lround(value * 255.0f));
    if (unorm8_value(q) != value)
      throw std::invalid_argument("to_rgba8: value is not an 8-bit value q / 255");
    bytes[i] = q;
  }
  return bytes;
}

LinearImage image_from_samples(std::int32_t width, std::int32_t height,
                               std::span<const Vec4> samples) {
  LinearImage image;
  image.rgba.resize(value_count(width, height));
  if (samples.size() * 4 != image.rgba.size())
    throw std::invalid_argument("image_from_samples: sample count is not width x height");
  image.width = width;
  image.height = height;
  for (std::size_t i = 0; i < samples.size(); ++i) {
    image.rgba[4 * i + 0] = samples[i].x;
    image.rgba[4 * i + 1] = samples[i].y;
    image.rgba[4 * i + 2] = samples[i].z;
    image.rgba[4 * i + 3] = samples[i].w;
  }
  return image;
}

}  // namespace edgewise::texture_scene
