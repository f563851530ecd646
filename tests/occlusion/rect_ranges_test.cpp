// Rectangles to ranges of samples: every ISA's kernel (rect_sample_ranges, in float lanes) gives
// the reference's ranges (rect_samples(), in double) field for field, on the values where a float
// clamp or rounding could part from a double one, and rejects the same first rectangle.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <limits>
#include <vector>

#include "edgewise/occlusion.hpp"
#include "isa_params.hpp"
#include "random.hpp"
#include "core/kernel_table.hpp"

namespace edgewise::test {
namespace {

class RectRanges : public IsaTest {};

// Coordinates at the edges of what the conversions do: half-pixel centres and their neighbours,
// the view's sides, where c - 0.5 stops being exact in float (2^22, 2^23, 2^24), huge, tiny and
// infinite values.
std::vector<float> edge_coordinates(std::int32_t size) {
  const float inf = std::numeric_limits<float>::infinity();
  std::vector<float> values = {0.0f, -0.0f, 1e-40f, -1e-40f, 1e30f, -1e30f, inf, -inf};
  const float s = static_cast<float>(size);
  for (const float base : {0.0f, 0.5f, 1.0f, 7.5f, 8.0f, 8.5f, s - 1.0f, s - 0.5f, s, s + 0.5f,
                           0x1p22f, 0x1p23f, 0x1p24f, -0.5f, -1.0f, -1.5f}) {
    values.push_back(base);
    values.push_back(std::nextafter(base, inf));
    values.push_back(std::nextafter(base, -inf));
  }
  return values;
}

TEST_P(RectRanges, EqualTheReferenceOnEdgeValuesAndRandomOnes) {
  const detail::KernelTable& kernels = detail::kernel_table(isa());
  const detail::KernelTable& reference = detail::kernel_table(Isa::reference);
  const std::int32_t width = 37, height = 21;
  const std::vector<float> xs = edge_coordinates(width), ys = edge_coordinates(height);
  const float inf = std::numeric_limits<float>::infinity();
  const float depths[] = {-inf, -1.0f, 0.0f, 0.25f, 1.0f, std::nextafter(1.0f, 2.0f), 2.0f, inf};
  Random random(0x7ec7);
  std::vector<OcclusionRect> rects;
  for (const float x0 : xs) {
    for (const float x1 : xs) {
      if (!(x0 <= x1)) continue;
      const float y0 =
          ys[static_cast<std::size_t>(random.integer(0, static_cast<std::int64_t>(ys.size()) - 1))];
      const float y1 =
          ys[static_cast<std::size_t>(random.integer(0, static_cast<std::int64_t>(ys.size()) - 1))];
      rects.push_back({x0, y0 <= y1 ? y0 : y1, x1, y0 <= y1 ? y1 : y0,
                       depths[random.integer(0, std::size(depths) - 1)]});
    }
  }
  for (int i = 0; i < 20000; ++i) {
    const float a = static_cast<float>(random.uniform(-8.0, width + 8.0));
    const float b = static_cast<float>(random.uniform(-8.0, height + 8.0));
    const float w = static_cast<float>(random.log_uniform(0.01, 2.0 * width));
    const float h = static_cast<float>(random.log_uniform(0.01, 2.0 * height));
    rects.push_back({a, b, a + w, b + h, static_cast<float>(random.uniform(-0.1, 1.1))});
  }
  // Counts that leave a part batch at the end, on every lane count.
  for (const std::size_t count : {rects.size(), rects.size() - 1, std::size_t{3}}) {
    for (const std::int32_t reduction : {1, 2, 4}) {
      std::vector<detail::SampleRect> got(count), want(count);
      ASSERT_EQ(
          kernels.rect_sample_ranges(rects.data(), count, width, height, reduction, got.data()),
          count);
      ASSERT_EQ(
          reference.rect_sample_ranges(rects.data(), count, width, height, reduction, want.data()),
          count);
      for (std::size_t i = 0; i < count; ++i) {
        const OcclusionRect& r = rects[i];
        ASSERT_TRUE(got[i].x0 == want[i].x0 && got[i].x1 == want[i].x1 && got[i].y0 == want[i].y0 &&
                    got[i].y1 == want[i].y1 && got[i].depth == want[i].depth)
            << "rectangle " << i << " [" << r.x0 << ", " << r.x1 << "] x [" << r.y0 << ", " << r.y1
            << "] depth " << r.depth << " reduction " << reduction << ": got [" << got[i].x0 << ", "
            << got[i].x1 << "] x [" << got[i].y0 << ", " << got[i].y1 << "] depth " << got[i].depth
            << ", want [" << want[i].x0 << ", " << want[i].x1 << "] x [" << want[i].y0 << ", "
            << want[i].y1 << "] depth " << want[i].depth;
      }
    }
  }
}

TEST_P(RectRanges, RejectTheFirstBadRectangle) {
  const detail::KernelTable& kernels = detail::kernel_table(isa());
  const float nan = std::numeric_limits<float>::quiet_NaN();
  const OcclusionRect good{1.0f, 1.0f, 5.0f, 5.0f, 0.5f};
  const OcclusionRect bad[] = {{nan, 1.0f, 5.0f, 5.0f, 0.5f}, {1.0f, nan, 5.0f, 5.0f, 0.5f},
                               {1.0f, 1.0f, nan, 5.0f, 0.5f}, {1.0f, 1.0f, 5.0f, nan, 0.5f},
                               {1.0f, 1.0f, 5.0f, 5.0f, nan}, {6.0f, 1.0f, 5.0f, 5.0f, 0.5f},
                               {1.0f, 6.0f, 5.0f, 5.0f, 0.5f}};
  for (const OcclusionRect& b : bad) {
    for (const std::size_t at : {0u, 1u, 7u, 8u, 16u, 20u}) {
      std::vector<OcclusionRect> rects(21, good);
      rects[at] = b;
      if (at + 1 < rects.size()) rects[at + 1] = b;  // only the first is named
      std::vector<detail::SampleRect> out(rects.size());
      EXPECT_EQ(kernels.rect_sample_ranges(rects.data(), rects.size(), 64, 64, 1, out.data()), at);
      for (std::size_t i = 0; i < at; ++i)
        EXPECT_TRUE(out[i].x0 == 1 && out[i].x1 == 4 && out[i].y0 == 1 && out[i].y1 == 4);
    }
  }
}

INSTANTIATE_TEST_SUITE_P(Isas, RectRanges, ::testing::ValuesIn(every_isa()), isa_test_name);

}  // namespace
}  // namespace edgewise::test
