// Transforms, cameras and the viewport mapping put known points where the conventions say
// (camera.hpp): D3D clip space, right-handed view space looking down -z, docs/DESIGN.md's
// screen.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>

#include "edgewise/camera.hpp"
#include "float_roundoff.hpp"

namespace edgewise::test {
namespace {

// Each clip coordinate is a sum of four products of matrix entries (each the float nearest an
// exact value, relative error u) and inputs: the entries add u, each product u, the three sums
// 3u, all relative to the sum of the terms' magnitudes, and the camera's own exact value carries
// the error of its float inputs (fovy, near, far: about 2u). 8u of `magnitude` covers it.
void expect_close(double actual, double exact, double magnitude, const char* what) {
  EXPECT_NEAR(actual, exact, 8.0 * kFloatUnitRoundoff * magnitude) << what;
}

void expect_clip(const Vec4& c, double x, double y, double z, double w, double magnitude) {
  expect_close(c.x, x, magnitude, "x");
  expect_close(c.y, y, magnitude, "y");
  expect_close(c.z, z, magnitude, "z");
  expect_close(c.w, w, magnitude, "w");
}

TEST(Camera, PerspectiveMapsNearToZeroAndFarToW) {
  const float near = 0.25f, far = 80.0f;
  const Mat4 m = perspective(1.2f, 16.0f / 9.0f, near, far);
  expect_clip(transform(m, Vec3{0, 0, -near}), 0, 0, 0, near, near);
  expect_clip(transform(m, Vec3{0, 0, -far}), 0, 0, far, far, 2 * far);
  // Halfway in depth lands between, with w the distance in front of the camera.
  const Vec4 mid = transform(m, Vec3{0, 0, -10.0f});
  EXPECT_GT(mid.z, 0.0f);
  EXPECT_LT(mid.z, mid.w);
  expect_close(mid.w, 10.0, 10.0, "w");
}

TEST(Camera, PerspectiveMapsTheFieldOfViewToTheFrustumSides) {
  const double fovy = 1.2, aspect = 1.5, depth = 7.0;
  const Mat4 m = perspective(static_cast<float>(fovy), static_cast<float>(aspect), 0.1f, 100.0f);
  const double half_height = depth * std::tan(fovy / 2);
  const double half_width = half_height * aspect;
  // Top-right corner of the view at that depth: x = w and y = w.
  const Vec4 c =
      transform(m, Vec3{static_cast<float>(half_width), static_cast<float>(half_height), -7.0f});
  expect_close(c.x, c.w, 2 * depth, "x = w on the right side");
  expect_close(c.y, c.w, 2 * depth, "y = w on the top side");
  // Behind the camera w is negative.
  EXPECT_LT(transform(m, Vec3{0, 0, 3.0f}).w, 0.0f);
}

TEST(Camera, OrthographicMapsTheBoxToTheClipCube) {
  const Mat4 m = orthographic(-4.0f, 12.0f, -3.0f, 5.0f, 1.0f, 21.0f);
  expect_clip(transform(m, Vec3{-4, -3, -1}), -1, -1, 0, 1, 24);
  expect_clip(transform(m, Vec3{12, 5, -21}), 1, 1, 1, 1, 24);
  expect_clip(transform(m, Vec3{4, 1, -11}), 0, 0, 0.5, 1, 24);
}

TEST(Camera, LookAtPutsTheTargetDownMinusZ) {
  // From (5, 0, 0) towards the origin with y up: forward is -x, so right is -z.
  const Mat4 view = look_at({5, 0, 0}, {0, 0, 0}, {0, 1, 0});
  expect_clip(transform(view, Vec3{0, 0, 0}), 0, 0, -5, 1, 10);
  expect_clip(transform(view, Vec3{5, 1, 0}), 0, 1, 0, 1, 10);
  expect_clip(transform(view, Vec3{5, 0, -1}), 1, 0, 0, 1, 10);
  // A translation only, when the camera already looks down -z.
  const Mat4 moved = look_at({1, 2, 3}, {1, 2, -7}, {0, 1, 0});
  expect_clip(transform(moved, Vec3{1, 2, -7}), 0, 0, -10, 1, 20);
}

TEST(Camera, TransformsComposeRightToLeft) {
  const Mat4 rz = rotate({0, 0, 2}, static_cast<float>(std::numbers::pi / 2));
  expect_clip(transform(rz, Vec3{1, 0, 0}), 0, 1, 0, 1, 2);
  const Mat4 m = translate({1, 2, 3}) * scale({2, 3, 4});  // scale first
  expect_clip(transform(m, Vec3{1, 1, 1}), 3, 5, 7, 1, 16);
  expect_clip(transform(identity() * m, Vec4{1, 1, 1, 0}), 2, 3, 4, 0, 16);
  expect_clip(transform(rotate({0, 0, 0}, 1.0f), Vec3{1, 2, 3}), 1, 2, 3, 1, 8);
}

// Powers of two keep every step of the mapping exact, so positions compare with ==.
TEST(Viewport, NdcCornersLandOnTheTargetCorners) {
  const Viewport viewport{64, 40};
  const float w = 4.0f;
  const auto screen = [&](float ndc_x, float ndc_y) {
    return to_screen({ndc_x * w, ndc_y * w, 0.5f * w, w}, viewport);
  };
  const ScreenVertex top_left = screen(-1, 1), bottom_right = screen(1, -1);
  EXPECT_EQ(top_left.x, 0.0f);
  EXPECT_EQ(top_left.y, 0.0f);
  EXPECT_EQ(bottom_right.x, 64.0f);
  EXPECT_EQ(bottom_right.y, 40.0f);
  EXPECT_EQ(screen(1, 1).x, 64.0f);
  EXPECT_EQ(screen(1, 1).y, 0.0f);
  EXPECT_EQ(screen(-1, -1).x, 0.0f);
  EXPECT_EQ(screen(-1, -1).y, 40.0f);
  EXPECT_EQ(top_left.z, 0.5f);
  EXPECT_EQ(top_left.inv_w, 0.25f);
}

TEST(Viewport, PixelCentersAreAtHalfIntegers) {
  const Viewport viewport{64, 32};
  for (int i : {0, 5, 63}) {
    const float ndc_x = static_cast<float>(2.0 * (i + 0.5) / 64 - 1.0);
    EXPECT_EQ(to_screen({ndc_x, 0, 0, 1}, viewport).x, i + 0.5f) << "column " << i;
  }
  for (int j : {0, 9, 31}) {
    const float ndc_y = static_cast<float>(1.0 - 2.0 * (j + 0.5) / 32);
    EXPECT_EQ(to_screen({0, ndc_y, 0, 1}, viewport).y, j + 0.5f) << "row " << j;
  }
}

TEST(Viewport, DepthIsZOverWClampedToZeroOne) {
  const Viewport viewport{8, 8};
  EXPECT_EQ(to_screen({0, 0, 0, 3}, viewport).z, 0.0f);
  EXPECT_EQ(to_screen({0, 0, 3, 3}, viewport).z, 1.0f);
  EXPECT_EQ(to_screen({0, 0, 1, 4}, viewport).z, 0.25f);
  // z = w whose 1/w rounds up still gives depth 1, not one ulp above.
  for (float w : {3.0f, 7.0f, 0.1f, 1e7f})
    EXPECT_LE(to_screen({0, 0, w, w}, viewport).z, 1.0f);
}

// The whole chain: a world point seen by a camera lands on the pixel it should.
TEST(Viewport, PipelinePutsAWorldPointOnItsPixel) {
  const Viewport viewport{200, 100};
  const Mat4 view = look_at({0, 0, 10}, {0, 0, 0}, {0, 1, 0});
  const Mat4 projection = perspective(static_cast<float>(std::numbers::pi / 2), 2.0f, 1.0f, 100.0f);
  // At distance 10 with a 90 degree vertical field, y = 5 is half-way up: NDC y = 0.5.
  const ScreenVertex v = to_screen(transform(projection * view, Vec3{10, 5, 0}), viewport);
  // About twenty roundings (matrix product, transform, divide, mapping), each relative u of
  // values below 2 in NDC: 32u of NDC, times half the viewport in pixels.
  EXPECT_NEAR(v.x, 150.0, 32 * kFloatUnitRoundoff * 100);  // NDC x = 10 / (10 * 2) = 0.5
  EXPECT_NEAR(v.y, 25.0, 32 * kFloatUnitRoundoff * 50);
  EXPECT_NEAR(v.inv_w, 0.1, 32 * kFloatUnitRoundoff * 0.1);
}

}  // namespace
}  // namespace edgewise::test
