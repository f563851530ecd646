// The ground-truth evaluator: exact on a constant texture, the analytic average of a linear
// ramp under an affine and under a perspective view, its convergence rule on the hard part of
// the ground plane, capped pixels reported, and the same result on any number of threads.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <stdexcept>

#include "texture_scene/builtin_views.hpp"
#include "texture_scene/ground_truth.hpp"
#include "texture_scene/procedural_textures.hpp"
#include "texture_scene/wrap_modes.hpp"

namespace edgewise::texture_scene {
namespace {

constexpr double kFloatRounding = 0x1.0p-24;  // relative, storing a result as float

TEST(GroundTruth, ConstantTextureGivesExactlyTheConstant) {
  // The lerp form returns a constant's texels exactly, n^2 copies of a float sum exactly in
  // double (n^2 <= 2^22, 24 significant bits each), and dividing by n^2 (a power of two) is exact.
  LinearImage texture = LinearImage::filled(7, 5, 0.0f);
  const float constant[4] = {0.3f, 0.7f, 1.0f / 3.0f, 1.0f};
  for (std::int32_t b = 0; b < 5; ++b)
    for (std::int32_t a = 0; a < 7; ++a)
      for (int c = 0; c < 4; ++c)
        texture.texel(a, b)[c] = constant[c];
  const TextureView ground = ground_plane_view(1920, 1080);
  const TextureView magnify = magnification_view(64, 36, 7, 5);
  for (WrapMode wrap : kWrapModes) {
    for (const auto& [view, region] : {std::pair{&ground, ScreenRegion{900, 0, 6, 3}},
                                       std::pair{&ground, ScreenRegion{0, 1077, 4, 3}},
                                       std::pair{&magnify, ScreenRegion{30, 15, 5, 4}}}) {
      const GroundTruth truth = ground_truth(texture, wrap, wrap, *view, region);
      for (std::int32_t y = 0; y < region.height; ++y) {
        for (std::int32_t x = 0; x < region.width; ++x) {
          for (int c = 0; c < 4; ++c)
            ASSERT_EQ(truth.image.texel(x, y)[c], constant[c]);
        }
      }
      // The first doubling changes nothing.
      EXPECT_EQ(truth.report.largest_grid, 8);
      EXPECT_EQ(truth.report.worst_converged_change, 0.0);
      EXPECT_EQ(truth.report.capped_pixels, 0);
    }
  }
}

// A 64 x 64 texture whose value is linear in the texel index, alpha + beta a + gamma b (exact in
// float). Between texel centres its bilinear reconstruction is the same linear function of
// (u, v) = (s W - 0.5, t H - 0.5), so inside [0, 63]^2 clamping changes nothing.
struct Ramp {
  static constexpr double alpha = 0.0625, beta = 1.0 / 128.0, gamma = 1.0 / 256.0;
  LinearImage texture = LinearImage::filled(64, 64, 1.0f);
  Ramp() {
    for (std::int32_t b = 0; b < 64; ++b)
      for (std::int32_t a = 0; a < 64; ++a)
        for (int c = 0; c < 3; ++c)
          texture.texel(a, b)[c] = static_cast<float>((c + 1) * (alpha + beta * a + gamma * b));
  }
  // Channel c's value at texel-space point (u, v).
  static double value(int c, double u, double v) {
    return (c + 1) * (alpha + beta * u + gamma * v);
  }
};

TEST(GroundTruth, RampUnderAffineViewIsTheCentreValue) {
  // Affine view: the ramp is linear over each pixel, so its average is its value at the centre,
  // and the midpoint grid reproduces that up to rounding (float storage dominates).
  const Ramp ramp;
  const ProjectiveMap map{
      {2.0 / 64, -0.5 / 64, 14.0 / 64}, {0.5 / 64, 1.75 / 64, 2.0 / 64}, {0.0, 0.0, 1.0}};
  const TextureView view(20, 20, map);  // u, v (texels) stay in [1.5, 53.5]
  const ScreenRegion region{0, 0, 20, 20};
  const GroundTruth truth =
      ground_truth(ramp.texture, WrapMode::clamp_to_edge, WrapMode::clamp_to_edge, view, region);
  for (std::int32_t y = 0; y < 20; ++y) {
    for (std::int32_t x = 0; x < 20; ++x) {
      const TexturePoint p = view.point(x + 0.5, y + 0.5);
      for (int c = 0; c < 3; ++c) {
        const double expected = Ramp::value(c, p.s * 64 - 0.5, p.t * 64 - 0.5);
        // Float storage, plus double rounding of the 64 grid sums (far below).
        ASSERT_NEAR(truth.image.texel(x, y)[c], expected, kFloatRounding * expected + 1e-12)
            << x << "," << y << " channel " << c;
      }
      EXPECT_EQ(truth.image.texel(x, y)[3], 1.0f);
    }
  }
  EXPECT_EQ(truth.report.capped_pixels, 0);
}

TEST(GroundTruth, RampUnderPerspectiveViewMatchesTheAnalyticAverage) {
  // w = h y + k depends on y only, so along x the ramp is linear (exact for the midpoint grid)
  // and the average is the 1D one of G(y) = P + (A y + B) / (h y + k) over [j, j + 1]:
  //   A / h + (B - A k / h) / h ln(1 + h / (h j + k)).
  // The composite midpoint rule with n cells errs by at most max|G''| / (24 n^2), with
  // G'' = 2 (B - A k / h) h^2 / (h y + k)^3, largest where w is smallest (y = j).
  const Ramp ramp;
  const double h = 0.5 / 16, k = 1.0;  // w from 1 to 1.5 over 16 rows
  const ProjectiveMap map{
      {3.0 / 64, 0.5 / 64, 2.0 / 64}, {0.8 / 64, 2.5 / 64, 3.0 / 64}, {0.0, h, k}};
  const TextureView view(16, 16, map);  // u, v (texels) stay in [1.5, 49.5]
  const GroundTruth truth = ground_truth(ramp.texture, WrapMode::clamp_to_edge,
                                         WrapMode::clamp_to_edge, view, view.screen());
  double worst_error = 0.0, worst_bound = 0.0;
  for (std::int32_t j = 0; j < 16; ++j) {
    for (std::int32_t i = 0; i < 16; ++i) {
      const std::int32_t n = truth.grid[static_cast<std::size_t>(j) * 16 + i];
      const double xc = i + 0.5;
      for (int c = 0; c < 3; ++c) {
        // value = (c+1) (alpha - beta/2 - gamma/2 + (beta s_num + gamma t_num) 64 / w).
        const double scale = c + 1;
        const double p = scale * (Ramp::alpha - Ramp::beta / 2 - Ramp::gamma / 2);
        const double a = scale * 64 * (Ramp::beta * map.s_row[1] + Ramp::gamma * map.t_row[1]);
        const double b = scale * 64 *
                         (Ramp::beta * (map.s_row[0] * xc + map.s_row[2]) +
                          Ramp::gamma * (map.t_row[0] * xc + map.t_row[2]));
        const double rest = b - a * k / h;
        const double average = p + a / h + rest / h * std::log1p(h / (h * j + k));
        const double second_derivative = 2.0 * std::abs(rest) * h * h / std::pow(h * j + k, 3);
        const double bound =
            second_derivative / (24.0 * n * n) + kFloatRounding * std::abs(average) + 1e-12;
        const double error = std::abs(truth.image.texel(i, j)[c] - average);
        ASSERT_LE(error, bound) << i << "," << j << " channel " << c << " n " << n;
        worst_error = std::max(worst_error, error);
        worst_bound = std::max(worst_bound, bound);
      }
    }
  }
  std::printf("perspective ramp: worst error %.3g, worst bound %.3g (tolerance 1e-4)\n",
              worst_error, worst_bound);
  // The convergence rule stopped where the quadrature bound was already below the tolerance.
  EXPECT_LT(worst_bound, 1e-4);
  EXPECT_EQ(truth.report.capped_pixels, 0);
}

// The stopping rule on the ground plane's far rows (many texture edges per footprint) and near
// rows: every pixel converged, and one more doubling beyond each pixel's final grid still
// changes it by less than the tolerance.
TEST(GroundTruth, ConvergenceRuleHoldsOnTheGroundPlane) {
  const LinearImage texture = checkerboard(256, 16);
  const TextureView view = ground_plane_view(1920, 1080);
  const BilinearReconstruction reconstruction(texture, WrapMode::repeat, WrapMode::repeat);
  for (const ScreenRegion region :
       {ScreenRegion{1000, 0, 8, 3}, ScreenRegion{37, 2, 4, 2}, ScreenRegion{1500, 1076, 8, 4}}) {
    const GroundTruthOptions options;
    const GroundTruth truth =
        ground_truth(texture, WrapMode::repeat, WrapMode::repeat, view, region, options);
    EXPECT_EQ(truth.report.pixels, std::int64_t{region.width} * region.height);
    EXPECT_EQ(truth.report.capped_pixels, 0);
    EXPECT_LT(truth.report.worst_converged_change, options.tolerance);
    std::int64_t samples = 0;
    for (std::int32_t y = 0; y < region.height; ++y) {
      for (std::int32_t x = 0; x < region.width; ++x) {
        const std::int32_t n = truth.grid[static_cast<std::size_t>(y) * region.width + x];
        // Grids run 4, 8, ..., n: the samples add up to the report's.
        for (std::int32_t m = options.initial_grid; m <= n; m *= 2)
          samples += std::int64_t{m} * m;
        double finer[4];
        pixel_average(reconstruction, view, region.x0 + x, region.y0 + y, 2 * n, finer);
        for (int c = 0; c < 4; ++c) {
          EXPECT_LT(std::abs(finer[c] - truth.image.texel(x, y)[c]), options.tolerance)
              << "pixel " << region.x0 + x << "," << region.y0 + y << " n " << n;
        }
      }
    }
    EXPECT_EQ(samples, truth.report.samples);
    std::printf("region (%d, %d) %dx%d: largest grid %d, worst last change %.3g, %.3f s\n",
                region.x0, region.y0, region.width, region.height, truth.report.largest_grid,
                truth.report.worst_converged_change, truth.report.seconds);
  }
}

TEST(GroundTruth, CappedPixelsAreReported) {
  // Far-row pixels straddle many checkerboard edges: an 8 x 8 grid cannot converge there.
  const LinearImage texture = checkerboard(256, 16);
  const TextureView view = ground_plane_view(1920, 1080);
  GroundTruthOptions options;
  options.max_grid = 8;
  const GroundTruth truth =
      ground_truth(texture, WrapMode::repeat, WrapMode::repeat, view, {1000, 0, 8, 2}, options);
  EXPECT_GT(truth.report.capped_pixels, 0);
  EXPECT_GE(truth.report.worst_capped_change, options.tolerance);
  EXPECT_EQ(truth.report.largest_grid, 8);
  // A cap equal to the initial grid allows no comparison: every pixel is capped.
  options.max_grid = options.initial_grid;
  const GroundTruth single =
      ground_truth(texture, WrapMode::repeat, WrapMode::repeat, view, {0, 1079, 3, 1}, options);
  EXPECT_EQ(single.report.capped_pixels, 3);
  EXPECT_EQ(single.report.worst_capped_change, std::numeric_limits<double>::infinity());
}

TEST(GroundTruth, SameResultOnAnyNumberOfThreads) {
  const LinearImage texture = sinusoids(128);
  const TextureView view = ground_plane_view(480, 270);
  const ScreenRegion region{200, 0, 16, 5};
  GroundTruthOptions one, three;
  one.threads = 1;
  three.threads = 3;
  const GroundTruth a =
      ground_truth(texture, WrapMode::repeat, WrapMode::mirror, view, region, one);
  const GroundTruth b =
      ground_truth(texture, WrapMode::repeat, WrapMode::mirror, view, region, three);
  EXPECT_EQ(a.image.rgba, b.image.rgba);
  EXPECT_EQ(a.grid, b.grid);
  EXPECT_EQ(a.report.samples, b.report.samples);
}

TEST(GroundTruth, RejectsBadArguments) {
  const LinearImage texture = checkerboard(16, 2);
  const TextureView view = ground_plane_view(32, 18);
  const auto run = [&](const ScreenRegion& region, const GroundTruthOptions& options) {
    return ground_truth(texture, WrapMode::repeat, WrapMode::repeat, view, region, options);
  };
  EXPECT_THROW(run({30, 0, 3, 1}, {}), std::invalid_argument);
  EXPECT_THROW(run({0, 0, 0, 1}, {}), std::invalid_argument);
  const auto with = [](auto change) {
    GroundTruthOptions options;
    change(options);
    return options;
  };
  const GroundTruthOptions bad[] = {
      with([](auto& o) { o.tolerance = 0.0; }),
      with([](auto& o) { o.tolerance = std::nan(""); }),
      with([](auto& o) { o.initial_grid = 0; }),
      with([](auto& o) { o.max_grid = 2; }),
      with([](auto& o) { o.max_grid = 24; }),  // not 4 times a power of two
      with([](auto& o) { o.max_grid = 1 << 17; }),
      with([](auto& o) { o.threads = -1; }),
  };
  for (const GroundTruthOptions& options : bad)
    EXPECT_THROW(run({0, 0, 2, 2}, options), std::invalid_argument);
  const BilinearReconstruction reconstruction(texture, WrapMode::repeat, WrapMode::repeat);
  double out[4];
  EXPECT_THROW(pixel_average(reconstruction, view, 32, 0, 4, out), std::invalid_argument);
  EXPECT_THROW(pixel_average(reconstruction, view, 0, 0, 0, out), std::invalid_argument);
  EXPECT_THROW(ground_truth(LinearImage{}, WrapMode::repeat, WrapMode::repeat, view, {0, 0, 1, 1}),
               std::invalid_argument);
}

}  // namespace
}  // namespace edgewise::texture_scene
