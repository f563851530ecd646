// Boxes to ranges of samples: every ISA's kernel (box_sample_ranges, a batch of boxes in lanes)
// gives the reference's answer (box_samples(), one box at a time) field for field, on random
// cameras and boxes and on boxes whose corners lie on the clipping planes or next to them, and
// rejects the same first box.
#include <gtest/gtest.h>

#include <array>
#include <bit>
#include <cmath>
#include <cstdint>
#include <limits>
#include <utility>
#include <vector>

#include "edgewise/camera.hpp"
#include "edgewise/occlusion.hpp"
#include "isa_params.hpp"
#include "occlusion_scenes.hpp"
#include "random.hpp"
#include "core/kernel_table.hpp"
#include "draw/vertex_stage/clip.hpp"
#include "occlusion/query_bounds.hpp"

namespace edgewise::test {
namespace {

class BoxRanges : public IsaTest {};

constexpr Viewport kView{96, 64};

// The kernel's answers for `boxes` under `to_clip` against the reference's, for the whole list
// and for counts that leave a part batch at the end; returns how many boxes were bounded,
// outside and unbounded in the whole list.
std::array<std::size_t, 3> expect_reference_answers(const detail::KernelTable& kernels,
                                                    const std::vector<OcclusionBox>& boxes,
                                                    const Mat4& to_clip) {
  const detail::KernelTable& reference = detail::kernel_table(Isa::reference);
  const GuardBandPlanes planes = guard_band_planes(kView);
  std::array<std::size_t, 3> reaches{};
  for (const std::size_t count : {boxes.size(), boxes.size() - 1, std::size_t{3}}) {
    std::vector<detail::BoxSamples> got(count), want(count);
    EXPECT_EQ(kernels.box_sample_ranges(boxes.data(), count, to_clip, kView, planes, got.data()),
              count);
    EXPECT_EQ(reference.box_sample_ranges(boxes.data(), count, to_clip, kView, planes, want.data()),
              count);
    for (std::size_t i = 0; i < count; ++i) {
      const detail::SampleRect& g = got[i].samples;
      const detail::SampleRect& w = want[i].samples;
      const OcclusionBox& b = boxes[i];
      EXPECT_TRUE(got[i].reach == want[i].reach && g.x0 == w.x0 && g.x1 == w.x1 && g.y0 == w.y0 &&
                  g.y1 == w.y1 &&
                  std::bit_cast<std::uint32_t>(g.depth) == std::bit_cast<std::uint32_t>(w.depth))
          << "box " << i << " (" << b.min.x << ", " << b.min.y << ", " << b.min.z << ") - ("
          << b.max.x << ", " << b.max.y << ", " << b.max.z << "): got reach "
          << static_cast<int>(got[i].reach) << " [" << g.x0 << ", " << g.x1 << "] x [" << g.y0
          << ", " << g.y1 << "] depth " << g.depth << ", want reach "
          << static_cast<int>(want[i].reach) << " [" << w.x0 << ", " << w.x1 << "] x [" << w.y0
          << ", " << w.y1 << "] depth " << w.depth;
      if (count == boxes.size()) ++reaches[static_cast<std::size_t>(want[i].reach)];
      if (::testing::Test::HasFailure()) return reaches;
    }
  }
  return reaches;
}

TEST_P(BoxRanges, EqualTheReferenceOnRandomCamerasAndBoxes) {
  const detail::KernelTable& kernels = detail::kernel_table(isa());
  Random random(0xb0c5);
  std::array<std::size_t, 3> reaches{};
  for (int camera = 0; camera < 40; ++camera) {
    const Mat4 to_clip =
        random_camera(random, static_cast<float>(kView.width) / static_cast<float>(kView.height));
    const std::vector<OcclusionBox> boxes = random_boxes(random, 203);
    const std::array<std::size_t, 3> found = expect_reference_answers(kernels, boxes, to_clip);
    if (HasFailure()) return;
    for (std::size_t r = 0; r < 3; ++r)
      reaches[r] += found[r];
  }
  // Every kind of answer was compared, the bounded ones most (the slopes, the margin, the ranges).
  EXPECT_GT(reaches[static_cast<std::size_t>(detail::BoxReach::bounded)], 2000u);
  EXPECT_GT(reaches[static_cast<std::size_t>(detail::BoxReach::outside)], 200u);
  EXPECT_GT(reaches[static_cast<std::size_t>(detail::BoxReach::unbounded)], 200u);
}

// Under the identity, a box's corners are clip-space points with w = 1: coordinates on the
// frustum planes (x, y = +-1, z = 0 or 1), on the guard band's, one float either side of them,
// and huge ones that no clip-space check takes.
TEST_P(BoxRanges, EqualTheReferenceOnThePlanesAndBesideThem) {
  const detail::KernelTable& kernels = detail::kernel_table(isa());
  const GuardBandPlanes planes = guard_band_planes(kView);
  const float inf = std::numeric_limits<float>::infinity();
  const auto around = [&](std::vector<float> bases) {
    std::vector<float> values;
    for (const float base : bases) {
      values.push_back(base);
      values.push_back(std::nextafter(base, inf));
      values.push_back(std::nextafter(base, -inf));
    }
    return values;
  };
  const std::vector<float> xs =
      around({-1.0f, -0.5f, 0.0f, 0.3f, 1.0f, planes.x_min, planes.x_max, 1e30f, -1e30f});
  const std::vector<float> ys =
      around({-1.0f, -0.25f, 0.0f, 0.7f, 1.0f, planes.y_min, planes.y_max, 1e30f});
  const std::vector<float> zs = around({-1.0f, 0.0f, 0.5f, 1.0f, 2.0f});
  Random random(0x91a7e5);
  std::vector<OcclusionBox> boxes;
  const auto pick = [&](const std::vector<float>& v) {
    return v[static_cast<std::size_t>(random.integer(0, static_cast<std::int64_t>(v.size()) - 1))];
  };
  // Half of the boxes within the frustum's planes and their neighbours (most of them bounded).
  const std::vector<float> inner_xs = around({-1.0f, -0.5f, 0.0f, 0.3f, 1.0f});
  const std::vector<float> inner_ys = around({-1.0f, -0.25f, 0.0f, 0.7f, 1.0f});
  const std::vector<float> inner_zs = around({0.0f, 0.5f, 1.0f});
  for (int i = 0; i < 8000; ++i) {
    const bool inner = i % 2 == 0;
    const std::vector<float>& x = inner ? inner_xs : xs;
    const std::vector<float>& y = inner ? inner_ys : ys;
    const std::vector<float>& z = inner ? inner_zs : zs;
    float c[6] = {pick(x), pick(y), pick(z), pick(x), pick(y), pick(z)};
    for (int axis = 0; axis < 3; ++axis) {
      if (c[axis] > c[axis + 3]) std::swap(c[axis], c[axis + 3]);
    }
    boxes.push_back({{c[0], c[1], c[2]}, {c[3], c[4], c[5]}});
  }
  const std::array<std::size_t, 3> reaches = expect_reference_answers(kernels, boxes, identity());
  EXPECT_GT(reaches[static_cast<std::size_t>(detail::BoxReach::bounded)], 100u);
  EXPECT_GT(reaches[static_cast<std::size_t>(detail::BoxReach::outside)], 100u);
  EXPECT_GT(reaches[static_cast<std::size_t>(detail::BoxReach::unbounded)], 100u);
}

TEST_P(BoxRanges, RejectTheFirstBadBox) {
  const detail::KernelTable& kernels = detail::kernel_table(isa());
  const GuardBandPlanes planes = guard_band_planes(kView);
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const float inf = std::numeric_limits<float>::infinity();
  const OcclusionBox good{{-0.5f, -0.5f, 0.25f}, {0.5f, 0.5f, 0.75f}};
  std::vector<OcclusionBox> bad;
  for (int field = 0; field < 6; ++field) {
    for (const float value : {nan, inf, -inf}) {
      OcclusionBox b = good;
      (field < 3 ? (&b.min.x)[field] : (&b.max.x)[field - 3]) = value;
      bad.push_back(b);
    }
  }
  bad.push_back({{0.6f, -0.5f, 0.25f}, {0.5f, 0.5f, 0.75f}});  // inverted on x
  bad.push_back({{-0.5f, 0.6f, 0.25f}, {0.5f, 0.5f, 0.75f}});  // on y
  bad.push_back({{-0.5f, -0.5f, 0.8f}, {0.5f, 0.5f, 0.75f}});  // on z
  detail::BoxSamples expected;
  for (const OcclusionBox& b : bad) {
    for (const std::size_t at : {0u, 1u, 7u, 8u, 16u, 20u}) {
      std::vector<OcclusionBox> boxes(21, good);
      boxes[at] = b;
      if (at + 1 < boxes.size()) boxes[at + 1] = b;  // only the first is named
      std::vector<detail::BoxSamples> out(boxes.size());
      ASSERT_EQ(kernels.box_sample_ranges(boxes.data(), boxes.size(), identity(), kView, planes,
                                          out.data()),
                at);
      expected = detail::box_samples(good, identity(), kView, planes, 0);
      for (std::size_t i = 0; i < at; ++i) {
        EXPECT_TRUE(out[i].reach == expected.reach && out[i].samples.x0 == expected.samples.x0 &&
                    out[i].samples.x1 == expected.samples.x1 &&
                    out[i].samples.y0 == expected.samples.y0 &&
                    out[i].samples.y1 == expected.samples.y1 &&
                    out[i].samples.depth == expected.samples.depth)
            << "box " << i << " before the bad one at " << at;
      }
    }
  }
  EXPECT_EQ(expected.reach, detail::BoxReach::bounded);
}

INSTANTIATE_TEST_SUITE_P(Isas, BoxRanges, ::testing::ValuesIn(every_isa()), isa_test_name);

}  // namespace
}  // namespace edgewise::test
