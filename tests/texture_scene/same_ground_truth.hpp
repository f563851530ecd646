// Whether two ground truths are the same result, bit for bit: region, image, grid and report
// (all but the time it took, which no two computations share).
#pragma once

#include <gtest/gtest.h>

#include <cstring>

#include "texture_scene/ground_truth.hpp"

namespace edgewise::texture_scene {

inline void expect_same_result(const GroundTruth& a, const GroundTruth& b) {
  EXPECT_EQ(a.region.x0, b.region.x0);
  EXPECT_EQ(a.region.y0, b.region.y0);
  EXPECT_EQ(a.region.width, b.region.width);
  EXPECT_EQ(a.region.height, b.region.height);
  ASSERT_EQ(a.image.rgba.size(), b.image.rgba.size());
  EXPECT_EQ(
      std::memcmp(a.image.rgba.data(), b.image.rgba.data(), a.image.rgba.size() * sizeof(float)),
      0);
  EXPECT_EQ(a.grid, b.grid);
  EXPECT_EQ(a.report.pixels, b.report.pixels);
  EXPECT_EQ(a.report.capped_pixels, b.report.capped_pixels);
  EXPECT_EQ(a.report.worst_capped_change, b.report.worst_capped_change);
  EXPECT_EQ(a.report.worst_converged_change, b.report.worst_converged_change);
  EXPECT_EQ(a.report.largest_grid, b.report.largest_grid);
  EXPECT_EQ(a.report.samples, b.report.samples);
}

}  // namespace edgewise::texture_scene
