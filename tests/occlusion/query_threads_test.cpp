// Rectangle and box queries on several threads (the OcclusionOptions overloads): the answers of
// one thread for every thread count, and the first bad query of the list named whichever range
// holds it.
#include <gtest/gtest.h>

#include <cmath>
#include <cstddef>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "edgewise/occlusion.hpp"
#include "isa_params.hpp"
#include "occlusion/occlusion_scenes.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

constexpr std::int32_t kQueryWidth = 160, kQueryHeight = 96;

class QueryThreads : public IsaTest {
 protected:
  OcclusionOptions options(std::size_t threads) const {
    OcclusionOptions o;
    o.isa = isa();
    o.threads = threads;
    return o;
  }
};

// Enough queries for several tasks of the call (thousands each).
constexpr int kQueries = 20000;

TEST_P(QueryThreads, AnswerAsOneThreadOnEveryThreadCount) {
  Random random(0x7d5);
  const OccluderSoup soup = random_occluders(random, 400);
  for (const std::int32_t reduction : {1, 4}) {
    OcclusionBuffer buffer(kQueryWidth, kQueryHeight, reduction);
    buffer.draw_occluders(soup.mesh(), options(1));
    const std::vector<OcclusionRect> rects =
        random_rects(random, kQueries, kQueryWidth, kQueryHeight);
    const Mat4 camera = random_camera(random, static_cast<float>(kQueryWidth) / kQueryHeight);
    const std::vector<OcclusionBox> boxes = random_boxes(random, kQueries);
    std::vector<Visibility> rects_alone(rects.size()), boxes_alone(boxes.size());
    buffer.test_rects(rects, rects_alone, isa());
    buffer.test_boxes(boxes, camera, boxes_alone, isa());
    std::size_t answers[3] = {};
    for (const Visibility v : boxes_alone)
      ++answers[static_cast<int>(v)];
    for (const std::size_t threads : {1u, 2u, 3u, 0u}) {
      std::vector<Visibility> got_rects(rects.size()), got_boxes(boxes.size());
      buffer.test_rects(rects, got_rects, options(threads));
      OcclusionOptions box_options = options(threads);
      box_options.transform = camera;
      buffer.test_boxes(boxes, got_boxes, box_options);
      for (std::size_t i = 0; i < rects.size(); ++i)
        ASSERT_EQ(got_rects[i], rects_alone[i])
            << "rectangle " << i << ", " << threads << " threads";
      for (std::size_t i = 0; i < boxes.size(); ++i)
        ASSERT_EQ(got_boxes[i], boxes_alone[i]) << "box " << i << ", " << threads << " threads";
    }
    // The boxes took every answer, so every path of the call was compared.
    for (const std::size_t count : answers)
      EXPECT_GT(count, 100u) << "reduction " << reduction;
  }
}

// The message of the std::invalid_argument that `call` throws, or "" when it throws none.
template <class Call>
std::string thrown_message(const Call& call) {
  try {
    call();
  } catch (const std::invalid_argument& error) {
    return error.what();
  }
  return "";
}

TEST_P(QueryThreads, NameTheFirstBadQueryOfTheList) {
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const OcclusionBuffer buffer(kQueryWidth, kQueryHeight);
  // Bad queries in several ranges: the first of the list is named, whichever task meets it first.
  for (const std::size_t first_bad : {std::size_t{0}, std::size_t{4999}, std::size_t{15000}}) {
    std::vector<OcclusionRect> rects(kQueries, OcclusionRect{1.0f, 1.0f, 9.0f, 9.0f, 0.5f});
    std::vector<OcclusionBox> boxes(kQueries,
                                    OcclusionBox{{-0.5f, -0.5f, 0.25f}, {0.5f, 0.5f, 0.75f}});
    for (const std::size_t bad : {first_bad, first_bad + 3, std::size_t{kQueries - 1}}) {
      rects[bad].x0 = nan;
      boxes[bad].max.y = -1.0f;  // inverted
    }
    std::vector<Visibility> out(kQueries);
    for (const std::size_t threads : {1u, 3u, 0u}) {
      EXPECT_EQ(
          thrown_message([&] { buffer.test_rects(rects, out, options(threads)); }),
          "test_rects: rectangle " + std::to_string(first_bad) + " has a NaN coordinate or depth")
          << threads << " threads";
      EXPECT_EQ(
          thrown_message([&] { buffer.test_boxes(boxes, out, options(threads)); }),
          "test_boxes: box " + std::to_string(first_bad) + " is inverted (min > max on an axis)")
          << threads << " threads";
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Isas, QueryThreads, ::testing::ValuesIn(every_isa()), isa_test_name);

}  // namespace
}  // namespace edgewise::test
