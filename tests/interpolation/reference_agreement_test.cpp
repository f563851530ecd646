// The course calls sub-triangle areas, edge functions, scan-line and plane equations equivalent.
// In double precision each stays within its derived rounding bound of the exact barycentrics,
// so any two agree within the sum of their bounds; the bounds grow with the triangle's
// conditioning (coordinates and extrapolation distance over area), as slivers show.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <vector>

#include "error_bounds.hpp"
#include "interpolation_triangles.hpp"
#include "interpolation/interpolation_reference.hpp"

namespace edgewise::test {
namespace {

constexpr int kReferenceTrianglesPerSource = 400;
constexpr int kSamplesPerTriangle = 16;

TEST(InterpolationReference, EquivalentMethodsAgreeWithinDerivedBound) {
  Random random(0x1e7e1a7e);
  std::vector<double> relative_bounds;  // bound / (exact magnitude + 1), to show it is informative
  for (const InterpolationTriangleSource& source : interpolation_triangle_sources()) {
    double worst_difference = 0.0, worst_bound = 0.0;
    for (int n = 0; n < kReferenceTrianglesPerSource; ++n) {
      const ScreenTriangle t = source.make(random);
      for (int s = 0; s < kSamplesPerTriangle; ++s) {
        double px, py;
        random_pixel_center(random, t, px, py);
        const ExactWeights exact = exact_weights_with_error(t, px, py);
        reference::Weights weights[4];
        BoundedWeights bounds[4];
        for (int m = 0; m < 4; ++m) {
          const InterpolationMethod method = kBarycentricMethods[m];
          weights[m] = reference::screen_weights(method, t, px, py);
          bounds[m] = screen_weight_bounds(method, Evaluator::reference, t, 0, 0, px, py);
          for (int i = 0; i < 3; ++i) {
            const double bound = bounds[m].b[i].error + exact.screen_error[i];
            ASSERT_LE(std::abs(weights[m].b[i] - exact.screen.b[i]), bound)
                << source.name << " " << name_of(method) << " b" << i << " at (" << px << ", " << py
                << ")";
            relative_bounds.push_back(bounds[m].b[i].error / (std::abs(exact.screen.b[i]) + 1.0));
          }
        }
        for (int m1 = 0; m1 < 4; ++m1) {
          for (int m2 = m1 + 1; m2 < 4; ++m2) {
            for (int i = 0; i < 3; ++i) {
              const double difference = std::abs(weights[m1].b[i] - weights[m2].b[i]);
              const double bound = bounds[m1].b[i].error + bounds[m2].b[i].error;
              ASSERT_LE(difference, bound) << source.name << " " << name_of(kBarycentricMethods[m1])
                                           << " vs " << name_of(kBarycentricMethods[m2]);
              worst_difference = std::max(worst_difference, difference);
              worst_bound = std::max(worst_bound, bound);
            }
          }
        }
      }
    }
    std::printf("%-11s largest difference between methods %.3g (largest bound %.3g)\n",
                std::string(source.name).c_str(), worst_difference, worst_bound);
  }
  // The bounds are informative: for nearly all samples, far below any visible error.
  std::sort(relative_bounds.begin(), relative_bounds.end());
  const double p99 = relative_bounds[relative_bounds.size() * 99 / 100];
  std::printf("99th percentile of bound / (|b| + 1): %.3g\n", p99);
  EXPECT_LT(p99, 0x1.0p-30);
}

}  // namespace
}  // namespace edgewise::test
