#include "texture_scene/procedural_textures.hpp"

#include <array>
#include <cmath>
#include <numbers>
#include <stdexcept>
#include <string>

namespace edgewise::texture_scene {
namespace {

constexpr std::int32_t kMaxSize = 1 << 15;  // Texture's own limit

void check_size(std::int32_t size, const char* what) {
  if (size < 1 || size > kMaxSize)
    throw std::invalid_argument(std::string(what) + ": size outside [1, 32768]");
}

float quantized(double value) {
  return unorm8_value(static_cast<std::uint8_t>(std::lround(value * 255.0)));
}

struct Sinusoid {
  double frequency_fraction;  // of highest_frequency
  double direction_degrees;   // of the wave vector, from the s axis toward t
  double amplitude;
  double phase;  // radians
};

// Three per channel, directions spread so that no channel is one-dimensional.
constexpr std::array<std::array<Sinusoid, 3>, 3> kChannels{{
    {{{1.00, 10.0, 0.15, 0.0}, {0.35, 75.0, 0.15, 1.0}, {0.10, 140.0, 0.15, 2.0}}},
    {{{0.80, 100.0, 0.15, 0.5}, {0.45, 35.0, 0.15, 2.5}, {0.15, 0.0, 0.15, 4.0}}},
    {{{0.60, 55.0, 0.15, 1.5}, {0.90, 160.0, 0.15, 3.0}, {0.25, 90.0, 0.15, 5.0}}},
}};

}  // namespace

LinearImage checkerboard(std::int32_t size, std::int32_t squares) {
  check_size(size, "checkerboard");
  if (squares < 1 || squares > size)
    throw std::invalid_argument("checkerboard: squares outside [1, size]");
  LinearImage image = LinearImage::filled(size, size, 1.0f);
  for (std::int32_t b = 0; b < size; ++b) {
    const std::int64_t row_square = std::int64_t{b} * squares / size;
    for (std::int32_t a = 0; a < size; ++a) {
      const std::int64_t column_square = std::int64_t{a} * squares / size;
      const float value = (row_square + column_square) % 2 == 0 ? 1.0f : 0.0f;
      float* texel = image.texel(a, b);
      texel[0] = texel[1] = texel[2] = value;
    }
  }
  return image;
}

LinearImage sinusoids(std::int32_t size, double highest_frequency) {
  check_size(size, "sinusoids");
  if (!(highest_frequency > 0.0 && highest_frequency <= 0.25))
    throw std::invalid_argument("sinusoids: highest_frequency outside (0, 1/4]");
  // Integer cycles over the texture, truncated toward zero so that no frequency exceeds its
  // target (the target is at most highest_frequency).
  struct Wave {
    double kx, ky, amplitude, phase;
  };
  std::array<std::array<Wave, 3>, 3> waves{};
  for (std::size_t c = 0; c < 3; ++c) {
    for (std::size_t k = 0; k < 3; ++k) {
      const Sinusoid& sinusoid = kChannels[c][k];
      const double cycles = sinusoid.frequency_fraction * highest_frequency * size;
      const double angle = sinusoid.direction_degrees * std::numbers::pi / 180.0;
      waves[c][k] = {std::trunc(cycles * std::cos(angle)), std::trunc(cycles * std::sin(angle)),
                     sinusoid.amplitude, sinusoid.phase};
    }
  }
  LinearImage image = LinearImage::filled(size, size, 1.0f);
  for (std::int32_t b = 0; b < size; ++b) {
    for (std::int32_t a = 0; a < size; ++a) {
      float* texel = image.texel(a, b);
      for (std::size_t c = 0; c < 3; ++c) {
        double value = 0.5;
        for (const Wave& wave : waves[c]) {
          // kx a + ky b is an integer: reduce it mod size first, so the angle stays small and
          // exact, and texels a and a + size get bit-identical values.
          const double cycles = std::fmod(wave.kx * a + wave.ky * b, double(size));
          value += wave.amplitude * std::sin(2.0 * std::numbers::pi * cycles / size + wave.phase);
        }
        texel[c] = quantized(value);
      }
    }
  }
  return image;
}

}  // namespace edgewise::texture_scene
