// Nearest vertex and inverse distance are not barycentric: they are measured against the exact
// value (figures printed), and held to the properties they must have.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>

#include "interpolation_triangles.hpp"
#include "interpolation/interpolation_reference.hpp"

namespace edgewise::test {
namespace {

constexpr InterpolationMethod kVertexMethods[] = {InterpolationMethod::nearest_vertex,
                                                  InterpolationMethod::inverse_distance};

double distance(const ScreenTriangle& t, int i, double px, double py) {
  return std::hypot(px - t.x[i], py - t.y[i]);
}

// Weights in [0, 1] summing to 1: the double inverse-distance weights are each within
// 8 * 2^-53 relative (error_bounds.hpp), so their sum is within 3 * 8 * 2^-53 of 1.
void expect_convex(const reference::Weights& w, const char* what) {
  double sum = 0.0;
  for (double b : w.b) {
    EXPECT_GE(b, 0.0) << what;
    EXPECT_LE(b, 1.0) << what;
    sum += b;
  }
  EXPECT_NEAR(sum, 1.0, 24.0 * 0x1.0p-53) << what;
}

TEST(VertexMethods, ExactAtVerticesOneHotNearThem) {
  Random random(0x0e4e57);
  for (int n = 0; n < 2000; ++n) {
    ScreenTriangle t = interpolation_triangle_sources()[0].make(random);
    // Put each vertex on a pixel center so that samples can land on it.
    for (int i = 0; i < 3; ++i) {
      t.x[i] = std::floor(t.x[i]) + 0.5;
      t.y[i] = std::floor(t.y[i]) + 0.5;
    }
    for (InterpolationMethod method : kVertexMethods) {
      for (int i = 0; i < 3; ++i) {
        const bool shared = (t.x[i] == t.x[(i + 1) % 3] && t.y[i] == t.y[(i + 1) % 3]) ||
                            (t.x[i] == t.x[(i + 2) % 3] && t.y[i] == t.y[(i + 2) % 3]);
        if (shared) continue;
        const reference::Weights at = reference::screen_weights(method, t, t.x[i], t.y[i]);
        for (int k = 0; k < 3; ++k)
          EXPECT_EQ(at.b[k], k == i ? 1.0 : 0.0) << name_of(method);
      }
    }
    // A sample at distance d from vertex i and at least D from the others: nearest vertex picks
    // i when d < D; inverse distance gives b_i = (1/d) / (1/d + 1/d_j + 1/d_k) >= 1 - 2 d / D.
    const int i = static_cast<int>(random.integer(0, 2));
    const double px = t.x[i] + random.uniform(-2.0, 2.0), py = t.y[i] + random.uniform(-2.0, 2.0);
    const double d = distance(t, i, px, py);
    const double others =
        std::min(distance(t, (i + 1) % 3, px, py), distance(t, (i + 2) % 3, px, py));
    if (d < others) {
      EXPECT_EQ(reference::screen_weights(InterpolationMethod::nearest_vertex, t, px, py).b[i],
                1.0);
      const double b =
          reference::screen_weights(InterpolationMethod::inverse_distance, t, px, py).b[i];
      EXPECT_GE(b, 1.0 - 2.0 * d / others - 24.0 * 0x1.0p-53);
    }
  }
}

// Error of an attribute (vertex values uniform in [0, 1]) against the exact barycentric value,
// at pixel centers inside random triangles. The weights must be convex (so the value stays
// within the vertex values); the error figures are printed.
TEST(VertexMethods, ErrorAgainstExact) {
  Random random(0xd157a9ce);
  for (const InterpolationTriangleSource& source : interpolation_triangle_sources()) {
    double squared_sum[2] = {0.0, 0.0}, worst[2] = {0.0, 0.0};
    long samples = 0;
    for (int n = 0; n < 300; ++n) {
      const ScreenTriangle t = source.make(random);
      const double values[3] = {random.uniform(), random.uniform(), random.uniform()};
      for (int s = 0; s < 16; ++s) {
        double px, py;
        random_pixel_center(random, t, px, py);
        const reference::Weights exact = reference::exact_weights(t, px, py);
        if (std::min({exact.b[0], exact.b[1], exact.b[2]}) < 0.0) continue;  // outside
        const double truth =
            exact.b[0] * values[0] + exact.b[1] * values[1] + exact.b[2] * values[2];
        ++samples;
        for (int m = 0; m < 2; ++m) {
          const reference::Weights w = reference::screen_weights(kVertexMethods[m], t, px, py);
          expect_convex(w, std::string(name_of(kVertexMethods[m])).c_str());
          const double error = w.b[0] * values[0] + w.b[1] * values[1] + w.b[2] * values[2] - truth;
          squared_sum[m] += error * error;
          worst[m] = std::max(worst[m], std::abs(error));
        }
      }
    }
    ASSERT_GT(samples, 0);
    for (int m = 0; m < 2; ++m) {
      std::printf("%-11s %-16s attribute in [0,1]: RMSE %.4f, worst %.4f (%ld samples)\n",
                  std::string(source.name).c_str(), std::string(name_of(kVertexMethods[m])).c_str(),
                  std::sqrt(squared_sum[m] / static_cast<double>(samples)), worst[m], samples);
    }
  }
}

}  // namespace
}  // namespace edgewise::test
