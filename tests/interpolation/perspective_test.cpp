// Perspective: the reference's perspective step on each barycentric method stays within its
// derived bound of the exact perspective-correct barycentrics; the affine variant's error grows
// with the depth range w_max / w_min (one of the project's stability results, printed).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "error_bounds.hpp"
#include "interpolation_triangles.hpp"
#include "interpolation/interpolation_reference.hpp"

namespace edgewise::test {
namespace {

TEST(Perspective, CorrectMatchesExactWithinDerivedBound) {
  Random random(0x9e59ec71);
  for (const InterpolationTriangleSource& source : interpolation_triangle_sources()) {
    for (double depth_ratio : {1.0, 2.0, 10.0, 100.0, 1e4}) {
      for (int n = 0; n < 60; ++n) {
        ScreenTriangle t = source.make(random);
        assign_depths(random, depth_ratio, t);
        for (int s = 0; s < 8; ++s) {
          double px, py;
          random_pixel_center(random, t, px, py);
          const ExactWeights exact = exact_weights_with_error(t, px, py);
          for (InterpolationMethod method : kBarycentricMethods) {
            const reference::Weights correct =
                reference::interpolation_weights(method, Perspective::correct, t, px, py);
            const BoundedWeights bound = perspective_bounds(
                Evaluator::reference,
                screen_weight_bounds(method, Evaluator::reference, t, 0, 0, px, py), t);
            for (int i = 0; i < 3; ++i) {
              ASSERT_LE(std::abs(correct.b[i] - exact.correct.b[i]),
                        bound.b[i].error + exact.correct_error[i])
                  << source.name << " " << name_of(method) << " ratio " << depth_ratio << " b" << i;
            }
          }
        }
      }
    }
  }
}

// Inside the triangle (weights >= 0), for attribute values in [0, 1] and w in [1, R], the
// affine error is at most the edge case's maximum (sqrt(R) - 1) / (sqrt(R) + 1): with S the
// vertices whose affine weight exceeds the correct one and beta their affine weight sum, the
// error is at most beta - (beta / R) / (beta / R + 1 - beta), whose maximum over beta is that.
double affine_error_limit(double depth_ratio) {
  const double root = std::sqrt(depth_ratio);
  return (root - 1.0) / (root + 1.0);
}

TEST(Perspective, AffineErrorGrowsWithDepthRange) {
  const double ratios[] = {1.0, 1.25, 2.0, 4.0, 10.0, 100.0, 1000.0};
  double previous_rmse = -1.0, previous_worst = -1.0;
  std::printf("affine vs perspective-correct, attribute in [0,1], samples inside triangles\n");
  std::printf("%10s %12s %12s %12s\n", "w_max/w_min", "RMSE", "worst", "limit");
  for (double depth_ratio : ratios) {
    Random random(0xaff1e);  // the same triangles and samples for every ratio
    double squared_sum = 0.0, worst = 0.0;
    long samples = 0;
    for (int n = 0; n < 1500; ++n) {
      ScreenTriangle t = interpolation_triangle_sources()[1].make(random);  // large
      assign_depths(random, depth_ratio, t);
      const double values[3] = {random.uniform(), random.uniform(), random.uniform()};
      for (int s = 0; s < 8; ++s) {
        double px, py;
        random_pixel_center(random, t, px, py);
        const reference::Weights exact = reference::exact_weights(t, px, py);
        const reference::Weights affine = reference::interpolation_weights(
            InterpolationMethod::plane_equations, Perspective::affine, t, px, py);
        if (std::min({affine.b[0], affine.b[1], affine.b[2]}) < 0.0) continue;  // outside
        double error = 0.0;
        for (int i = 0; i < 3; ++i)
          error += (affine.b[i] - exact.b[i]) * values[i];
        squared_sum += error * error;
        worst = std::max(worst, std::abs(error));
        ++samples;
      }
    }
    ASSERT_GT(samples, 1000);
    const double rmse = std::sqrt(squared_sum / static_cast<double>(samples));
    std::printf("%10g %12.3e %12.3e %12.3e\n", depth_ratio, rmse, worst,
                affine_error_limit(depth_ratio));
    // Rounding alone (double weights near 1) stays below 2^-40 of the attribute range.
    EXPECT_LE(worst, affine_error_limit(depth_ratio) + 0x1.0p-40);
    if (depth_ratio == 1.0) {
      EXPECT_LE(worst, 0x1.0p-40) << "constant w: affine is exact";
    } else {
      EXPECT_GT(rmse, previous_rmse) << "ratio " << depth_ratio;
      EXPECT_GT(worst, previous_worst) << "ratio " << depth_ratio;
    }
    previous_rmse = rmse;
    previous_worst = worst;
  }
}

}  // namespace
}  // namespace edgewise::test
