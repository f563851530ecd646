// The tool computes ground truth in bands of rows (to show its progress): the result must be the
// single ground_truth() call's, bit for bit, whatever the band height.
#include <gtest/gtest.h>

#include <stdexcept>
#include <vector>

#include "texture_quality/ground_truth_store.hpp"
#include "texture_scene/builtin_views.hpp"
#include "texture_scene/ground_truth.hpp"
#include "texture_scene/procedural_textures.hpp"
#include "texture_scene/same_ground_truth.hpp"

namespace edgewise::texture_quality {
namespace {

TEST(BandedGroundTruth, EqualsOneCallForAnyBandHeight) {
  const texture_scene::LinearImage texture = texture_scene::checkerboard(64, 8);
  const texture_scene::TextureView view = texture_scene::ground_plane_view(1920, 1080);
  // Rows near the horizon, where pixels need the largest grids, and a height no band divides.
  const texture_scene::ScreenRegion region{940, 560, 12, 23};
  const texture_scene::GroundTruthOptions options;
  const texture_scene::GroundTruth whole = texture_scene::ground_truth(
      texture, WrapMode::repeat, WrapMode::repeat, view, region, options);
  for (std::int32_t rows : {1, 5, 8, 23, 40}) {
    SCOPED_TRACE(rows);
    const texture_scene::GroundTruth banded =
        banded_ground_truth(texture, view, region, options, rows);
    texture_scene::expect_same_result(banded, whole);
  }
}

TEST(BandedGroundTruth, RejectsAnEmptyBand) {
  const texture_scene::LinearImage texture = texture_scene::checkerboard(8, 2);
  const texture_scene::TextureView view = texture_scene::ground_plane_view(64, 36);
  EXPECT_THROW(banded_ground_truth(texture, view, {0, 0, 4, 4}, {}, 0), std::invalid_argument);
}

}  // namespace
}  // namespace edgewise::texture_quality
