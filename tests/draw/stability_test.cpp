// Stability of the fast paths' documented safe ranges (docs/method-atlas.md, "Safe ranges"):
// each test pins a regime the method atlas charts, and fails if the code moves it.
// - Affine weights: never further from the perspective-correct colour than the derived bound
//   (interpolation/affine_error_bound.hpp) plus the 8-bit rounding, at every depth range; and the
//   bound is reached, so the safe depth range it gives for a tolerance is not pessimistic by more
//   than a little.
// - Depth: the separation of two surfaces that float32 z/w and reversed z/w resolve at half the
//   far distance, for far / near = 1000.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "edgewise/edgewise.hpp"
#include "draw_probes.hpp"
#include "random.hpp"
#include "interpolation/affine_error_bound.hpp"

namespace edgewise {
namespace {

constexpr int kSize = 256;

std::vector<std::uint8_t> draw_rgba(const std::vector<Vec3>& positions,
                                    const std::vector<Vec4>& colours, Perspective perspective) {
  Framebuffer target(kSize, kSize);
  target.clear({0, 0, 0, 0}, 1.0f);
  DrawOptions options;
  options.transform = probes::clip_from_xyw();
  options.depth_test = DepthTest::always;
  options.perspective = perspective;
  options.threads = 1;
  DrawMesh mesh;
  mesh.positions = positions;
  mesh.colors = colours;
  draw(target, mesh, options);
  std::vector<std::uint8_t> rgba(std::size_t{kSize} * kSize * 4);
  target.read_rgba8(rgba);
  return rgba;
}

// The largest difference between affine and perspective-correct colours, in 8-bit codes, over
// triangles drawn one at a time whose vertices have w of 1, `ratio` and one between; and the
// largest value the bound gives for them (in codes).
struct AffineGap {
  int worst_codes = 0;
  double bound_codes = 0.0;
};

AffineGap affine_gap(double ratio, int triangles, std::uint64_t seed) {
  test::Random random(seed);
  AffineGap gap;
  for (int t = 0; t < triangles; ++t) {
    std::vector<Vec3> positions;
    std::vector<Vec4> colours;
    const double ws[3] = {1.0, ratio, random.uniform(1.0, ratio)};
    float low = 1.0f, high = 0.0f;
    for (int i = 0; i < 3; ++i) {
      const double sx = random.uniform(16.0, kSize - 16.0), sy = random.uniform(16.0, kSize - 16.0);
      const auto w = static_cast<float>(ws[i]);
      positions.push_back(
          probes::xyw_position(static_cast<float>(sx), static_cast<float>(sy), w, kSize, kSize));
      // Red from 0 to 1 across the vertices (range 1): the bound's worst case.
      const float red = i == 0 ? 0.0f : (i == 1 ? 1.0f : static_cast<float>(random.uniform()));
      colours.push_back({red, 0.5f, 0.5f, 1.0f});
      low = std::min(low, red);
      high = std::max(high, red);
    }
    const auto affine = draw_rgba(positions, colours, Perspective::affine);
    const auto correct = draw_rgba(positions, colours, Perspective::correct);
    for (std::size_t i = 0; i < affine.size(); i += 4)
      gap.worst_codes = std::max(gap.worst_codes, std::abs(int(affine[i]) - int(correct[i])));
    gap.bound_codes = std::max(
        gap.bound_codes,
        255.0 * (high - low) *
            detail::affine_weight_error_bound(1.0, static_cast<float>(ratio)));  // w as drawn
  }
  return gap;
}

TEST(Stability, AffineWeightsStayWithinTheirBoundAtEveryDepthRange) {
  for (double ratio : {1.001, 1.0158, 1.1, 2.0, 4.0, 10.0, 100.0, 1e4}) {
    const AffineGap gap = affine_gap(ratio, 24, 0xaff1 + static_cast<std::uint64_t>(ratio * 1000));
    // Each colour is rounded to 8 bits on its own: one code more than the exact gap, and the
    // float32 weights' rounding (below 1e-5 of the range here, tests/draw/colour_bounds.cpp)
    // cannot add another.
    EXPECT_LE(gap.worst_codes, std::floor(gap.bound_codes + 1e-3) + 1) << "w_max / w_min " << ratio;
  }
}

TEST(Stability, AffineBoundIsReached) {
  // Random triangles with vertices at w = 1 and w = 4 and red from 0 to 1 between them: the
  // bound (a third of the range, 85 codes) is met within a few codes somewhere on that edge.
  const AffineGap gap = affine_gap(4.0, 24, 0xaff4);
  EXPECT_NEAR(gap.bound_codes, 85.0, 0.01);
  EXPECT_GE(gap.worst_codes, 70);
}

TEST(Stability, AffineSafeDepthRangeForOneCode) {
  // Within 1/255 for a value range of 1 up to w_max / w_min = ((1 + 1/255) / (1 - 1/255))^2.
  EXPECT_NEAR(detail::affine_safe_depth_ratio(1.0 / 255.0, 1.0), 1.01582, 1e-5);
  EXPECT_LE(
      detail::affine_weight_error_bound(1.0, detail::affine_safe_depth_ratio(1.0 / 255.0, 1.0)),
      1.0 / 255.0 + 1e-12);
  EXPECT_EQ(detail::affine_safe_depth_ratio(2.0, 1.0), INFINITY);
}

bool resolved(bool reverse, float near, float far, float near_plane, float far_plane) {
  return probes::nearer_plane_wins(reverse, near, far, near_plane, far_plane, 32);
}

TEST(Stability, DepthResolutionAtHalfTheFarDistance) {
  // near 0.1, far 100, surfaces at 50: z/w steps by 2^-24 near 1 while z/w changes by
  // near / d^2 per unit of distance, so it resolves about 2^-24 d / near = 3e-5 of the distance
  // and not 1e-6; reversed z/w resolves 1e-6 (its values near 0 keep float32's relative step).
  // The atlas's depth study charts the whole range.
  const float d = 50.0f;
  for (float separation : {1e-4f, 3e-4f}) {
    EXPECT_TRUE(resolved(false, 0.1f, 100.0f, d, d * (1.0f + separation))) << separation;
  }
  EXPECT_FALSE(resolved(false, 0.1f, 100.0f, d, d * (1.0f + 1e-6f)));
  EXPECT_TRUE(resolved(true, 0.1f, 100.0f, d, d * (1.0f + 1e-6f)));
}

}  // namespace
}  // namespace edgewise
