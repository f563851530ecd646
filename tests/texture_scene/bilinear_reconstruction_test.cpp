// The ground truth's reference signal: bilinear level 0 with the sampler's wrap rules.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>

#include "random.hpp"
#include "texture_scene/bilinear_reconstruction.hpp"
#include "texture_scene/wrap_modes.hpp"

namespace edgewise::texture_scene {
namespace {

using edgewise::test::Random;

TEST(WrapTexelIndex, HandCases) {
  // n = 3: ... -4 -3 -2 -1 | 0 1 2 | 3 4 5 6 ...
  const std::int64_t indices[] = {-7, -4, -3, -2, -1, 0, 1, 2, 3, 4, 5, 6, 7};
  const std::int64_t repeat[] = {2, 2, 0, 1, 2, 0, 1, 2, 0, 1, 2, 0, 1};
  const std::int64_t clamp[] = {0, 0, 0, 0, 0, 0, 1, 2, 2, 2, 2, 2, 2};
  const std::int64_t mirror[] = {0, 2, 2, 1, 0, 0, 1, 2, 2, 1, 0, 0, 1};
  for (std::size_t k = 0; k < std::size(indices); ++k) {
    EXPECT_EQ(wrap_texel_index(indices[k], 3, WrapMode::repeat), repeat[k]) << indices[k];
    EXPECT_EQ(wrap_texel_index(indices[k], 3, WrapMode::clamp_to_edge), clamp[k]) << indices[k];
    EXPECT_EQ(wrap_texel_index(indices[k], 3, WrapMode::mirror), mirror[k]) << indices[k];
  }
  for (WrapMode mode : kWrapModes)
    EXPECT_EQ(wrap_texel_index(-5, 1, mode), 0);
}

LinearImage random_image(Random& random, std::int32_t width, std::int32_t height) {
  LinearImage image = LinearImage::filled(width, height, 0.0f);
  for (float& value : image.rgba)
    value = static_cast<float>(random.uniform());
  return image;
}

TEST(BilinearReconstruction, TexelCentresGiveTheTexels) {
  Random random(0xb111);
  const LinearImage image = random_image(random, 5, 3);
  for (WrapMode mode : kWrapModes) {
    const BilinearReconstruction texture(image, mode, mode);
    for (std::int32_t b = 0; b < 3; ++b) {
      for (std::int32_t a = 0; a < 5; ++a) {
        double out[4];
        texture.evaluate((a + 0.5) / 5.0, (b + 0.5) / 3.0, out);
        for (int c = 0; c < 4; ++c)
          EXPECT_EQ(out[c], image.texel(a, b)[c]);
      }
    }
  }
}

TEST(BilinearReconstruction, BlendsWithTheSpecWeights) {
  Random random(0xb112);
  const LinearImage image = random_image(random, 6, 4);
  for (WrapMode wrap_s : kWrapModes) {
    for (WrapMode wrap_t : kWrapModes) {
      const BilinearReconstruction texture(image, wrap_s, wrap_t);
      for (int k = 0; k < 200; ++k) {
        const double s = random.uniform(-2.5, 3.5), t = random.uniform(-2.5, 3.5);
        // texture_spec.md's formulation: four weights.
        const double u = s * 6 - 0.5, v = t * 4 - 0.5;
        const double i0 = std::floor(u), j0 = std::floor(v);
        const double fu = u - i0, fv = v - j0;
        const auto texel = [&](double i, double j) {
          return image.texel(
              static_cast<std::int32_t>(wrap_texel_index(std::int64_t(i), 6, wrap_s)),
              static_cast<std::int32_t>(wrap_texel_index(std::int64_t(j), 4, wrap_t)));
        };
        double out[4];
        texture.evaluate(s, t, out);
        for (int c = 0; c < 4; ++c) {
          const double expected =
              (1 - fu) * (1 - fv) * texel(i0, j0)[c] + fu * (1 - fv) * texel(i0 + 1, j0)[c] +
              (1 - fu) * fv * texel(i0, j0 + 1)[c] + fu * fv * texel(i0 + 1, j0 + 1)[c];
          // Values in [0, 1]. The lerp form rounds within 3 eps, the weights form within 6 eps.
          // Re-centring u by whole periods (fmod is exact; adding the period back to a
          // negative remainder is not) moves the fraction by at most half an ulp of the
          // period: 2^-50 for 12 texels (mirror of 6) plus 2^-51 for 8, about 6 eps in all.
          EXPECT_NEAR(out[c], expected, 16 * std::numeric_limits<double>::epsilon())
              << s << " " << t;
        }
      }
    }
  }
}

TEST(BilinearReconstruction, SeamFollowsTheWrapMode) {
  LinearImage image = LinearImage::filled(4, 1, 0.0f);
  for (std::int32_t a = 0; a < 4; ++a)
    image.texel(a, 0)[0] = float(a + 1);  // 1 2 3 4
  const auto value_at = [&](WrapMode mode, double s) {
    double out[4];
    BilinearReconstruction(image, mode, WrapMode::clamp_to_edge).evaluate(s, 0.5, out);
    return out[0];
  };
  // s = 0 is halfway between texel -1 and texel 0.
  EXPECT_EQ(value_at(WrapMode::repeat, 0.0), 2.5);  // texels 3 (value 4) and 0 (value 1)
  EXPECT_EQ(value_at(WrapMode::clamp_to_edge, 0.0), 1.0);
  EXPECT_EQ(value_at(WrapMode::mirror, 0.0), 1.0);  // texel -1 mirrors texel 0
  // One period further: repeat has period 1, mirror period 2.
  EXPECT_EQ(value_at(WrapMode::repeat, 1.0), 2.5);
  EXPECT_EQ(value_at(WrapMode::mirror, 1.0), 4.0);  // texels 3 and 4 -> 3, 3
  EXPECT_EQ(value_at(WrapMode::mirror, 2.0), 1.0);
  EXPECT_EQ(value_at(WrapMode::mirror, -1.0), 4.0);
  EXPECT_EQ(value_at(WrapMode::clamp_to_edge, 7.0), 4.0);
  EXPECT_EQ(value_at(WrapMode::clamp_to_edge, -7.0), 1.0);
}

TEST(BilinearReconstruction, ExtremeCoordinatesAreDefined) {
  Random random(0xb113);
  const LinearImage image = random_image(random, 3, 5);
  const double inf = std::numeric_limits<double>::infinity();
  for (WrapMode mode : kWrapModes) {
    const BilinearReconstruction texture(image, mode, mode);
    double out[4];
    for (double huge : {1e300, -1e300, 1e17, -3e15 - 0.25}) {
      texture.evaluate(huge, -huge, out);
      for (int c = 0; c < 4; ++c) {
        EXPECT_GE(out[c], 0.0);
        EXPECT_LE(out[c], 1.0);
      }
    }
    for (double bad : {inf, -inf, std::nan("")}) {
      texture.evaluate(bad, 0.5, out);
      EXPECT_EQ(out[0], 0.0);
      EXPECT_EQ(out[3], 0.0);
      texture.evaluate(0.5, bad, out);
      EXPECT_EQ(out[1], 0.0);
    }
  }
}

TEST(BilinearReconstruction, RejectsEmptyImages) {
  const LinearImage empty;
  EXPECT_THROW(BilinearReconstruction(empty, WrapMode::repeat, WrapMode::repeat),
               std::invalid_argument);
  LinearImage short_data = LinearImage::filled(2, 2, 0.0f);
  short_data.rgba.pop_back();
  EXPECT_THROW(BilinearReconstruction(short_data, WrapMode::repeat, WrapMode::repeat),
               std::invalid_argument);
}

}  // namespace
}  // namespace edgewise::texture_scene
