// The occlusion buffer's contract: its depth is draw()'s, queries answer the hand cases their
// rules give, bad input is refused by name.
#include <gtest/gtest.h>

#include <bit>
#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "edgewise/draw.hpp"
#include "edgewise/occlusion.hpp"
#include "isa_params.hpp"
#include "occlusion/occlusion_scenes.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

constexpr std::int32_t kWidth = 96, kHeight = 64;

// A quad over the whole view at depth z (clip space, w = 1).
std::vector<Vec3> screen_quad(float z) {
  return {{-1.0f, -1.0f, z}, {1.0f, -1.0f, z}, {1.0f, 1.0f, z},
          {-1.0f, -1.0f, z}, {1.0f, 1.0f, z},  {-1.0f, 1.0f, z}};
}

class OcclusionApi : public IsaTest {
 protected:
  OcclusionOptions options(std::size_t threads = 1) const {
    OcclusionOptions o;
    o.isa = isa();
    o.threads = threads;
    return o;
  }
};

TEST_P(OcclusionApi, DepthIsDrawsBitForBitOnEveryThreadCount) {
  Random random(7);
  const OccluderSoup soup = random_occluders(random, 300);
  Framebuffer expected(kWidth, kHeight);
  expected.clear({0.0f, 0.0f, 0.0f, 1.0f}, 1.0f);
  DrawOptions draw_options;
  draw_options.isa = isa();
  draw_options.threads = 1;
  draw(expected, {soup.positions, {}, {}, {}}, draw_options);
  std::vector<float> want(static_cast<std::size_t>(kWidth) * kHeight), got(want.size());
  expected.read_depth(want);
  for (const std::size_t threads : {1u, 2u, 5u}) {
    OcclusionBuffer buffer(kWidth, kHeight);
    const DrawReport report = buffer.draw_occluders(soup.mesh(), options(threads));
    EXPECT_EQ(report.triangles, 302u);  // the backdrop's two and 300
    buffer.read_depth(got);
    for (std::size_t i = 0; i < want.size(); ++i)
      ASSERT_EQ(std::bit_cast<std::uint32_t>(got[i]), std::bit_cast<std::uint32_t>(want[i]))
          << "pixel " << i << " with " << threads << " threads";
  }
}

TEST_P(OcclusionApi, CopiedDepthAnswersAsDrawnOccluders) {
  Random random(11);
  const OccluderSoup soup = random_occluders(random, 200);
  OcclusionBuffer drawn(kWidth, kHeight), copied(kWidth, kHeight);
  drawn.draw_occluders(soup.mesh(), options());
  Framebuffer frame(kWidth, kHeight);
  frame.clear({0.0f, 0.0f, 0.0f, 1.0f}, 1.0f);
  DrawOptions draw_options;
  draw_options.isa = isa();
  draw(frame, {soup.positions, {}, {}, {}}, draw_options);
  copied.copy_depth(frame, options());
  std::vector<float> want(static_cast<std::size_t>(kWidth) * kHeight), got(want.size());
  drawn.read_depth(want);
  copied.read_depth(got);
  EXPECT_EQ(want, got);
  const std::vector<OcclusionRect> rects = random_rects(random, 2000, kWidth, kHeight);
  std::vector<Visibility> from_drawn(rects.size()), from_copied(rects.size());
  drawn.test_rects(rects, from_drawn, isa());
  copied.test_rects(rects, from_copied, isa());
  EXPECT_EQ(from_drawn, from_copied);
  EXPECT_THROW(copied.copy_depth(Framebuffer(kWidth + 1, kHeight)), std::invalid_argument);
  EXPECT_THROW(copied.copy_depth(Framebuffer(kWidth, kHeight, 4)), std::invalid_argument);
}

TEST_P(OcclusionApi, RectanglesAgainstAWall) {
  OcclusionBuffer buffer(kWidth, kHeight);
  const std::vector<OcclusionRect> rects = {
      {10.0f, 10.0f, 20.0f, 20.0f, 0.6f},    // behind the wall
      {10.0f, 10.0f, 20.0f, 20.0f, 0.4f},    // in front of it
      {10.0f, 10.0f, 20.0f, 20.0f, 0.5f},    // at it: less fails
      {200.0f, 10.0f, 300.0f, 20.0f, 0.0f},  // right of the view
      {10.2f, 10.0f, 10.4f, 20.0f, 0.0f},    // between two pixel centres
      {10.0f, 10.0f, 20.0f, 20.0f, 1.5f},    // beyond the far plane
      {-std::numeric_limits<float>::infinity(), 0.0f, std::numeric_limits<float>::infinity(),
       1000.0f, 0.7f},  // the whole view, behind
  };
  std::vector<Visibility> answers(rects.size());
  buffer.test_rects(rects, answers, isa());
  // Nothing drawn: everything in the view is visible.
  EXPECT_EQ(answers[0], Visibility::visible);
  EXPECT_EQ(answers[6], Visibility::visible);
  const std::vector<Vec3> wall = screen_quad(0.5f);
  buffer.draw_occluders({wall, {}}, options());
  buffer.test_rects(rects, answers, isa());
  const Visibility want[] = {Visibility::occluded, Visibility::visible, Visibility::occluded,
                             Visibility::outside,  Visibility::outside, Visibility::outside,
                             Visibility::occluded};
  for (std::size_t i = 0; i < rects.size(); ++i)
    EXPECT_EQ(answers[i], want[i]) << "rectangle " << i;
}

TEST_P(OcclusionApi, RectangleSeesOneNearerSample) {
  // A wall at depth 0.2 with a gap one pixel wide at column 40.
  OcclusionBuffer buffer(kWidth, kHeight);
  const float x0 = 2.0f * 40.0f / kWidth - 1.0f, x1 = 2.0f * 41.0f / kWidth - 1.0f;
  const std::vector<Vec3> left = {{-1.0f, -1.0f, 0.2f}, {x0, -1.0f, 0.2f}, {x0, 1.0f, 0.2f},
                                  {-1.0f, -1.0f, 0.2f}, {x0, 1.0f, 0.2f},  {-1.0f, 1.0f, 0.2f}};
  const std::vector<Vec3> right = {{x1, -1.0f, 0.2f}, {1.0f, -1.0f, 0.2f}, {1.0f, 1.0f, 0.2f},
                                   {x1, -1.0f, 0.2f}, {1.0f, 1.0f, 0.2f},  {x1, 1.0f, 0.2f}};
  buffer.draw_occluders({left, {}}, options());
  buffer.draw_occluders({right, {}}, options());
  // Column 40 is left at the far plane: a rectangle holding its centre sees through.
  // The rectangle is closed: one whose edge passes through the centre holds it.
  std::vector<Visibility> answers(4);
  const std::vector<OcclusionRect> rects = {{30.0f, 20.0f, 50.0f, 40.0f, 0.3f},
                                            {30.0f, 20.0f, 40.4f, 40.0f, 0.3f},
                                            {40.6f, 20.0f, 50.0f, 40.0f, 0.3f},
                                            {40.5f, 20.0f, 40.5f, 40.0f, 0.3f}};
  buffer.test_rects(rects, answers, isa());
  EXPECT_EQ(answers[0], Visibility::visible);
  EXPECT_EQ(answers[1], Visibility::occluded);
  EXPECT_EQ(answers[2], Visibility::occluded);
  EXPECT_EQ(answers[3], Visibility::visible);
}

TEST_P(OcclusionApi, BoxesBehindBesideAndAroundTheCamera) {
  OcclusionBuffer buffer(kWidth, kHeight);
  const Mat4 camera = perspective(1.0f, static_cast<float>(kWidth) / kHeight, 0.5f, 100.0f) *
                      look_at({0.0f, 0.0f, 10.0f}, {0.0f, 0.0f, 0.0f}, {0.0f, 1.0f, 0.0f});
  // A wall at z = 0 much wider than the view.
  const std::vector<Vec3> wall = {{-50.0f, -50.0f, 0.0f}, {50.0f, -50.0f, 0.0f},
                                  {50.0f, 50.0f, 0.0f},   {-50.0f, -50.0f, 0.0f},
                                  {50.0f, 50.0f, 0.0f},   {-50.0f, 50.0f, 0.0f}};
  OcclusionOptions o = options();
  o.transform = camera;
  buffer.draw_occluders({wall, {}}, o);
  const std::vector<OcclusionBox> boxes = {
      {{-1.0f, -1.0f, -3.0f}, {1.0f, 1.0f, -1.0f}},  // behind the wall
      {{-1.0f, -1.0f, 1.0f}, {1.0f, 1.0f, 3.0f}},    // in front of it
      {{-1.0f, -1.0f, -1.0f}, {1.0f, 1.0f, 1.0f}},   // through it
      {{-1.0f, -1.0f, 9.0f}, {1.0f, 1.0f, 11.0f}},   // around the camera
      {{-1.0f, -1.0f, 20.0f}, {1.0f, 1.0f, 22.0f}},  // behind the camera
      {{40.0f, -1.0f, -1.0f}, {41.0f, 1.0f, 1.0f}},  // far beside the view
  };
  std::vector<Visibility> answers(boxes.size());
  buffer.test_boxes(boxes, camera, answers, isa());
  const Visibility want[] = {Visibility::occluded, Visibility::visible, Visibility::visible,
                             Visibility::visible,  Visibility::outside, Visibility::outside};
  for (std::size_t i = 0; i < boxes.size(); ++i) {
    EXPECT_EQ(answers[i], want[i]) << "box " << i;
    // Each agrees with its faces drawn, wherever the bounds decide.
    const std::vector<Vec3> faces = box_faces(boxes[i]);
    const Visibility exact = buffer.test_triangles({faces, {}}, o);
    if (answers[i] != Visibility::visible) {
      EXPECT_EQ(exact, answers[i]) << "box " << i;
    }
  }
}

TEST_P(OcclusionApi, TestTrianglesLeavesTheDepthAlone) {
  OcclusionBuffer buffer(kWidth, kHeight);
  buffer.draw_occluders({screen_quad(0.5f), {}}, options());
  std::vector<float> before(static_cast<std::size_t>(kWidth) * kHeight), after(before.size());
  buffer.read_depth(before);
  EXPECT_EQ(buffer.test_triangles({screen_quad(0.25f), {}}, options()), Visibility::visible);
  EXPECT_EQ(buffer.test_triangles({screen_quad(0.75f), {}}, options()), Visibility::occluded);
  const std::vector<Vec3> outside = {{2.0f, 2.0f, 0.1f}, {3.0f, 2.0f, 0.1f}, {2.0f, 3.0f, 0.1f}};
  EXPECT_EQ(buffer.test_triangles({outside, {}}, options()), Visibility::outside);
  buffer.read_depth(after);
  EXPECT_EQ(before, after);
}

TEST_P(OcclusionApi, BadQueriesAreRefusedByName) {
  OcclusionBuffer buffer(kWidth, kHeight);
  std::vector<Visibility> one(1), two(2);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const auto refuses = [&](auto call, const char* words) {
    try {
      call();
      ADD_FAILURE() << "accepted: " << words;
    } catch (const std::invalid_argument& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  const std::vector<OcclusionRect> nan_rect = {{0.0f, 0.0f, 1.0f, 1.0f, 0.5f},
                                               {0.0f, nan, 1.0f, 1.0f, 0.5f}};
  refuses([&] { buffer.test_rects(nan_rect, two, isa()); }, "rectangle 1 has a NaN");
  const std::vector<OcclusionRect> inverted = {{5.0f, 0.0f, 1.0f, 1.0f, 0.5f}};
  refuses([&] { buffer.test_rects(inverted, one, isa()); }, "rectangle 0 is inverted");
  refuses([&] { buffer.test_rects(inverted, two, isa()); }, "2 answers for 1 queries");
  const std::vector<OcclusionBox> bad_box = {{{0.0f, 0.0f, 0.0f}, {1.0f, nan, 1.0f}}};
  refuses([&] { buffer.test_boxes(bad_box, identity(), one, isa()); },
          "box 0 has a non-finite coordinate");
  const std::vector<OcclusionBox> flipped = {{{0.0f, 2.0f, 0.0f}, {1.0f, 1.0f, 1.0f}}};
  refuses([&] { buffer.test_boxes(flipped, identity(), one, isa()); }, "box 0 is inverted");
  refuses([&] { OcclusionBuffer(0, 10); }, "has no pixel");
  refuses([&] { OcclusionBuffer(10, kMaxTargetSize + 1); }, "outside");
}

INSTANTIATE_TEST_SUITE_P(Isas, OcclusionApi, ::testing::ValuesIn(every_isa()), isa_test_name);

}  // namespace
}  // namespace edgewise::test
