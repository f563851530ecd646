// Bad input gets its documented status from both clippers and never a NaN: non-finite and
// out-of-range coordinates, zero-area triangles, vertices at w = 0, bad viewports.
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <stdexcept>
#include <vector>

#include "draw/vertex_stage/clip.hpp"
#include "edgewise/coverage.hpp"
#include "draw/vertex_stage/clip_reference.hpp"

namespace edgewise {
inline void PrintTo(ClipStatus status, std::ostream* out) {
  *out << static_cast<int>(status);
}
}  // namespace edgewise

namespace edgewise::test {
namespace {

const Viewport kViewport{64, 48};

// Both clippers' status; the fast clipper's vertices must be finite with w > 0.
ClipStatus clip_both(const Vec4& a, const Vec4& b, const Vec4& c) {
  const ClippedPolygon fast = clip_triangle(a, b, c, guard_band_planes(kViewport));
  const reference::ClippedPolygon exact = reference::clip_triangle(a, b, c, kViewport);
  EXPECT_EQ(fast.status, exact.status);
  EXPECT_EQ(fast.count, exact.vertices.size());
  for (int i = 0; i < fast.count; ++i) {
    const ClipVertex& v = fast.vertices[i];
    for (float f : {v.position.x, v.position.y, v.position.z, v.position.w, v.b0, v.b1, v.b2})
      EXPECT_TRUE(std::isfinite(f));
    EXPECT_GT(v.position.w, 0.0f);
  }
  const bool drawn = fast.status == ClipStatus::inside || fast.status == ClipStatus::clipped;
  EXPECT_EQ(drawn, fast.count >= 3);
  return fast.status;
}

const Vec4 kInside{0.1f, 0.2f, 0.5f, 1.0f};
const Vec4 kInside2{-0.3f, 0.1f, 0.4f, 1.0f};

TEST(ClipBadInput, NonFiniteCoordinatesAreRejected) {
  const float specials[] = {std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::infinity(),
                            -std::numeric_limits<float>::infinity()};
  for (float special : specials) {
    for (int coordinate = 0; coordinate < 4; ++coordinate) {
      Vec4 bad = kInside;
      (&bad.x)[coordinate] = special;
      EXPECT_EQ(clip_both(bad, kInside, kInside2), ClipStatus::error_non_finite);
      EXPECT_EQ(clip_both(kInside, kInside2, bad), ClipStatus::error_non_finite);
    }
  }
  // Non-finite wins over out of range.
  EXPECT_EQ(clip_both({1e30f, 0, 0, 1}, {std::nanf(""), 0, 0, 1}, kInside),
            ClipStatus::error_non_finite);
}

TEST(ClipBadInput, HugeCoordinatesAreRejectedAboveTheLimit) {
  const float limit = kMaxClipCoordinate;
  const float above = std::nextafter(limit, std::numeric_limits<float>::infinity());
  EXPECT_EQ(clip_both({above, 0, 0.5f, 1}, kInside, kInside2), ClipStatus::error_out_of_range);
  EXPECT_EQ(clip_both(kInside, {0, 0, 0.5f, -3e38f}, kInside2), ClipStatus::error_out_of_range);
  // At the limit itself the clipper runs, and crosses the guard band and near planes finitely.
  EXPECT_EQ(clip_both({limit, 0, 0.5f, 1}, kInside, kInside2), ClipStatus::clipped);
  EXPECT_EQ(clip_both({0, 0, -limit, limit}, {limit, -limit, limit, limit}, kInside),
            ClipStatus::clipped);
}

TEST(ClipBadInput, ZeroAreaTrianglesStayFinite) {
  // Three equal points inside: passed through, for the rasterizer to cull.
  EXPECT_EQ(clip_both(kInside, kInside, kInside), ClipStatus::inside);
  // Collinear points crossing the near plane and the guard band.
  const Vec4 a{0, 0, -1, 1}, b{1, 1, 1, 1}, mid{0.5f, 0.5f, 0, 1};
  const ClipStatus collinear = clip_both(a, b, mid);
  EXPECT_TRUE(collinear == ClipStatus::clipped || collinear == ClipStatus::outside ||
              collinear == ClipStatus::culled_degenerate);
  EXPECT_EQ(clip_both(a, a, a), ClipStatus::outside);
  const Vec4 far_out{5000, 0, 0.5f, 1};
  const ClipStatus sliver = clip_both(kInside, far_out, kInside);
  EXPECT_TRUE(sliver == ClipStatus::clipped || sliver == ClipStatus::outside ||
              sliver == ClipStatus::culled_degenerate);
}

TEST(ClipBadInput, VerticesAtWZero) {
  // All three at w = 0: directions, not points. Outside unless at the origin, which is
  // culled_degenerate rather than divided by.
  EXPECT_EQ(clip_both({1, 0, 0, 0}, {0, 1, 0, 0}, {1, 1, 0, 0}), ClipStatus::outside);
  EXPECT_EQ(clip_both({1, 0, 0, 0}, {-1, 0, 0, 0}, {0, 1, 0, 0}), ClipStatus::culled_degenerate);
  EXPECT_EQ(clip_both({0, 0, 0, 0}, {0, 0, 0, 0}, {0, 0, 0, 0}), ClipStatus::culled_degenerate);
  EXPECT_EQ(clip_both({0, 0, 1, 0}, {0, 0, 2, 0}, {0, 0, 3, 0}), ClipStatus::outside);
  // One vertex at the eye (w = 0, z = 0), as a projection without a near plane makes.
  EXPECT_EQ(clip_both({0, 0, 0, 0}, kInside, kInside2), ClipStatus::culled_degenerate);
  // A vertex at w = 0 but z < 0 (beyond the near plane): clipped away, the rest is drawn.
  EXPECT_EQ(clip_both({0.2f, 0.1f, -1, 0}, kInside, kInside2), ClipStatus::clipped);
}

TEST(ClipBadInput, BadViewportsThrow) {
  EXPECT_THROW(guard_band_planes({0, 10}), std::invalid_argument);
  EXPECT_THROW(guard_band_planes({10, -1}), std::invalid_argument);
  EXPECT_THROW(guard_band_planes({kMaxTargetSize + 1, 10}), std::invalid_argument);
  EXPECT_NO_THROW(guard_band_planes({kMaxTargetSize, kMaxTargetSize}));
}

}  // namespace
}  // namespace edgewise::test
