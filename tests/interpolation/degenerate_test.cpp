// Degenerate input gets finite, documented weights in the references and in every ISA's float32
// interpolators (kernels/interpolation/interpolation_reference.hpp lists the rules).
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <vector>

#include "fast_interpolation.hpp"
#include "isa_params.hpp"
#include "interpolation/interpolation_reference.hpp"

namespace edgewise::test {
namespace {

constexpr double kNaN = std::numeric_limits<double>::quiet_NaN();
constexpr double kInf = std::numeric_limits<double>::infinity();

// Expected weights of a case, per kind of method (nullopt: only finiteness is required).
struct Expected {
  std::optional<reference::Weights> barycentric;  // areas, edge functions, plane equations
  std::optional<reference::Weights> scanline;
  std::optional<reference::Weights> inverse_distance;
  std::optional<reference::Weights> nearest_vertex;
};

struct DegenerateCase {
  const char* name;
  ScreenTriangle triangle;
  double px, py;  // a pixel center
  Expected expected;
};

constexpr reference::Weights kCentroid = reference::kCentroidWeights;
constexpr reference::Weights kVertex0 = {{1, 0, 0}}, kVertex1 = {{0, 1, 0}}, kVertex2 = {{0, 0, 1}};

std::vector<DegenerateCase> degenerate_cases() {
  const double one[3] = {1, 1, 1};
  auto tri = [&](double x0, double y0, double x1, double y1, double x2, double y2,
                 const double(&w)[3]) {
    return ScreenTriangle{{x0, x1, x2}, {y0, y1, y2}, {w[0], w[1], w[2]}};
  };
  const double far_depth[3] = {1, 1000, 1000};
  return {
      {"collinear, on the line",
       tri(0.5, 0.5, 10.5, 10.5, 20.5, 20.5, one),
       5.5,
       5.5,
       {kCentroid, kCentroid, std::nullopt, kVertex0}},
      {"collinear, off the line",
       tri(0.5, 0.5, 10.5, 10.5, 20.5, 20.5, one),
       3.5,
       9.5,
       {kCentroid, kCentroid, std::nullopt, std::nullopt}},
      {"horizontal collinear",
       tri(0.5, 5.5, 10.5, 5.5, 20.5, 5.5, one),
       12.5,
       5.5,
       {kCentroid, kCentroid, std::nullopt, kVertex1}},
      {"all vertices coincide on the sample",
       tri(4.5, 4.5, 4.5, 4.5, 4.5, 4.5, one),
       4.5,
       4.5,
       {kCentroid, kCentroid, kVertex0, kVertex0}},
      {"two coincide on the sample",
       tri(9.5, 3.5, 2.5, 2.5, 2.5, 2.5, one),
       2.5,
       2.5,
       {kCentroid, kCentroid, kVertex1, kVertex1}},
      {"NaN coordinate",
       tri(kNaN, 0.5, 10.5, 0.5, 0.5, 10.5, one),
       2.5,
       2.5,
       {kCentroid, kCentroid, kCentroid, kCentroid}},
      {"infinite coordinate",
       tri(0.5, 0.5, kInf, 0.5, 0.5, 10.5, one),
       2.5,
       2.5,
       {kCentroid, kCentroid, kCentroid, kCentroid}},
      {"inverse distance at a vertex",
       tri(0.5, 0.5, 10.5, 0.5, 3.5, 9.5, one),
       10.5,
       0.5,
       {kVertex1, kVertex1, kVertex1, kVertex1}},
      {"scan-line row through the top vertex",
       tri(3.5, 1.5, 10.25, 9.0, 0.0, 12.0, one),
       3.5,
       1.5,
       {kVertex0, kVertex0, kVertex0, kVertex0}},
      {"scan-line row through the bottom vertex",
       tri(3.0, 1.25, 10.25, 9.0, 6.5, 12.5, one),
       6.5,
       12.5,
       {kVertex2, kVertex2, kVertex2, kVertex2}},
      {"scan-line on a horizontal top edge",
       tri(0.5, 2.5, 16.5, 2.5, 4.0, 11.0, one),
       8.5,
       2.5,
       {reference::Weights{{0.5, 0.5, 0.0}}, reference::Weights{{0.5, 0.5, 0.0}}, std::nullopt,
        std::nullopt}},
      {"scan-line on a horizontal bottom edge",
       tri(4.0, 1.0, 16.5, 10.5, 0.5, 10.5, one),
       12.5,
       10.5,
       {reference::Weights{{0.0, 0.75, 0.25}}, reference::Weights{{0.0, 0.75, 0.25}}, std::nullopt,
        std::nullopt}},
      {"sample far outside", tri(0.5, 0.5, 3.25, 0.75, 1.0, 2.5, one), 30000.5, -20000.5, {}},
      {"sliver across the guard band",
       tri(-32768.0, -32768.0, 32767.99609375, 32767.99609375, -32767.99609375, -32768.0, one),
       -32767.5,
       32767.5,
       {}},
      {"beyond the horizon (interpolated 1/w <= 0)",
       tri(0.5, 0.5, 100.5, 0.5, 0.5, 100.5, far_depth),
       150.5,
       150.5,
       {}},
      {"zero w", tri(0.5, 0.5, 10.5, 0.5, 0.5, 10.5, {0, 1, 1}), 2.5, 2.5, {}},
      {"negative w", tri(0.5, 0.5, 10.5, 0.5, 0.5, 10.5, {1, -1, 1}), 2.5, 2.5, {}},
      {"NaN w", tri(0.5, 0.5, 10.5, 0.5, 0.5, 10.5, {1, 1, kNaN}), 2.5, 2.5, {}},
      {"infinite w", tri(0.5, 0.5, 10.5, 0.5, 0.5, 10.5, {kInf, 1, 1}), 2.5, 2.5, {}},
      {"tiny w", tri(0.5, 0.5, 10.5, 0.5, 0.5, 10.5, {1e-300, 1, 1}), 2.5, 2.5, {}},
  };
}

const std::optional<reference::Weights>& expected_for(const Expected& e, InterpolationMethod m) {
  switch (m) {
    case InterpolationMethod::nearest_vertex:
      return e.nearest_vertex;
    case InterpolationMethod::inverse_distance:
      return e.inverse_distance;
    case InterpolationMethod::scanline:
      return e.scanline;
    default:
      return e.barycentric;
  }
}

bool bad_w(const ScreenTriangle& t) {
  for (double w : t.w) {
    if (!(w >= kMinClipW && w <= kMaxClipW)) return true;
  }
  return false;
}

TEST(InterpolationDegenerate, ReferenceFiniteAndAsDocumented) {
  for (const DegenerateCase& c : degenerate_cases()) {
    for (InterpolationMethod method : kInterpolationMethods) {
      const reference::Weights screen = reference::screen_weights(method, c.triangle, c.px, c.py);
      const reference::Weights correct =
          reference::interpolation_weights(method, Perspective::correct, c.triangle, c.px, c.py);
      for (int i = 0; i < 3; ++i) {
        EXPECT_TRUE(std::isfinite(screen.b[i])) << c.name << " " << name_of(method);
        EXPECT_TRUE(std::isfinite(correct.b[i])) << c.name << " " << name_of(method);
        if (bad_w(c.triangle)) {
          EXPECT_EQ(correct.b[i], screen.b[i]) << c.name << ": affine";
        }
      }
      if (const auto& expected = expected_for(c.expected, method)) {
        for (int i = 0; i < 3; ++i) {
          EXPECT_NEAR(screen.b[i], expected->b[i], 0x1.0p-50)
              << c.name << " " << name_of(method) << " b" << i;
        }
      }
    }
    const reference::Weights exact = reference::exact_weights(c.triangle, c.px, c.py);
    for (double b : exact.b)
      EXPECT_TRUE(std::isfinite(b)) << c.name << " exact";
  }
}

class InterpolationDegenerateFast : public IsaTest {};

TEST_P(InterpolationDegenerateFast, FiniteAndAsDocumented) {
  const FastInterpolation* fast = fast_interpolation(isa());
  ASSERT_NE(fast, nullptr);
  const std::size_t lanes = fast->lanes;
  std::vector<float> screen(3 * lanes), correct(3 * lanes);
  for (const DegenerateCase& c : degenerate_cases()) {
    // Lane 0 is the case's sample; the other lanes are its neighbours to the right.
    const double origin_x = std::floor(c.px), origin_y = std::floor(c.py);
    for (InterpolationMethod method : kInterpolationMethods) {
      fast->screen_row(method, c.triangle, origin_x, origin_y, 0, 0, screen.data());
      fast->perspective_row(method, c.triangle, origin_x, origin_y, 0, 0, correct.data());
      for (std::size_t k = 0; k < 3 * lanes; ++k) {
        ASSERT_TRUE(std::isfinite(screen[k])) << c.name << " " << name_of(method);
        ASSERT_TRUE(std::isfinite(correct[k])) << c.name << " " << name_of(method);
      }
      if (const auto& expected = expected_for(c.expected, method)) {
        // Float rounding of exactly representable results, or of 1/3: within 2^-24.
        for (int i = 0; i < 3; ++i) {
          EXPECT_NEAR(screen[i * lanes], expected->b[i], 0x1.0p-24)
              << c.name << " " << name_of(method) << " b" << i;
        }
      }
    }
  }
}

EDGEWISE_INSTANTIATE_PER_ISA(InterpolationDegenerateFast, fast_isas());

}  // namespace
}  // namespace edgewise::test
