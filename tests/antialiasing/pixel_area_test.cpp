// The exact-area reference (kernels/antialiasing/pixel_area_reference.hpp) against what is known
// independently of its clipping: hand areas, areas of rectangles (products of exact lengths),
// the triangle's own area, partitions of a triangle, and the sample-coverage reference.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <vector>

#include "random.hpp"
#include "antialiasing/pixel_area_reference.hpp"

namespace edgewise::test {
namespace {

using reference::kPixelAreaErrorBound;
using reference::pixel_area;
using reference::SnappedTriangle;
using reference::triangle_area;

// A triangle from fixed-point coordinates (1/256 px).
SnappedTriangle fixed(std::int64_t x0, std::int64_t y0, std::int64_t x1, std::int64_t y1,
                      std::int64_t x2, std::int64_t y2) {
  return {{x0, x1, x2}, {y0, y1, y2}};
}

SnappedTriangle reversed(const SnappedTriangle& t) {
  return {{t.x[0], t.x[2], t.x[1]}, {t.y[0], t.y[2], t.y[1]}};
}

// Pixels of the triangle's box, one pixel of margin around it.
PixelRect box_of(const SnappedTriangle& t) {
  const auto [x0, x1] = std::minmax({t.x[0], t.x[1], t.x[2]});
  const auto [y0, y1] = std::minmax({t.y[0], t.y[1], t.y[2]});
  const auto floor_px = [](std::int64_t v) { return static_cast<std::int32_t>((v >> 8) - 1); };
  return {floor_px(x0), floor_px(y0), floor_px(x1) + 3, floor_px(y1) + 3};
}

// The length of [a, b) (fixed point) inside pixel column [p, p + 1), in pixels: exact.
double overlap(std::int64_t a, std::int64_t b, std::int32_t p) {
  const std::int64_t lo = std::max(a, std::int64_t{p} * 256);
  const std::int64_t hi = std::min(b, std::int64_t{p} * 256 + 256);
  return hi > lo ? static_cast<double>(hi - lo) / 256.0 : 0.0;
}

TEST(PixelArea, HandCasesOfARightTriangle) {
  // (0, 0), (4, 0), (0, 4) px: pixels below the diagonal are whole, those it crosses halved.
  const SnappedTriangle t = fixed(0, 0, 1024, 0, 0, 1024);
  for (const SnappedTriangle& tri : {t, reversed(t)}) {
    for (std::int32_t y = -1; y < 6; ++y) {
      for (std::int32_t x = -1; x < 6; ++x) {
        const bool inside = x >= 0 && y >= 0 && x + y <= 3;
        const double expected = !inside ? 0.0 : (x + y < 3 ? 1.0 : 0.5);
        EXPECT_NEAR(pixel_area(tri, x, y), expected, kPixelAreaErrorBound) << x << "," << y;
      }
    }
  }
  EXPECT_EQ(triangle_area(t), 8.0);
  EXPECT_EQ(triangle_area(reversed(t)), 8.0);
}

TEST(PixelArea, ASubpixelTriangleInsideOnePixel) {
  // Vertices at 1/256 px steps inside pixel (3, 5): its whole area lands there.
  const SnappedTriangle t =
      fixed(3 * 256 + 10, 5 * 256 + 20, 3 * 256 + 200, 5 * 256 + 31, 3 * 256 + 77, 5 * 256 + 250);
  EXPECT_NEAR(pixel_area(t, 3, 5), triangle_area(t), kPixelAreaErrorBound);
  EXPECT_EQ(pixel_area(t, 4, 5), 0.0);
  EXPECT_EQ(pixel_area(t, 3, 4), 0.0);
}

// A rectangle of fixed-point corners cut into triangles in two ways: along a diagonal, and as
// a fan around an inner point. Per pixel, the triangles' areas must add up to the rectangle's
// area in the pixel, a product of two exact lengths. Each triangle errs by at most the bound,
// and the sum of at most four terms in [0, 1] by at most 4 ulps of 1 more.
TEST(PixelArea, RectanglesCutIntoTriangles) {
  Random random(0xa7ea'0001);
  for (int trial = 0; trial < 300; ++trial) {
    // Near the origin, or anywhere in the guard band (large coordinates).
    const std::int64_t reach = trial % 3 == 0 ? (std::int64_t{1} << 23) - 8192 : 4096;
    const std::int64_t x0 = random.integer(-reach, reach), y0 = random.integer(-reach, reach);
    const std::int64_t x1 = x0 + random.integer(1, 2048), y1 = y0 + random.integer(1, 2048);
    const std::int64_t cx = random.integer(x0 + 1, std::max(x0 + 1, x1 - 1));
    const std::int64_t cy = random.integer(y0 + 1, std::max(y0 + 1, y1 - 1));
    const bool has_inner = cx < x1 && cy < y1;
    std::vector<SnappedTriangle> diagonal = {fixed(x0, y0, x1, y0, x1, y1),
                                             fixed(x0, y0, x1, y1, x0, y1)};
    std::vector<SnappedTriangle> fan;
    if (has_inner) {
      fan = {fixed(x0, y0, x1, y0, cx, cy), fixed(x1, y0, x1, y1, cx, cy),
             fixed(x1, y1, x0, y1, cx, cy), fixed(x0, y1, x0, y0, cx, cy)};
    }
    const PixelRect box = box_of(diagonal[0]);
    for (std::int32_t py = box.y0; py < box.y1; ++py) {
      for (std::int32_t px = box.x0; px < box.x1; ++px) {
        const double expected = overlap(x0, x1, px) * overlap(y0, y1, py);
        for (const auto* cut : {&diagonal, &fan}) {
          if (cut->empty()) continue;
          double sum = 0.0;
          for (const SnappedTriangle& t : *cut)
            sum += pixel_area(t, px, py);
          const double tolerance =
              static_cast<double>(cut->size()) * (kPixelAreaErrorBound + 0x1p-52);
          ASSERT_NEAR(sum, expected, tolerance)
              << "trial " << trial << " pixel " << px << "," << py << " cut of " << cut->size();
        }
      }
    }
  }
}

// A random triangle, from slivers to wide ones, anywhere in the guard band.
SnappedTriangle random_guard_band_triangle(Random& random) {
  const std::int64_t reach = random.chance(0.3) ? (std::int64_t{1} << 23) - 8192 : 1 << 14;
  const std::int64_t x = random.integer(-reach, reach), y = random.integer(-reach, reach);
  const double size = random.log_uniform(1.0, 16384.0);  // fixed-point units: up to 64 px
  SnappedTriangle t;
  for (int i = 0; i < 3; ++i) {
    t.x[i] = x + static_cast<std::int64_t>(std::llround(random.uniform(-size, size)));
    t.y[i] = y + static_cast<std::int64_t>(std::llround(random.uniform(-size, size)));
  }
  return t;
}

bool has_area(const SnappedTriangle& t) {
  return (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) != (t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
}

// Summed over the pixels, the areas give the triangle's area: each of the n pixels errs by at
// most the bound, and summing n terms of total A rounds by at most n ulps of A.
TEST(PixelArea, PixelsAddUpToTheTriangle) {
  Random random(0xa7ea'0002);
  for (int trial = 0; trial < 2000; ++trial) {
    const SnappedTriangle t = random_guard_band_triangle(random);
    if (!has_area(t)) continue;
    const PixelRect box = box_of(t);
    double sum = 0.0;
    std::size_t pixels = 0;
    for (std::int32_t py = box.y0; py < box.y1; ++py) {
      for (std::int32_t px = box.x0; px < box.x1; ++px) {
        const double area = pixel_area(t, px, py);
        ASSERT_GE(area, 0.0);
        ASSERT_LE(area, 1.0 + kPixelAreaErrorBound);
        sum += area;
        ++pixels;
      }
    }
    const double exact = triangle_area(t);
    const double n = static_cast<double>(pixels);
    ASSERT_NEAR(sum, exact, n * (kPixelAreaErrorBound + 0x1p-52 * exact)) << "trial " << trial;
  }
}

// A triangle cut in three at an inner fixed-point point: per pixel, the parts add up to the
// whole within four times the bound (three parts and the whole) and the sum's rounding.
TEST(PixelArea, PartsOfATriangleAddUpPerPixel) {
  Random random(0xa7ea'0003);
  int checked = 0;
  for (int trial = 0; trial < 3000 && checked < 1000; ++trial) {
    const SnappedTriangle t = random_guard_band_triangle(random);
    if (!has_area(t)) continue;
    // A point inside: a rounded convex combination, kept only if strictly inside.
    const double a = random.uniform(0.05, 0.9), b = random.uniform(0.05, 0.95 - a);
    const std::int64_t cx = std::llround(t.x[0] + a * (t.x[1] - t.x[0]) + b * (t.x[2] - t.x[0]));
    const std::int64_t cy = std::llround(t.y[0] + a * (t.y[1] - t.y[0]) + b * (t.y[2] - t.y[0]));
    const SnappedTriangle parts[3] = {fixed(t.x[0], t.y[0], t.x[1], t.y[1], cx, cy),
                                      fixed(t.x[1], t.y[1], t.x[2], t.y[2], cx, cy),
                                      fixed(t.x[2], t.y[2], t.x[0], t.y[0], cx, cy)};
    const double whole = triangle_area(t);
    const double sum_of_parts =
        triangle_area(parts[0]) + triangle_area(parts[1]) + triangle_area(parts[2]);
    if (!has_area(parts[0]) || !has_area(parts[1]) || !has_area(parts[2]) ||
        sum_of_parts != whole) {
      continue;  // the rounded point fell on or outside an edge
    }
    ++checked;
    const PixelRect box = box_of(t);
    for (std::int32_t py = box.y0; py < box.y1; ++py) {
      for (std::int32_t px = box.x0; px < box.x1; ++px) {
        const double sum = pixel_area(parts[0], px, py) + pixel_area(parts[1], px, py) +
                           pixel_area(parts[2], px, py);
        ASSERT_NEAR(sum, pixel_area(t, px, py), 4.0 * kPixelAreaErrorBound + 0x1p-51)
            << "trial " << trial << " pixel " << px << "," << py;
      }
    }
  }
  EXPECT_EQ(checked, 1000);
}

// Against the sample-coverage reference: a covered centre means some area (the triangle holds
// a wedge around any point of its closed edges), and more than half the square means a covered
// centre (an edge with the centre on its outer side leaves at most the half of the square that
// a parallel line through the centre cuts off).
TEST(PixelArea, AgreesWithTheSampleAtThePixelCentre) {
  Random random(0xa7ea'0004);
  for (int trial = 0; trial < 2000; ++trial) {
    const SnappedTriangle t = random_guard_band_triangle(random);
    if (!has_area(t)) continue;
    const PixelRect box = box_of(t);
    for (std::int32_t py = box.y0; py < box.y1; ++py) {
      for (std::int32_t px = box.x0; px < box.x1; ++px) {
        const double area = pixel_area(t, px, py);
        const bool covered = reference::covers(t, px, py);
        if (covered) {
          ASSERT_GT(area, 0.0) << "trial " << trial << " pixel " << px << "," << py;
        }
        if (area > 0.5 + kPixelAreaErrorBound) {
          ASSERT_TRUE(covered) << "trial " << trial << " pixel " << px << "," << py;
        }
      }
    }
  }
}

}  // namespace
}  // namespace edgewise::test
