// Every ISA's answers against the reference's and against brute-force oracles: a rectangle's
// samples read one by one, and a box's twelve faces drawn with depth test less
// (OcclusionBuffer::test_triangles(), draw() itself). EDGEWISE_FUZZ_ITERS sets the rectangles
// per ISA (default 1,000,000), EDGEWISE_FUZZ_SEED the seed.
#include <gtest/gtest.h>

#include <cstdint>
#include <vector>

#include "edgewise/occlusion.hpp"
#include "env_number.hpp"
#include "isa_params.hpp"
#include "occlusion/occlusion_scenes.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

constexpr std::int32_t kOracleWidth = 160, kOracleHeight = 120;

// Visible when a sample whose centre lies in the closed rectangle holds a depth above the
// rectangle's; outside when there is no such centre in the view or the depth lies beyond 1.
Visibility brute_force_rect(const std::vector<float>& depth, const OcclusionRect& r) {
  if (r.depth > 1.0f) return Visibility::outside;
  bool any_sample = false;
  for (std::int32_t y = 0; y < kOracleHeight; ++y) {
    const double cy = y + 0.5;
    if (cy < r.y0 || cy > r.y1) continue;
    for (std::int32_t x = 0; x < kOracleWidth; ++x) {
      const double cx = x + 0.5;
      if (cx < r.x0 || cx > r.x1) continue;
      any_sample = true;
      if (depth[static_cast<std::size_t>(y) * kOracleWidth + x] > r.depth)
        return Visibility::visible;
    }
  }
  return any_sample ? Visibility::occluded : Visibility::outside;
}

class OcclusionOracle : public IsaTest {};

// The rectangle test is exact for its closed rectangle: every answer equals the brute force's.
// A rectangle drawn as two triangles covers a subset of those samples (the fill rule leaves out
// its right and bottom edges), so no rectangle is called occluded that such a draw would show.
TEST_P(OcclusionOracle, RectanglesEqualTheirSamplesBruteForce) {
  const std::uint64_t seed = env_number("EDGEWISE_FUZZ_SEED", 0x0cc1);
  const int count = static_cast<int>(env_number("EDGEWISE_FUZZ_ITERS", 1000000));
  Random random(seed);
  OcclusionBuffer buffer(kOracleWidth, kOracleHeight);
  std::vector<float> depth(static_cast<std::size_t>(kOracleWidth) * kOracleHeight);
  std::vector<OcclusionRect> rects;
  std::vector<Visibility> answers;
  std::uint64_t checked = 0, occluded = 0;
  // Several scenes: a rectangle's answer depends on the depths it covers.
  const int scenes = 20;
  for (int scene = 0; scene < scenes; ++scene) {
    buffer.clear();
    const OccluderSoup soup = random_occluders(random, 1 + scene * 4);
    OcclusionOptions options;
    options.isa = isa();
    options.threads = 1;
    buffer.draw_occluders(soup.mesh(), options);
    buffer.read_depth(depth);
    rects = random_rects(random, count / scenes, kOracleWidth, kOracleHeight);
    answers.assign(rects.size(), Visibility::visible);
    buffer.test_rects(rects, answers, isa());
    for (std::size_t i = 0; i < rects.size(); ++i) {
      const Visibility expected = brute_force_rect(depth, rects[i]);
      ASSERT_EQ(answers[i], expected)
          << "scene " << scene << " rectangle " << i << " [" << rects[i].x0 << ", " << rects[i].x1
          << "] x [" << rects[i].y0 << ", " << rects[i].y1 << "] depth " << rects[i].depth
          << ", seed " << seed;
      occluded += answers[i] == Visibility::occluded;
    }
    checked += rects.size();
  }
  EXPECT_EQ(checked, static_cast<std::uint64_t>(count / scenes) * scenes);
  // The scenes must occlude some rectangles, or the comparison shows little.
  EXPECT_GT(occluded, checked / 20) << "too few occluded rectangles to test";
}

// Boxes: never occluded where their faces drawn show a sample, never outside where the faces
// cover one; every ISA answers as the reference does.
TEST_P(OcclusionOracle, BoxesAreNeverOccludedWhereTheirFacesShow) {
  const std::uint64_t seed = env_number("EDGEWISE_FUZZ_SEED", 0xb0c5);
  const int boxes_per_scene = 2000;
  const int scenes = static_cast<int>(env_number("EDGEWISE_FUZZ_ITERS", 1000000) / 20000) + 1;
  Random random(seed);
  OcclusionBuffer buffer(kOracleWidth, kOracleHeight);
  std::uint64_t occluded = 0, faces_occluded = 0, total = 0;
  for (int scene = 0; scene < scenes; ++scene) {
    buffer.clear();
    OcclusionOptions options;
    options.isa = isa();
    options.threads = 1;
    options.transform = random_camera(random, static_cast<float>(kOracleWidth) / kOracleHeight);
    // Occluders: the faces of a few large boxes.
    std::vector<Vec3> walls;
    for (const OcclusionBox& wall : random_boxes(random, 6)) {
      const std::vector<Vec3> faces = box_faces(wall);
      walls.insert(walls.end(), faces.begin(), faces.end());
    }
    buffer.draw_occluders({walls, {}}, options);
    const std::vector<OcclusionBox> boxes = random_boxes(random, boxes_per_scene);
    std::vector<Visibility> answers(boxes.size()), reference(boxes.size());
    buffer.test_boxes(boxes, options.transform, answers, isa());
    buffer.test_boxes(boxes, options.transform, reference, Isa::reference);
    for (std::size_t i = 0; i < boxes.size(); ++i) {
      ASSERT_EQ(answers[i], reference[i]) << "scene " << scene << " box " << i << ", seed " << seed;
      const std::vector<Vec3> faces = box_faces(boxes[i]);
      const Visibility oracle = buffer.test_triangles({faces, {}}, options);
      if (oracle == Visibility::visible) {
        ASSERT_EQ(answers[i], Visibility::visible)
            << "scene " << scene << " box " << i << ", seed " << seed;
      }
      if (answers[i] == Visibility::outside) {
        ASSERT_EQ(oracle, Visibility::outside)
            << "scene " << scene << " box " << i << ", seed " << seed;
      }
      occluded += answers[i] == Visibility::occluded;
      faces_occluded += oracle == Visibility::occluded;
      ++total;
    }
  }
  // Most boxes the faces' draw finds hidden are found hidden from the bounds too; far fewer
  // would mean the bounds lost their use (the share is in docs/design/occlusion.md).
  EXPECT_GT(occluded, faces_occluded / 2) << occluded << " of " << faces_occluded;
  RecordProperty("boxes", static_cast<int>(total));
  RecordProperty("occluded", static_cast<int>(occluded));
  RecordProperty("faces_occluded", static_cast<int>(faces_occluded));
}

INSTANTIATE_TEST_SUITE_P(Isas, OcclusionOracle, ::testing::ValuesIn(every_isa()), isa_test_name);

}  // namespace
}  // namespace edgewise::test
