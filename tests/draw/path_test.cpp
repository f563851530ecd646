// Paths and strokes (path.hpp): the flattening formula against the true curve, round strokes
// against their definition (every point within half the width of the path), joins and caps at
// their defining points, areas, painting on every ISA, and the errors.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>
#include <numbers>
#include <stdexcept>
#include <vector>

#include "edgewise/path.hpp"
#include "edgewise/pixel_area.hpp"
#include "edgewise/resolve.hpp"
#include "isa_params.hpp"
#include "random.hpp"

namespace edgewise::test {
namespace {

struct P {
  double x, y;
};

P bezier(P p0, P p1, P p2, double t) {
  const double u = 1.0 - t;
  return {u * u * p0.x + 2 * t * u * p1.x + t * t * p2.x,
          u * u * p0.y + 2 * t * u * p1.y + t * t * p2.y};
}

double distance_to_segment(P p, P a, P b) {
  const double dx = b.x - a.x, dy = b.y - a.y;
  const double length_sq = dx * dx + dy * dy;
  double t = length_sq > 0.0 ? ((p.x - a.x) * dx + (p.y - a.y) * dy) / length_sq : 0.0;
  t = std::clamp(t, 0.0, 1.0);
  return std::hypot(p.x - (a.x + t * dx), p.y - (a.y + t * dy));
}

double distance_to_polyline(P p, const std::vector<P>& line) {
  double best = std::numeric_limits<double>::infinity();
  if (line.size() == 1) return std::hypot(p.x - line[0].x, p.y - line[0].y);
  for (std::size_t i = 0; i + 1 < line.size(); ++i)
    best = std::min(best, distance_to_segment(p, line[i], line[i + 1]));
  return best;
}

// Whether p lies in some triangle (boundary included), in double.
bool covered(const std::vector<Vec2>& triangles, P p) {
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    double s[3];
    for (int i = 0; i < 3; ++i) {
      const Vec2 a = triangles[t + i], b = triangles[t + (i + 1) % 3];
      s[i] = (static_cast<double>(b.x) - a.x) * (p.y - a.y) -
             (static_cast<double>(b.y) - a.y) * (p.x - a.x);
    }
    if ((s[0] >= 0 && s[1] >= 0 && s[2] >= 0) || (s[0] <= 0 && s[1] <= 0 && s[2] <= 0)) {
      return true;
    }
  }
  return false;
}

double triangle_area_sum(const std::vector<Vec2>& triangles) {
  double sum = 0.0;
  for (std::size_t t = 0; t + 2 < triangles.size(); t += 3) {
    const Vec2 a = triangles[t], b = triangles[t + 1], c = triangles[t + 2];
    sum += 0.5 * std::fabs((static_cast<double>(b.x) - a.x) * (static_cast<double>(c.y) - a.y) -
                           (static_cast<double>(b.y) - a.y) * (static_cast<double>(c.x) - a.x));
  }
  return sum;
}

// Flattening: every step's chord within the tolerance of the curve at the same parameter (plus
// the points' rounding to float: half an ulp of each coordinate, below 2^-24 of the largest
// magnitude, twice), and one step fewer would not be.
TEST(Path, QuadSegmentsAreTheFewestEqualStepsWithinTheTolerance) {
  Random random(8);
  for (int trial = 0; trial < 400; ++trial) {
    const double scale = random.log_uniform(0.5, 2000.0);
    const P p0{random.uniform(-scale, scale), random.uniform(-scale, scale)};
    const P p1{random.uniform(-scale, scale), random.uniform(-scale, scale)};
    const P p2{random.uniform(-scale, scale), random.uniform(-scale, scale)};
    const float tolerance = static_cast<float>(random.log_uniform(0.01, 2.0));
    const auto f = [](P p) { return Vec2{static_cast<float>(p.x), static_cast<float>(p.y)}; };
    Path path;
    path.move_to(f(p0));
    path.quad_to(f(p1), f(p2));
    // The curve of the float control points is the one flattened.
    const P q0{f(p0).x, f(p0).y}, q1{f(p1).x, f(p1).y}, q2{f(p2).x, f(p2).y};
    const std::size_t n = quad_segments(f(p0), f(p1), f(p2), tolerance);
    const std::vector<Polyline> lines = flatten(path, tolerance);
    ASSERT_EQ(lines.size(), 1u);
    ASSERT_EQ(lines[0].points.size(), n + 1);
    const double rounding = 4.0 * 0x1p-24 * 3.0 * scale;
    double worst = 0.0;
    for (std::size_t k = 0; k < n; ++k) {
      const P a{lines[0].points[k].x, lines[0].points[k].y};
      const P b{lines[0].points[k + 1].x, lines[0].points[k + 1].y};
      for (int j = 0; j <= 16; ++j) {
        const double s = j / 16.0;
        const P curve = bezier(q0, q1, q2, (static_cast<double>(k) + s) / static_cast<double>(n));
        const P chord{a.x + s * (b.x - a.x), a.y + s * (b.y - a.y)};
        worst = std::max(worst, std::hypot(curve.x - chord.x, curve.y - chord.y));
      }
    }
    EXPECT_LE(worst, tolerance + rounding) << "trial " << trial << ", " << n << " steps";
    const double d = std::hypot(q0.x - 2 * q1.x + q2.x, q0.y - 2 * q1.y + q2.y);
    if (n > 1) {
      // n - 1 equal steps miss the curve by d / (4 (n - 1)^2) at a step's middle.
      EXPECT_GT(d / (4.0 * static_cast<double>(n - 1) * static_cast<double>(n - 1)), tolerance)
          << "trial " << trial;
    }
  }
}

// A round-joined, round-capped stroke is every point within half the width of its path: points
// that far inside (less the flattening and arc tolerances) are covered, points beyond are not.
TEST(Path, RoundStrokesHoldEveryPointWithinHalfTheWidth) {
  Random random(9);
  const float tolerance = 0.05f;
  for (int trial = 0; trial < 16; ++trial) {
    Path path;
    std::vector<P> centre;  // the true path, densely sampled
    P current{random.uniform(10, 90), random.uniform(10, 90)};
    path.move_to({static_cast<float>(current.x), static_cast<float>(current.y)});
    centre.push_back(current);
    for (int piece = 0; piece < 4; ++piece) {
      const P end{random.uniform(10, 90), random.uniform(10, 90)};
      const Vec2 end_f{static_cast<float>(end.x), static_cast<float>(end.y)};
      if (random.uniform() < 0.5) {
        path.line_to(end_f);
        centre.push_back({end_f.x, end_f.y});
      } else {
        const P control{random.uniform(0, 100), random.uniform(0, 100)};
        const Vec2 control_f{static_cast<float>(control.x), static_cast<float>(control.y)};
        const P from = centre.back();
        for (int j = 1; j <= 1000; ++j)
          centre.push_back(
              bezier(from, {control_f.x, control_f.y}, {end_f.x, end_f.y}, j / 1000.0));
        path.quad_to(control_f, end_f);
      }
    }
    StrokeStyle style;
    style.width = static_cast<float>(random.uniform(1.0, 12.0));
    style.join = LineJoin::round;
    style.cap = LineCap::round;
    const std::vector<Vec2> triangles = stroke(path, style, tolerance);
    const double r = style.width / 2.0;
    // The dense samples' chords are within |P0 - 2 P1 + P2| / (4 * 1000^2) < 1e-4 px of the curve
    // (control points within 100 px); the margin holds that, the flattening and the arcs (each
    // within the tolerance).
    const double margin = 2.0 * tolerance + 1e-3;
    int inside = 0, outside = 0;
    for (int j = 0; j < 1500; ++j) {
      const P p{random.uniform(-5, 105), random.uniform(-5, 105)};
      const double d = distance_to_polyline(p, centre);
      if (d <= r - margin) {
        ASSERT_TRUE(covered(triangles, p)) << "trial " << trial << " at distance " << d;
        ++inside;
      } else if (d >= r + margin) {
        ASSERT_FALSE(covered(triangles, p)) << "trial " << trial << " at distance " << d;
        ++outside;
      }
    }
    EXPECT_GT(inside, 0);
    EXPECT_GT(outside, 0);
  }
}

Path right_angle() {
  Path path;
  path.move_to({10, 10});
  path.line_to({50, 10});
  path.line_to({50, 50});
  return path;
}

// A right-angle turn, 8 px wide: the miter's tip (54, 6) lies sqrt(2) half widths from the
// vertex, inside a limit of 4 and beyond one of 1.2 (a bevel, whose edge runs from (50, 6) to
// (54, 10): x - y = 44); round joins reach 4 px from the vertex, less the arcs' tolerance (an
// eighth of a pixel by default), only.
TEST(Path, JoinsAndCapsCoverTheirDefiningPoints) {
  StrokeStyle style;
  style.width = 8.0f;
  style.join = LineJoin::miter;
  const std::vector<Vec2> miter = stroke(right_angle(), style);
  EXPECT_TRUE(covered(miter, {53.9, 6.1}));
  style.miter_limit = 1.2f;
  const std::vector<Vec2> limited = stroke(right_angle(), style);
  EXPECT_FALSE(covered(limited, {53.9, 6.1}));
  EXPECT_TRUE(covered(limited, {51.9, 8.1}));  // inside the bevel's edge
  EXPECT_FALSE(covered(limited, {52.5, 8.0}));
  style.join = LineJoin::bevel;
  EXPECT_EQ(stroke(right_angle(), style).size(), limited.size());
  style.join = LineJoin::round;
  const std::vector<Vec2> round = stroke(right_angle(), style);
  EXPECT_TRUE(covered(round, {50 + 3.8 * std::cos(0.7), 10 - 3.8 * std::sin(0.7)}));
  EXPECT_FALSE(covered(round, {53.9, 6.1}));
  // Caps at (10, 10), leaving towards -x.
  style.cap = LineCap::butt;
  EXPECT_FALSE(covered(stroke(right_angle(), style), {9.0, 10.0}));
  style.cap = LineCap::square;
  EXPECT_TRUE(covered(stroke(right_angle(), style), {6.1, 13.9}));
  style.cap = LineCap::round;
  const std::vector<Vec2> capped = stroke(right_angle(), style);
  EXPECT_TRUE(covered(capped, {6.2, 10.0}));
  EXPECT_FALSE(covered(capped, {6.3, 13.7}));  // beyond the half disk, within the square
}

TEST(Path, AreasOfSegmentsCapsAndDots) {
  Path segment;
  segment.move_to({3.25f, 7.5f});
  segment.line_to({43.25f, 37.5f});  // 50 px long
  StrokeStyle style;
  style.width = 6.0f;
  EXPECT_NEAR(triangle_area_sum(stroke(segment, style)), 50.0 * 6.0, 1e-3);
  style.cap = LineCap::square;
  EXPECT_NEAR(triangle_area_sum(stroke(segment, style)), 56.0 * 6.0, 1e-3);
  // A dot: a square, or an inscribed polygon of the disk within the tolerance of its circle: its
  // area falls short of pi r^2 by less than the perimeter times the tolerance.
  Path dot;
  dot.move_to({20, 20});
  EXPECT_NEAR(triangle_area_sum(stroke(dot, style)), 36.0, 1e-4);
  style.cap = LineCap::round;
  const float tolerance = 0.01f;
  const double area = triangle_area_sum(stroke(dot, style, tolerance));
  EXPECT_LT(area, std::numbers::pi * 9.0);
  EXPECT_GT(area, std::numbers::pi * 9.0 - 2.0 * std::numbers::pi * 3.0 * tolerance);
  style.cap = LineCap::butt;
  EXPECT_TRUE(stroke(dot, style).empty());
}

TEST(Path, ClosedSubpathsJoinAtTheirStartAndTakeNoCaps) {
  Path square;
  square.move_to({10, 10});
  square.line_to({30, 10});
  square.line_to({30, 30});
  square.line_to({10, 30});
  square.close();
  StrokeStyle style;
  style.width = 4.0f;
  style.cap = LineCap::square;  // ignored: no ends
  const std::vector<Vec2> triangles = stroke(square, style);
  EXPECT_TRUE(covered(triangles, {8.1, 8.1}));    // the miter at the start, (8, 8)
  EXPECT_FALSE(covered(triangles, {20, 20}));     // the hole
  EXPECT_FALSE(covered(triangles, {6.0, 10.0}));  // no cap
  // A square ring: (24^2 - 16^2) px^2 from 4 rectangles and 4 miters, overlapping at the
  // corners: the triangles' areas add up to more.
  EXPECT_GT(triangle_area_sum(triangles), 24.0 * 24.0 - 16.0 * 16.0);
}

// Painted into a multisampled target: every ISA covers the same samples (flat colour: the
// images equal the reference's bit for bit), and the resolve shows the edge's coverage.
TEST(Path, PaintingIsTheSameOnEveryIsa) {
  Path path;
  path.move_to({8, 40});
  path.quad_to({64, -20}, {120, 40});
  path.line_to({100, 60});
  StrokeStyle style;
  style.width = 5.0f;
  style.join = LineJoin::round;
  style.cap = LineCap::round;
  const std::vector<Vec2> triangles = stroke(path, style);
  std::vector<std::uint8_t> expected;
  for (Isa isa : compiled_isas()) {
    if (!isa_supported(isa)) continue;
    Framebuffer target(128, 64, 8);
    target.clear({0, 0, 0, 1}, 1.0f);
    const DrawReport report = paint_triangles(target, triangles, {1, 1, 1, 1}, isa);
    EXPECT_GT(report.fragments, 8u * 400u);
    std::vector<std::uint8_t> rgba(128 * 64 * 4);
    resolve(target, rgba);
    if (expected.empty()) {
      expected = rgba;
      // Some pixels partly covered: neither black nor white.
      EXPECT_GT(
          std::count_if(rgba.begin(), rgba.end(), [](std::uint8_t v) { return v > 0 && v < 255; }),
          100);
    }
    EXPECT_EQ(rgba, expected) << name_of(isa);
  }
}

// Exact-area blending: each pixel moves towards the colour by its area (the reference's areas:
// the blend's arithmetic is what is checked here), rounded once: within half a code and the
// float arithmetic's few ulps.
TEST(Path, BlendingByExactAreaMovesEachPixelByItsArea) {
  const Vec2 triangle[3] = {{3.3f, 2.1f}, {27.8f, 9.6f}, {8.2f, 29.4f}};
  Framebuffer target(32, 32);
  target.clear({0.2f, 0.4f, 0.6f, 1.0f}, 1.0f);
  blend_triangle_areas(target, triangle, {1.0f, 0.0f, 0.5f, 1.0f});
  struct Areas final : AreaSink {
    float area[32][32] = {};
    void consume(std::span<const AreaTile> tiles) override {
      for (const AreaTile& t : tiles) {
        for (int i = 0; i < 64; ++i)
          area[t.tile_y * 8 + i / 8][t.tile_x * 8 + i % 8] += t.area[i];
      }
    }
  } areas;
  RasterOptions options;
  options.isa = Isa::reference;
  rasterize_areas(triangle, {}, RasterTarget{32, 32, {}}, options, areas);
  const double background[4] = {51 / 255.0, 102 / 255.0, 153 / 255.0, 1.0};
  const double colour[4] = {1.0, 0.0, 0.5, 1.0};
  int partial = 0;
  for (int y = 0; y < 32; ++y) {
    for (int x = 0; x < 32; ++x) {
      const double a = areas.area[y][x];
      partial += a > 0.0 && a < 1.0;
      for (int k = 0; k < 4; ++k) {
        const double expected = 255.0 * (background[k] + a * (colour[k] - background[k]));
        const int got = static_cast<int>((target.color(x, y) >> (8 * k)) & 0xFF);
        EXPECT_LE(std::abs(got - expected), 0.5 + 1e-4) << x << "," << y << " channel " << k;
      }
    }
  }
  EXPECT_GT(partial, 40);
}

// Where two triangles meet inside a pixel, each blends its own part: the background shows
// through the seam (conflation). A white square on black, cut along its diagonal: a pixel the
// diagonal halves gets 1 - (1 - 1/2)(1 - 1/2) = 3/4 of white, not all of it (in codes: 127.5,
// stored as 128 (to even), then 128 + 63.5 = 191.5, stored as 192).
TEST(Path, BlendingByExactAreaLeaksAtSharedEdges) {
  const Vec2 square[6] = {{4, 4}, {20, 4}, {20, 20}, {4, 4}, {20, 20}, {4, 20}};
  Framebuffer target(24, 24);
  target.clear({0, 0, 0, 1}, 1.0f);
  blend_triangle_areas(target, square, {1, 1, 1, 1});
  for (int i = 5; i < 19; ++i) {
    EXPECT_EQ(target.color(i, i) & 0xFF, 192u) << i;
    EXPECT_EQ(target.color(i + 1, i) & 0xFF, 255u) << i;  // whole pixels: no seam
  }
  Framebuffer multisampled(8, 8, 4);
  EXPECT_THROW(blend_triangle_areas(multisampled, square, {1, 1, 1, 1}), std::invalid_argument);
}

TEST(Path, RefusesBadInput) {
  Path path;
  path.move_to({0, 0});
  path.line_to({10, 0});
  StrokeStyle style;
  for (float width : {0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(),
                      std::numeric_limits<float>::infinity()}) {
    style.width = width;
    EXPECT_THROW(stroke(path, style), std::invalid_argument);
  }
  style.width = 1.0f;
  style.miter_limit = 0.5f;
  EXPECT_THROW(stroke(path, style), std::invalid_argument);
  style.miter_limit = 4.0f;
  EXPECT_THROW(stroke(path, style, 0.0f), std::invalid_argument);
  EXPECT_THROW(flatten(path, std::numeric_limits<float>::quiet_NaN()), std::invalid_argument);
  Path bad;
  bad.move_to({0, 0});
  bad.line_to({std::numeric_limits<float>::infinity(), 0});
  EXPECT_THROW(flatten(bad), std::invalid_argument);
  Framebuffer target(8, 8);
  const Vec2 four[4] = {{0, 0}, {1, 0}, {0, 1}, {1, 1}};
  EXPECT_THROW(paint_triangles(target, four, {1, 1, 1, 1}), std::invalid_argument);
  // A line after close() starts at the closed subpath's start.
  Path reopened;
  reopened.move_to({5, 5});
  reopened.line_to({9, 5});
  reopened.close();
  reopened.line_to({5, 9});
  const std::vector<Polyline> lines = flatten(reopened);
  ASSERT_EQ(lines.size(), 2u);
  EXPECT_EQ(lines[1].points.front().x, 5.0f);
  EXPECT_EQ(lines[1].points.front().y, 5.0f);
}

}  // namespace
}  // namespace edgewise::test
