// The tool computes ground truth in bands of rows (to show its progress): the result must be the
// single ground_truth() call's, bit for bit, whatever the band height.
#include <gtest/gtest.h>

#include <cstring>
#include <stdexcept>
#include <vector>

#include "texture_quality/ground_truth_store.hpp"
#include "texture_scene/builtin_views.hpp"
#include "texture_scene/ground_truth.hpp"
#include "texture_scene/procedural_textures.hpp"

namespace edgewise::texture_quality {
namespace {

using texture_scene::GroundTruth;

bool same_bits(const std::vector<float>& a, const std::vector<float>& b) {
  return a.size() == b.size() && std::memcmp(a.data(), b.data(), a.size() * sizeof(float)) == 0;
}

TEST(BandedGroundTruth, EqualsOneCallForAnyBandHeight) {
  const texture_scene::LinearImage texture = texture_scene::checkerboard(64, 8);
  const texture_scene::TextureView view = texture_scene::ground_plane_view(1920, 1080);
  // Rows near the horizon, where pixels need the largest grids, and a height no band divides.
  const texture_scene::ScreenRegion region{940, 560, 12, 23};
  const texture_scene::GroundTruthOptions options;
  const GroundTruth whole = texture_scene::ground_truth(texture, WrapMode::repeat, WrapMode::repeat,
                                                        view, region, options);
  for (std::int32_t rows : {1, 5, 8, 23, 40}) {
    SCOPED_TRACE(rows);
    const GroundTruth banded = banded_ground_truth(texture, view, region, options, rows);
    EXPECT_TRUE(same_bits(banded.image.rgba, whole.image.rgba));
    EXPECT_EQ(banded.grid, whole.grid);
    EXPECT_EQ(banded.report.pixels, whole.report.pixels);
    EXPECT_EQ(banded.report.capped_pixels, whole.report.capped_pixels);
    EXPECT_EQ(banded.report.samples, whole.report.samples);
    EXPECT_EQ(banded.report.largest_grid, whole.report.largest_grid);
    EXPECT_EQ(banded.report.worst_capped_change, whole.report.worst_capped_change);
    EXPECT_EQ(banded.report.worst_converged_change, whole.report.worst_converged_change);
  }
}

TEST(BandedGroundTruth, RejectsAnEmptyBand) {
  const texture_scene::LinearImage texture = texture_scene::checkerboard(8, 2);
  const texture_scene::TextureView view = texture_scene::ground_plane_view(64, 36);
  EXPECT_THROW(banded_ground_truth(texture, view, {0, 0, 4, 4}, {}, 0), std::invalid_argument);
}

}  // namespace
}  // namespace edgewise::texture_quality
