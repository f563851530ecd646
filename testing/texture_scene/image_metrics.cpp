#include "texture_scene/image_metrics.hpp"

#include <cmath>
#include <limits>
#include <stdexcept>

namespace edgewise::texture_scene {
namespace {

bool consistent(const LinearImage& image) {
  return image.width > 0 && image.height > 0 &&
         image.rgba.size() == image.texel_index(0, image.height);
}

}  // namespace

ImageError compare_images(const LinearImage& image, const LinearImage& truth) {
  if (!consistent(image) || !consistent(truth) || image.width != truth.width ||
      image.height != truth.height)
    throw std::invalid_argument("compare_images: empty, inconsistent or different sizes");
  const double infinity = std::numeric_limits<double>::infinity();
  ImageError error;
  double squared_sum = 0.0;
  for (std::int32_t y = 0; y < image.height; ++y) {
    for (std::int32_t x = 0; x < image.width; ++x) {
      const float* a = image.texel(x, y);
      const float* b = truth.texel(x, y);
      for (int c = 0; c < 3; ++c) {
        double difference = std::abs(double(a[c]) - double(b[c]));
        if (!std::isfinite(difference)) difference = infinity;
        squared_sum += difference * difference;
        if (difference > error.worst) {
          error.worst = difference;
          error.worst_x = x;
          error.worst_y = y;
          error.worst_channel = c;
        }
      }
    }
  }
  const double count = 3.0 * image.width * image.height;
  error.rmse = std::sqrt(squared_sum / count);
  error.psnr = error.rmse == 0.0 ? infinity : -10.0 * std::log10(error.rmse * error.rmse);
  return error;
}

}  // namespace edgewise::texture_scene
