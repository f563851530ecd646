// classify_clip_vertex(): the per-vertex classes draw() uses to skip clip_triangle(). When all
// three vertices are inside, clip_triangle() must return the triangle as ClipStatus::inside, bit
// for bit; when they share an outside frustum plane, as ClipStatus::outside.
#include <gtest/gtest.h>

#include <cmath>
#include <cstring>
#include <limits>

#include "draw/vertex_stage/clip.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

// Clip-space points around the view volume: inside, near every plane, beyond every plane, at
// w <= 0, and some non-finite or huge coordinates.
Vec4 random_clip_point(Random& random) {
  const double w = random.chance(0.1) ? random.uniform(-1.0, 0.01) : random.log_uniform(1e-3, 1e3);
  const double reach = random.chance(0.5) ? 1.05 : 40.0;
  Vec4 p{static_cast<float>(random.uniform(-reach, reach) * w),
         static_cast<float>(random.uniform(-reach, reach) * w),
         static_cast<float>(random.uniform(-0.05, 1.05) * w), static_cast<float>(w)};
  if (random.chance(0.01)) p.x = std::numeric_limits<float>::quiet_NaN();
  if (random.chance(0.01)) p.w = 0x1p70f;
  return p;
}

TEST(ClassifyClipVertex, ClassesAgreeWithClipTriangle) {
  Random random(5);
  const GuardBandPlanes planes = guard_band_planes(Viewport{640, 360});
  int accepted = 0, rejected = 0;
  for (int t = 0; t < 200000; ++t) {
    const Vec4 p[3] = {random_clip_point(random), random_clip_point(random),
                       random_clip_point(random)};
    const ClipClass c[3] = {classify_clip_vertex(p[0], planes), classify_clip_vertex(p[1], planes),
                            classify_clip_vertex(p[2], planes)};
    if (!(c[0].checked && c[1].checked && c[2].checked)) continue;
    if ((c[0].outside_frustum & c[1].outside_frustum & c[2].outside_frustum) != 0) {
      ++rejected;
      ASSERT_EQ(clip_triangle(p[0], p[1], p[2], planes).status, ClipStatus::outside);
      continue;
    }
    if (!(c[0].inside && c[1].inside && c[2].inside)) continue;
    ++accepted;
    const ClippedPolygon polygon = clip_triangle(p[0], p[1], p[2], planes);
    ASSERT_EQ(polygon.status, ClipStatus::inside) << "triangle " << t;
    ASSERT_EQ(polygon.count, 3);
    for (int i = 0; i < 3; ++i) {
      ASSERT_EQ(std::memcmp(&polygon.vertices[i].position, &p[i], sizeof(Vec4)), 0);
    }
  }
  EXPECT_GT(accepted, 1000);
  EXPECT_GT(rejected, 1000);
}

bool inside(const Vec4& p, const GuardBandPlanes& planes) {
  return classify_clip_vertex(p, planes).inside;
}

TEST(ClassifyClipVertex, InsideExcludesWhatClippingWouldChange) {
  const GuardBandPlanes planes = guard_band_planes(Viewport{640, 360});
  EXPECT_TRUE(inside({0.5f, -0.5f, 0.5f, 1.0f}, planes));
  EXPECT_FALSE(inside({0.0f, 0.0f, -0.01f, 1.0f}, planes));  // before the near plane
  EXPECT_FALSE(inside({0.0f, 0.0f, 1.01f, 1.0f}, planes));   // past the far plane
  EXPECT_FALSE(inside({1.5f, 0.0f, 0.5f, 1.0f}, planes));    // beyond a side
  EXPECT_FALSE(inside({0.0f, 0.0f, 0.0f, 0.0f}, planes));    // w = 0
  EXPECT_FALSE(inside({std::numeric_limits<float>::infinity(), 0, 0.5f, 1}, planes));
  EXPECT_FALSE(inside({0.0f, 0.0f, 0.5f, 0x1p70f}, planes));  // beyond the range
  EXPECT_FALSE(classify_clip_vertex({0.0f, 0.0f, 0.5f, 0x1p70f}, planes).checked);
  EXPECT_EQ(classify_clip_vertex({2.0f, 0.0f, 0.5f, 1.0f}, planes).outside_frustum != 0, true);
}

}  // namespace
}  // namespace edgewise::test
