// TextureView: the exact Jacobian against central differences of the mapping (with the
// difference's own truncation and rounding error bounded), the query stream against the mapping,
// and the rejection of views whose plane is not in front of the camera.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "random.hpp"
#include "texture_scene/builtin_views.hpp"
#include "texture_scene/texture_view.hpp"

namespace edgewise::texture_scene {
namespace {

using edgewise::test::Random;

constexpr double kEpsilon = std::numeric_limits<double>::epsilon();

double dot(const std::array<double, 3>& row, double x, double y) {
  return row[0] * x + row[1] * y + row[2];
}
double magnitude(const std::array<double, 3>& row, double x, double y) {
  return std::abs(row[0] * x) + std::abs(row[1] * y) + std::abs(row[2]);
}

// Along one screen axis the mapping is a Moebius function n(z) / w(z) with n, w linear, and its
// central difference is exactly (s'(z) w^2) / (w^2 - (w' e)^2): the truncation error is
//   |s'| r / (1 - r),  r = (w' e / w)^2.
// Rounding: s is a 3-term dot product over another, each within 3 eps of its terms' magnitudes,
// and the division adds eps; z +- e is rounded (eps |z + e|, changing s by |s'| times that). The
// difference of two such values over 2e errs by at most (error of s + |s'| eps (|z| + e)) / e.
// The analytic Jacobian (n' w - n w') / w^2 errs by at most 4 eps (|n'| |w| + |n| |w'|) / w^2.
double central_difference_bound(const std::array<double, 3>& numerator,
                                const std::array<double, 3>& denominator, double x, double y,
                                int axis, double step, double derivative) {
  const double w = dot(denominator, x, y);
  const double n = dot(numerator, x, y);
  const double z = axis == 0 ? x : y;
  const double r = std::pow(denominator[axis] * step / w, 2.0);
  const double truncation = std::abs(derivative) * r / (1.0 - r);
  // Evaluated at z +- e, where w is at least |w| - |w'| e.
  const double w_low = std::abs(w) - std::abs(denominator[axis]) * step;
  const double value_error =
      4.0 * kEpsilon *
      (magnitude(numerator, x, y) + std::abs(numerator[axis]) * step +
       std::abs(n / w) * (magnitude(denominator, x, y) + std::abs(denominator[axis]) * step)) /
      w_low;
  const double rounding =
      (value_error + std::abs(derivative) * kEpsilon * (std::abs(z) + step)) / step;
  const double analytic =
      4.0 * kEpsilon * (std::abs(numerator[axis] * w) + std::abs(n * denominator[axis])) / (w * w);
  return truncation + rounding + analytic;
}

void expect_jacobian_matches_differences(const TextureView& view, Random& random, int points) {
  const ProjectiveMap& map = view.map();
  const double step = 1.0 / 64.0;
  for (int p = 0; p < points; ++p) {
    const double x = random.uniform(step, view.width() - step);
    const double y = random.uniform(step, view.height() - step);
    const ScreenJacobian jacobian = view.jacobian(x, y);
    const TexturePoint right = view.point(x + step, y), left = view.point(x - step, y);
    const TexturePoint down = view.point(x, y + step), up = view.point(x, y - step);
    const struct {
      double difference, analytic;
      const std::array<double, 3>& numerator;
      int axis;
      const char* name;
    } checks[] = {
        {(right.s - left.s) / (2 * step), jacobian.dsdx, map.s_row, 0, "dsdx"},
        {(right.t - left.t) / (2 * step), jacobian.dtdx, map.t_row, 0, "dtdx"},
        {(down.s - up.s) / (2 * step), jacobian.dsdy, map.s_row, 1, "dsdy"},
        {(down.t - up.t) / (2 * step), jacobian.dtdy, map.t_row, 1, "dtdy"},
    };
    for (const auto& check : checks) {
      const double bound = central_difference_bound(check.numerator, map.w_row, x, y, check.axis,
                                                    step, check.analytic);
      ASSERT_LE(std::abs(check.difference - check.analytic), bound)
          << check.name << " at (" << x << ", " << y << "): analytic " << check.analytic
          << " difference " << check.difference;
    }
  }
}

TEST(TextureView, JacobianMatchesCentralDifferences) {
  Random random(0x7e5c0de);
  expect_jacobian_matches_differences(ground_plane_view(1920, 1080), random, 2000);
  expect_jacobian_matches_differences(ground_plane_view(33, 17), random, 2000);
  expect_jacobian_matches_differences(magnification_view(640, 360, 256, 128), random, 2000);
  // Random projective maps with a positive denominator over the screen.
  for (int m = 0; m < 50; ++m) {
    ProjectiveMap map{};
    for (auto* row : {&map.s_row, &map.t_row})
      for (double& coefficient : *row)
        coefficient = random.uniform(-2.0, 2.0);
    map.w_row = {random.uniform(-0.01, 0.01), random.uniform(-0.01, 0.01), 3.0};
    expect_jacobian_matches_differences(TextureView(100, 100, map), random, 100);
  }
}

// A wrong Jacobian formula must fail the check above: the bound is far below the derivatives.
TEST(TextureView, DifferenceBoundIsTight) {
  const TextureView view = ground_plane_view(1920, 1080);
  const ProjectiveMap& map = view.map();
  for (double y : {0.5, 540.0, 1079.5}) {
    const ScreenJacobian jacobian = view.jacobian(700.25, y);
    EXPECT_LT(
        central_difference_bound(map.s_row, map.w_row, 700.25, y, 1, 1.0 / 64.0, jacobian.dsdy),
        1e-6 * std::abs(jacobian.dsdy));
  }
}

TEST(TextureView, QueriesAreTheMappingAtPixelCentresRoundedOnce) {
  const TextureView view = ground_plane_view(40, 24);
  const std::vector<TextureQuery> queries = view.queries();
  ASSERT_EQ(queries.size(), 40u * 24u);
  for (std::int32_t j = 0; j < 24; ++j) {
    for (std::int32_t i = 0; i < 40; ++i) {
      const TextureQuery& q = queries[static_cast<std::size_t>(j) * 40 + i];
      const TexturePoint p = view.point(i + 0.5, j + 0.5);
      const ScreenJacobian d = view.jacobian(i + 0.5, j + 0.5);
      ASSERT_EQ(q.s, static_cast<float>(p.s)) << i << "," << j;
      ASSERT_EQ(q.t, static_cast<float>(p.t));
      ASSERT_EQ(q.dsdx, static_cast<float>(d.dsdx));
      ASSERT_EQ(q.dtdx, static_cast<float>(d.dtdx));
      ASSERT_EQ(q.dsdy, static_cast<float>(d.dsdy));
      ASSERT_EQ(q.dtdy, static_cast<float>(d.dtdy));
    }
  }
  // A region's queries are the same records, row-major within the region.
  const std::vector<TextureQuery> region = view.queries({5, 7, 3, 2});
  ASSERT_EQ(region.size(), 6u);
  for (std::int32_t j = 0; j < 2; ++j) {
    for (std::int32_t i = 0; i < 3; ++i) {
      const TextureQuery& a = region[static_cast<std::size_t>(j) * 3 + i];
      const TextureQuery& b = queries[static_cast<std::size_t>(7 + j) * 40 + 5 + i];
      EXPECT_EQ(a.s, b.s);
      EXPECT_EQ(a.dtdy, b.dtdy);
    }
  }
}

TEST(TextureView, RejectsBadRegions) {
  const TextureView view = ground_plane_view(40, 24);
  for (const ScreenRegion region : {ScreenRegion{0, 0, 0, 1}, ScreenRegion{-1, 0, 2, 2},
                                    ScreenRegion{39, 0, 2, 1}, ScreenRegion{0, 20, 1, 5}}) {
    EXPECT_THROW(view.queries(region), std::invalid_argument)
        << region.x0 << " " << region.y0 << " " << region.width << " " << region.height;
  }
  EXPECT_NO_THROW(view.queries({39, 23, 1, 1}));
  EXPECT_THROW(view.query(40, 0), std::invalid_argument);
  EXPECT_THROW(view.query(0, -1), std::invalid_argument);
}

TEST(TextureView, RejectsPlanesNotInFrontEverywhere) {
  const ProjectiveMap affine{{1.0, 0.0, 0.0}, {0.0, 1.0, 0.0}, {0.0, 0.0, 1.0}};
  EXPECT_NO_THROW(TextureView(10, 10, affine));
  ProjectiveMap horizon = affine;
  horizon.w_row = {0.0, 1.0, -5.0};  // w = 0 at y = 5: the horizon is on screen
  EXPECT_THROW(TextureView(10, 10, horizon), std::invalid_argument);
  horizon.w_row = {0.0, 1.0, 0.0};  // w = 0 on the top edge itself
  EXPECT_THROW(TextureView(10, 10, horizon), std::invalid_argument);
  ProjectiveMap behind = affine;
  behind.w_row = {0.0, 0.0, -1.0};
  EXPECT_THROW(TextureView(10, 10, behind), std::invalid_argument);
  ProjectiveMap not_finite = affine;
  not_finite.s_row[1] = std::numeric_limits<double>::quiet_NaN();
  EXPECT_THROW(TextureView(10, 10, not_finite), std::invalid_argument);
  not_finite = affine;
  not_finite.w_row[0] = std::numeric_limits<double>::infinity();
  EXPECT_THROW(TextureView(10, 10, not_finite), std::invalid_argument);
  EXPECT_THROW(TextureView(0, 10, affine), std::invalid_argument);
  EXPECT_THROW(TextureView(10, (1 << 15) + 1, affine), std::invalid_argument);
}

// Coordinates beyond float's range round to infinities, without undefined behaviour.
TEST(TextureView, QueriesBeyondFloatRangeBecomeInfinite) {
  const ProjectiveMap huge{{1e300, 0.0, 0.0}, {0.0, -1e300, 0.0}, {0.0, 0.0, 1.0}};
  const TextureQuery q = TextureView(2, 2, huge).query(0, 0);
  EXPECT_EQ(q.s, std::numeric_limits<float>::infinity());
  EXPECT_EQ(q.t, -std::numeric_limits<float>::infinity());
  EXPECT_EQ(q.dtdx, 0.0f);
  EXPECT_EQ(q.dsdx, std::numeric_limits<float>::infinity());
  EXPECT_EQ(q.dtdy, -std::numeric_limits<float>::infinity());
}

}  // namespace
}  // namespace edgewise::texture_scene
