// Error of a filtered image against its ground truth, in linear units, over R, G and B.
//
// Alpha is left out: the test textures are opaque (alpha 1 in every texel, so every filter and
// the ground truth give 1 up to rounding), and counting it would only dilute the colour error
// (by a factor sqrt(3/4) in RMSE).
#pragma once

#include <cstdint>

#include "texture_scene/linear_image.hpp"

namespace edgewise::texture_scene {

struct ImageError {
  double rmse = 0.0;  // sqrt(mean over pixels and R, G, B of the squared difference)
  // 10 log10(1 / rmse^2), peak 1 (linear units). +inf for identical images (rmse 0); -inf
  // when rmse is +inf.
  double psnr = 0.0;
  double worst = 0.0;  // the largest absolute difference of one channel
  std::int32_t worst_x = 0, worst_y = 0;
  int worst_channel = 0;  // 0, 1 or 2
};

// Compares `image` with `truth` pixel by pixel. A difference that is not finite (a NaN or an
// infinity in either image) counts as +inf: rmse and worst are then +inf and psnr -inf, at the
// first such value in row-major order. Throws std::invalid_argument when the sizes differ or an
// image is empty or inconsistent.
ImageError compare_images(const LinearImage& image, const LinearImage& truth);

}  // namespace edgewise::texture_scene
