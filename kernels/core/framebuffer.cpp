// The tiled render target.
#include "edgewise/framebuffer.hpp"

#include <algorithm>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <string>

#include "edgewise/coverage.hpp"
#include "edgewise/multisample.hpp"

namespace edgewise {
namespace {

std::uint32_t to_byte(float v) {
  // NaN compares false both ways and ends at 0.
  const float clamped = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;
  return static_cast<std::uint32_t>(std::lrint(clamped * 255.0f));
}

}  // namespace

std::uint32_t pack_rgba8(const Vec4& color) {
  return to_byte(color.x) | to_byte(color.y) << 8 | to_byte(color.z) << 16 | to_byte(color.w) << 24;
}

Framebuffer::Framebuffer(std::int32_t width, std::int32_t height, int samples)
    : width_(width), height_(height), samples_(samples) {
  if (width < 0 || width > kMaxTargetSize || height < 0 || height > kMaxTargetSize) {
    throw std::invalid_argument("Framebuffer: size " + std::to_string(width) + "x" +
                                std::to_string(height) + " is outside 0.." +
                                std::to_string(kMaxTargetSize) + " pixels per side");
  }
  if (!is_standard_sample_count(samples)) {
    throw std::invalid_argument("Framebuffer: " + std::to_string(samples) +
                                " samples per pixel has no standard pattern (1, 2, 4, 8 or 16)");
  }
  tiles_x_ = (width + 7) / 8;
  tiles_y_ = (height + 7) / 8;
  const std::size_t tiles = static_cast<std::size_t>(tiles_x_) * static_cast<std::size_t>(tiles_y_);
  const std::size_t values = tiles * 64 * static_cast<std::size_t>(samples);
  color_.assign(values, 0);
  depth_.assign(values, 1.0f);
  tile_max_depth_.assign(tiles, 1.0f);
}

void Framebuffer::clear(const Vec4& color, float depth) {
  std::fill(color_.begin(), color_.end(), pack_rgba8(color));
  std::fill(depth_.begin(), depth_.end(), depth);
  // NaN depth fails every comparison; +inf as its bound rejects nothing.
  const float bound = depth == depth ? depth : std::numeric_limits<float>::infinity();
  std::fill(tile_max_depth_.begin(), tile_max_depth_.end(), bound);
  depth_bounds_valid_ = true;
}

void Framebuffer::check_sample(int sample, const char* what) const {
  if (sample < 0 || sample >= samples_) {
    throw std::invalid_argument(std::string(what) + ": sample " + std::to_string(sample) +
                                " of a target with " + std::to_string(samples_) + " per pixel");
  }
}

void Framebuffer::read_rgba8(std::span<std::uint8_t> rgba, int sample) const {
  check_sample(sample, "read_rgba8");
  const std::size_t pixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  if (rgba.size() != pixels * 4) {
    throw std::invalid_argument("read_rgba8: the span holds " + std::to_string(rgba.size()) +
                                " bytes, not " + std::to_string(pixels * 4));
  }
  std::size_t out = 0;
  for (std::int32_t y = 0; y < height_; ++y) {
    for (std::int32_t x = 0; x < width_; ++x) {
      const std::uint32_t c = color(x, y, sample);
      for (int k = 0; k < 4; ++k)
        rgba[out++] = static_cast<std::uint8_t>(c >> (8 * k));
    }
  }
}

void Framebuffer::read_depth(std::span<float> depth_out, int sample) const {
  check_sample(sample, "read_depth");
  const std::size_t pixels = static_cast<std::size_t>(width_) * static_cast<std::size_t>(height_);
  if (depth_out.size() != pixels) {
    throw std::invalid_argument("read_depth: the span holds " + std::to_string(depth_out.size()) +
                                " values, not " + std::to_string(pixels));
  }
  std::size_t out = 0;
  for (std::int32_t y = 0; y < height_; ++y) {
    for (std::int32_t x = 0; x < width_; ++x)
      depth_out[out++] = depth(x, y, sample);
  }
}

}  // namespace edgewise
