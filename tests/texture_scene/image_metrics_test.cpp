// Image metrics on hand cases: identical images, one differing channel, a uniform offset,
// alpha ignored, non-finite values.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>

#include "texture_scene/image_metrics.hpp"

namespace edgewise::texture_scene {
namespace {

TEST(ImageMetrics, IdenticalImagesHaveInfinitePsnr) {
  const LinearImage image = LinearImage::filled(3, 2, 0.25f);
  const ImageError error = compare_images(image, image);
  EXPECT_EQ(error.rmse, 0.0);
  EXPECT_EQ(error.psnr, std::numeric_limits<double>::infinity());
  EXPECT_EQ(error.worst, 0.0);
}

TEST(ImageMetrics, OneDifferingChannel) {
  const LinearImage truth = LinearImage::filled(2, 1, 0.25f);
  LinearImage image = truth;
  image.texel(1, 0)[1] = 0.75f;  // 0.5 off in one of 6 colour values
  const ImageError error = compare_images(image, truth);
  EXPECT_DOUBLE_EQ(error.rmse, std::sqrt(0.25 / 6.0));
  EXPECT_DOUBLE_EQ(error.psnr, 10.0 * std::log10(24.0));  // 13.8 dB
  EXPECT_EQ(error.worst, 0.5);
  EXPECT_EQ(error.worst_x, 1);
  EXPECT_EQ(error.worst_y, 0);
  EXPECT_EQ(error.worst_channel, 1);
}

TEST(ImageMetrics, UniformOffset) {
  const LinearImage truth = LinearImage::filled(4, 3, 0.5f);
  const LinearImage image = LinearImage::filled(4, 3, 0.5f + 0x1.0p-7f);
  const ImageError error = compare_images(image, truth);
  EXPECT_EQ(error.rmse, 0x1.0p-7);
  EXPECT_DOUBLE_EQ(error.psnr, 140.0 * std::log10(2.0));  // 42.1 dB
  // Ties keep the first worst value in row-major order.
  EXPECT_EQ(error.worst_x, 0);
  EXPECT_EQ(error.worst_y, 0);
  EXPECT_EQ(error.worst_channel, 0);
}

TEST(ImageMetrics, AlphaIsIgnored) {
  const LinearImage truth = LinearImage::filled(2, 2, 1.0f);
  LinearImage image = truth;
  image.texel(1, 1)[3] = 0.0f;
  EXPECT_EQ(compare_images(image, truth).rmse, 0.0);
}

TEST(ImageMetrics, NonFiniteValuesGiveInfiniteError) {
  const LinearImage truth = LinearImage::filled(3, 3, 0.5f);
  for (float bad : {std::nanf(""), std::numeric_limits<float>::infinity()}) {
    LinearImage image = truth;
    image.texel(2, 1)[2] = bad;
    image.texel(0, 2)[0] = bad;
    const ImageError error = compare_images(image, truth);
    EXPECT_EQ(error.rmse, std::numeric_limits<double>::infinity());
    EXPECT_EQ(error.psnr, -std::numeric_limits<double>::infinity());
    EXPECT_EQ(error.worst, std::numeric_limits<double>::infinity());
    EXPECT_EQ(error.worst_x, 2);
    EXPECT_EQ(error.worst_y, 1);
    EXPECT_EQ(error.worst_channel, 2);
    // In the truth too.
    EXPECT_EQ(compare_images(truth, image).rmse, std::numeric_limits<double>::infinity());
  }
}

TEST(ImageMetrics, RejectsMismatchedImages) {
  EXPECT_THROW(compare_images(LinearImage::filled(2, 2, 0.0f), LinearImage::filled(2, 3, 0.0f)),
               std::invalid_argument);
  EXPECT_THROW(compare_images(LinearImage{}, LinearImage{}), std::invalid_argument);
  LinearImage broken = LinearImage::filled(2, 2, 0.0f);
  broken.rgba.pop_back();
  EXPECT_THROW(compare_images(broken, LinearImage::filled(2, 2, 0.0f)), std::invalid_argument);
}

}  // namespace
}  // namespace edgewise::texture_scene
