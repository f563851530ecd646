// The built-in views: the ground plane fills the screen up to just below the horizon, with far
// rows of high anisotropy and large footprints (the ranges are printed); the magnification view
// magnifies everywhere and stays inside the texture.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdio>
#include <limits>
#include <numbers>
#include <stdexcept>

#include "texture_scene/builtin_views.hpp"
#include "texture_scene/footprint.hpp"

namespace edgewise::texture_scene {
namespace {

struct Range {
  double low = std::numeric_limits<double>::infinity();
  double high = -std::numeric_limits<double>::infinity();
  void add(double value) {
    low = std::min(low, value);
    high = std::max(high, value);
  }
};

struct RowRanges {
  Range anisotropy, axis_ratio, lambda, major, minor;
  void add(const FootprintShape& shape) {
    anisotropy.add(shape.anisotropy);
    axis_ratio.add(shape.axis_ratio);
    lambda.add(shape.lambda);
    major.add(shape.major_texels);
    minor.add(shape.minor_texels);
  }
};

RowRanges row_ranges(const TextureView& view, std::int32_t row, std::int32_t texture_size) {
  RowRanges ranges;
  for (std::int32_t i = 0; i < view.width(); ++i)
    ranges.add(footprint_shape(view.jacobian(i + 0.5, row + 0.5), texture_size, texture_size));
  return ranges;
}

void print(const char* name, const RowRanges& r) {
  std::printf(
      "  %-7s anisotropy %6.2f..%6.2f  Pmax/Pmin %6.2f..%6.2f  lambda %6.2f..%6.2f  "
      "axes %8.3f..%8.3f x %7.3f..%7.3f texels\n",
      name, r.anisotropy.low, r.anisotropy.high, r.axis_ratio.low, r.axis_ratio.high, r.lambda.low,
      r.lambda.high, r.major.low, r.major.high, r.minor.low, r.minor.high);
}

TEST(GroundPlaneView, HorizonJustAboveTheTopEdge) {
  for (auto [width, height] : {std::pair{1920, 1080}, std::pair{480, 270}, std::pair{31, 17}}) {
    const TextureView view = ground_plane_view(width, height);
    const ProjectiveMap& map = view.map();
    // w depends on y only, and vanishes at the horizon.
    ASSERT_EQ(map.w_row[0], 0.0);
    const double horizon = -map.w_row[2] / map.w_row[1];
    EXPECT_LT(horizon, 0.0);
    // 2.5 degrees above the top edge with a 45-degree field of view: 6.3% of the height.
    EXPECT_GT(horizon, -0.1 * height);
    EXPECT_NEAR(horizon / height,
                0.5 * (1.0 - std::tan(25.0 * std::numbers::pi / 180.0) /
                                 std::tan(22.5 * std::numbers::pi / 180.0)),
                1e-12);
  }
}

TEST(GroundPlaneView, FarRowsAreHighlyAnisotropic) {
  constexpr std::int32_t kTexture = 1024;
  for (auto [width, height] : {std::pair{1920, 1080}, std::pair{480, 270}}) {
    const TextureView view = ground_plane_view(width, height);
    RowRanges all;
    for (std::int32_t j = 0; j < height; ++j) {
      for (std::int32_t i = 0; i < width; ++i)
        all.add(footprint_shape(view.jacobian(i + 0.5, j + 0.5), kTexture, kTexture));
    }
    const RowRanges top = row_ranges(view, 0, kTexture);
    const RowRanges bottom = row_ranges(view, height - 1, kTexture);
    std::printf("ground plane %dx%d, %dx%d texture:\n", width, height, kTexture, kTexture);
    print("all", all);
    print("top", top);
    print("bottom", bottom);
    // Far rows: anisotropy beyond 16 (21 at the centre, 30 in the corners) over many texels.
    EXPECT_GT(top.anisotropy.low, 16.0);
    EXPECT_GT(top.major.low, 64.0);
    // Near rows: nearly isotropic, up to about 2 in the corners, seen obliquely.
    EXPECT_LT(bottom.anisotropy.high, 2.5);
    // On the centre column, a pixel whose ray is b from the optical axis sees the plane a =
    // theta + b below the horizon (theta = 22.5 + 2.5 degrees, the pitch): its vertical angular
    // size is cos(b)^2 / F, its horizontal one cos(b) / F, and the plane stretches the vertical
    // one by 1 / sin(a), so the anisotropy is exactly cos(b) / sin(a) (1.25 at the bottom, 21 at
    // the top), growing toward the horizon.
    const double focal = (height / 2.0) / std::tan(22.5 * std::numbers::pi / 180.0);
    const double pitch = 25.0 * std::numbers::pi / 180.0;
    for (std::int32_t j = 0; j < height; ++j) {
      const double b = std::atan((j + 0.5 - height / 2.0) / focal);
      const double expected = std::cos(b) / std::sin(pitch + b);
      const double a =
          footprint_shape(view.jacobian(width / 2.0, j + 0.5), kTexture, kTexture).anisotropy;
      ASSERT_NEAR(a, expected, 1e-9 * expected) << "row " << j;
    }
  }
  // Footprints scale with 1 / screen size: the near rows magnify at 1920 x 1080.
  const TextureView full = ground_plane_view(1920, 1080);
  EXPECT_LT(row_ranges(full, 1079, kTexture).lambda.high, 0.0);
}

TEST(GroundPlaneView, RejectsBadOptions) {
  EXPECT_THROW(ground_plane_view(0, 10), std::invalid_argument);
  const auto with = [](auto change) {
    GroundPlaneOptions options;
    change(options);
    return options;
  };
  const GroundPlaneOptions bad[] = {
      with([](auto& o) { o.camera_height = 0.0; }),
      with([](auto& o) { o.texture_period = -1.0; }),
      with([](auto& o) { o.vertical_fov_degrees = 0.0; }),
      with([](auto& o) { o.vertical_fov_degrees = 180.0; }),
      with([](auto& o) { o.top_below_horizon_degrees = 0.0; }),
      with([](auto& o) { o.top_below_horizon_degrees = 70.0; }),  // the view would look past
                                                                  // straight down
      with([](auto& o) { o.yaw_degrees = std::numeric_limits<double>::quiet_NaN(); }),
  };
  for (const GroundPlaneOptions& options : bad)
    EXPECT_THROW(ground_plane_view(64, 36, options), std::invalid_argument);
}

TEST(MagnificationView, EveryPixelMagnifiesInsideTheTexture) {
  for (auto [width, height] :
       {std::pair{1920, 1080}, std::pair{480, 270}, std::pair{64, 36}, std::pair{32, 18}}) {
    for (std::int32_t texture : {1024, 64}) {
      const TextureView view = magnification_view(width, height, texture, texture);
      RowRanges all;
      double s_low = 1.0, s_high = 0.0, t_low = 1.0, t_high = 0.0;
      for (std::int32_t j = 0; j < height; ++j) {
        for (std::int32_t i = 0; i < width; ++i) {
          all.add(footprint_shape(view.jacobian(i + 0.5, j + 0.5), texture, texture));
        }
      }
      // The corners bound the region (each coordinate is monotone along screen lines).
      for (double x : {0.0, double(width)}) {
        for (double y : {0.0, double(height)}) {
          const TexturePoint p = view.point(x, y);
          s_low = std::min(s_low, p.s), s_high = std::max(s_high, p.s);
          t_low = std::min(t_low, p.t), t_high = std::max(t_high, p.t);
        }
      }
      if (width == 1920 && texture == 1024) print("magnify", all);
      // Well under a texel per pixel: 6 texels over the width, stretched by up to 1 / 0.875^2
      // where the perspective denominator is smallest, and a little more from its change along y.
      EXPECT_LT(all.major.high, 8.5 / width) << width << "x" << height << " texture " << texture;
      EXPECT_LT(all.major.high, 0.3);
      EXPECT_LT(all.anisotropy.high, 1.5);
      // A few texels across, two or more texels from the border: every wrap mode agrees.
      EXPECT_GT(s_low * texture, 2.0);
      EXPECT_LT(s_high * texture, texture - 2.0);
      EXPECT_GT(t_low * texture, 2.0);
      EXPECT_LT(t_high * texture, texture - 2.0);
      EXPECT_GT((s_high - s_low) * texture, 5.0);
      EXPECT_LT((s_high - s_low) * texture, 10.0);
    }
  }
}

TEST(MagnificationView, RejectsBadOptions) {
  EXPECT_THROW(magnification_view(64, 36, 0, 64), std::invalid_argument);
  EXPECT_THROW(magnification_view(0, 36, 64, 64), std::invalid_argument);
  MagnificationOptions options;
  options.texels_across = 0.0;
  EXPECT_THROW(magnification_view(64, 36, 64, 64, options), std::invalid_argument);
  options = {};
  options.perspective = 1.5;
  EXPECT_THROW(magnification_view(64, 36, 64, 64, options), std::invalid_argument);
  options = {};
  options.rotation_degrees = std::numeric_limits<double>::infinity();
  EXPECT_THROW(magnification_view(64, 36, 64, 64, options), std::invalid_argument);
}

}  // namespace
}  // namespace edgewise::texture_scene
