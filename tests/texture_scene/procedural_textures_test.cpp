// The test textures: the checkerboard's pattern, the sinusoids' range and band limit (checked
// through their spectrum), and that both hold 8-bit values exactly.
#include <gtest/gtest.h>

#include <cmath>
#include <complex>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "texture_scene/procedural_textures.hpp"

namespace edgewise::texture_scene {
namespace {

TEST(Checkerboard, SquaresAlternateFromWhite) {
  const LinearImage image = checkerboard(12, 4);  // 3-texel squares
  ASSERT_EQ(image.width, 12);
  ASSERT_EQ(image.height, 12);
  for (std::int32_t b = 0; b < 12; ++b) {
    for (std::int32_t a = 0; a < 12; ++a) {
      const float expected = ((a / 3) + (b / 3)) % 2 == 0 ? 1.0f : 0.0f;
      const float* texel = image.texel(a, b);
      EXPECT_EQ(texel[0], expected) << a << "," << b;
      EXPECT_EQ(texel[1], expected);
      EXPECT_EQ(texel[2], expected);
      EXPECT_EQ(texel[3], 1.0f);
    }
  }
}

TEST(Checkerboard, UnevenSquaresDifferByOneTexel) {
  const LinearImage image = checkerboard(7, 3);  // squares of 3, 2 and 2 texels (floor(a 3 / 7))
  const float row0[7] = {1, 1, 1, 0, 0, 1, 1};
  for (std::int32_t a = 0; a < 7; ++a)
    EXPECT_EQ(image.texel(a, 0)[0], row0[a]) << a;
}

TEST(Checkerboard, RejectsBadArguments) {
  EXPECT_THROW(checkerboard(0, 1), std::invalid_argument);
  EXPECT_THROW(checkerboard(8, 0), std::invalid_argument);
  EXPECT_THROW(checkerboard(8, 9), std::invalid_argument);
  EXPECT_THROW(checkerboard((1 << 15) + 1, 2), std::invalid_argument);
}

TEST(ProceduralTextures, BytesHoldExactlyTheSameValues) {
  for (const LinearImage& image : {checkerboard(32, 8), sinusoids(32), sinusoids(50, 0.25)}) {
    const std::vector<std::uint8_t> bytes = to_rgba8(image);
    ASSERT_EQ(bytes.size(), image.rgba.size());
    for (std::size_t i = 0; i < bytes.size(); ++i)
      ASSERT_EQ(unorm8_value(bytes[i]), image.rgba[i]) << i;
  }
}

TEST(Sinusoids, StayInsideTheirRangeAndAreOpaque) {
  // 0.5 +- 0.45 (the amplitudes' sum), plus at most half an 8-bit step of rounding.
  const double margin = 0.5 / 255.0;
  const LinearImage image = sinusoids(64);
  for (std::int32_t b = 0; b < 64; ++b) {
    for (std::int32_t a = 0; a < 64; ++a) {
      const float* texel = image.texel(a, b);
      for (int c = 0; c < 3; ++c) {
        EXPECT_GE(texel[c], 0.05 - margin);
        EXPECT_LE(texel[c], 0.95 + margin);
      }
      EXPECT_EQ(texel[3], 1.0f);
    }
  }
}

// Band limit and seamless repeat at once: the discrete Fourier transform treats the texture as
// periodic, so a seam would spread energy over high frequencies. The unrounded texture has no
// energy above highest_frequency; the 8-bit rounding error e (|e| <= 1/510 per texel) has mean
// square at most 1/510^2, and by Parseval the energy above the limit, which is e's own there,
// has mean square at most that.
TEST(Sinusoids, NoEnergyAboveTheHighestFrequencyBeyondRounding) {
  constexpr int n = 64;
  const double highest = 1.0 / 8.0;
  const LinearImage image = sinusoids(n, highest);
  const double pi = std::numbers::pi;
  for (int c = 0; c < 3; ++c) {
    // Separable DFT: rows, then columns.
    std::vector<std::complex<double>> rows(n * n), spectrum(n * n);
    for (int b = 0; b < n; ++b) {
      for (int k = 0; k < n; ++k) {
        std::complex<double> sum = 0.0;
        for (int a = 0; a < n; ++a)
          sum += double(image.texel(a, b)[c]) * std::polar(1.0, -2.0 * pi * k * a / n);
        rows[b * n + k] = sum;
      }
    }
    for (int k = 0; k < n; ++k) {
      for (int l = 0; l < n; ++l) {
        std::complex<double> sum = 0.0;
        for (int b = 0; b < n; ++b)
          sum += rows[b * n + k] * std::polar(1.0, -2.0 * pi * l * b / n);
        spectrum[l * n + k] = sum;
      }
    }
    double high_energy = 0.0, total_energy = 0.0;
    for (int l = 0; l < n; ++l) {
      for (int k = 0; k < n; ++k) {
        const double fk = (k <= n / 2 ? k : k - n) / double(n);
        const double fl = (l <= n / 2 ? l : l - n) / double(n);
        const double energy = std::norm(spectrum[l * n + k]);
        total_energy += energy;
        // A hair above the limit, so that a wave exactly at it (rounded DFT) is not counted.
        if (std::hypot(fk, fl) > highest * (1.0 + 1e-9)) high_energy += energy;
      }
    }
    // Parseval: sum |F|^2 = n^2 sum |f|^2, so the mean square is energy / n^4.
    const double high_mean_square = high_energy / (double(n) * n * n * n);
    EXPECT_LE(high_mean_square, 1.0 / (510.0 * 510.0)) << "channel " << c;
    // And the waves are there: the variance (energy without the mean) is at least that of two
    // of the three waves of amplitude 0.15 (0.15^2 / 2 each; at this size one may truncate to
    // zero cycles, a constant), less the rounding noise.
    const double mean_square_of_mean = std::norm(spectrum[0]) / (double(n) * n * n * n);
    const double variance = total_energy / (double(n) * n * n * n) - mean_square_of_mean;
    EXPECT_GT(variance, 2.0 * 0.15 * 0.15 / 2.0 - 1e-3) << "channel " << c;
  }
}

TEST(Sinusoids, RejectsBadArguments) {
  EXPECT_THROW(sinusoids(0), std::invalid_argument);
  EXPECT_THROW(sinusoids(64, 0.0), std::invalid_argument);
  EXPECT_THROW(sinusoids(64, 0.3), std::invalid_argument);
  EXPECT_THROW(sinusoids(64, std::nan("")), std::invalid_argument);
}

TEST(LinearImage, ToRgba8RejectsValuesThatAreNotEightBit) {
  LinearImage image = LinearImage::filled(2, 1, 0.0f);
  EXPECT_NO_THROW(to_rgba8(image));
  for (float bad : {0.5f, -0.0001f, 1.5f, std::nanf("")}) {
    image.rgba[5] = bad;
    EXPECT_THROW(to_rgba8(image), std::invalid_argument) << bad;
  }
  image.rgba.pop_back();
  image.rgba[5] = 0.0f;
  EXPECT_THROW(to_rgba8(image), std::invalid_argument);
}

TEST(LinearImage, FromSamplesIsRowMajor) {
  const std::vector<Vec4> samples = {{1, 2, 3, 4},     {5, 6, 7, 8},     {9, 10, 11, 12},
                                     {13, 14, 15, 16}, {17, 18, 19, 20}, {21, 22, 23, 24}};
  const LinearImage image = image_from_samples(3, 2, samples);
  EXPECT_EQ(image.texel(0, 1)[0], 13.0f);
  EXPECT_EQ(image.texel(2, 0)[3], 12.0f);
  EXPECT_THROW(image_from_samples(2, 2, samples), std::invalid_argument);
  EXPECT_THROW(LinearImage::filled(-1, 2, 0.0f), std::invalid_argument);
}

}  // namespace
}  // namespace edgewise::texture_scene
