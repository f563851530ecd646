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

double largest_coordinate(P p0, P p1, P p2) {
  return std::max({std::fabs(p0.x), std::fabs(p0.y), std::fabs(p1.x), std::fabs(p1.y),
                   std::fabs(p2.x), std::fabs(p2.y)});
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

// Flattening: every step's chord, between the float points, within the tolerance of the curve at
// the same parameter (sampled), and one step fewer would not keep the exact chords within what
// the tolerance leaves them after the points' rounding.
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
    EXPECT_LE(worst, tolerance) << "trial " << trial << ", " << n << " steps";
    const double d = std::hypot(q0.x - 2 * q1.x + q2.x, q0.y - 2 * q1.y + q2.y);
    if (n > 1) {
      // n - 1 equal steps miss the curve by d / (4 (n - 1)^2) at a step's middle.
      EXPECT_GT(d / (4.0 * static_cast<double>(n - 1) * static_cast<double>(n - 1)),
                tolerance - path_rounding(largest_coordinate(q0, q1, q2)))
          << "trial " << trial;
    }
  }
}

// The largest |D(s)| over s in [0, 1], D(s) = c0 + c1 s + c2 s^2 (vectors): at an end or where
// D . D' = 0, a cubic. Its derivative's roots cut [0, 1] into pieces on which it is monotone;
// bisection finds its one root in a piece, if any, to double precision.
double largest_norm(P c0, P c1, P c2) {
  const auto dot = [](P a, P b) { return a.x * b.x + a.y * b.y; };
  const auto norm = [&](double s) {
    return std::hypot(c0.x + s * (c1.x + s * c2.x), c0.y + s * (c1.y + s * c2.y));
  };
  const double a3 = 2 * dot(c2, c2), a2 = 3 * dot(c1, c2), a1 = dot(c1, c1) + 2 * dot(c0, c2);
  const double a0 = dot(c0, c1);
  const auto cubic = [&](double s) { return ((a3 * s + a2) * s + a1) * s + a0; };
  std::vector<double> cuts{0.0, 1.0};
  // 3 a3 s^2 + 2 a2 s + a1 = 0, by the stable form of the quadratic formula.
  const double qa = 3 * a3, qb = 2 * a2, qc = a1;
  if (qa != 0.0) {
    const double disc = qb * qb - 4 * qa * qc;
    if (disc >= 0.0) {
      const double q = -0.5 * (qb + std::copysign(std::sqrt(disc), qb));
      cuts.push_back(q / qa);
      if (q != 0.0) cuts.push_back(qc / q);
    }
  } else if (qb != 0.0) {
    cuts.push_back(-qc / qb);
  }
  std::erase_if(cuts, [](double s) { return !(s >= 0.0 && s <= 1.0); });
  std::sort(cuts.begin(), cuts.end());
  double best = std::max(norm(0.0), norm(1.0));
  for (std::size_t i = 0; i + 1 < cuts.size(); ++i) {
    double lo = cuts[i], hi = cuts[i + 1];
    const bool rising = cubic(lo) < 0.0;
    if ((cubic(hi) < 0.0) == rising) continue;  // no root inside
    for (int k = 0; k < 200 && lo < hi; ++k) {
      const double mid = 0.5 * (lo + hi);
      if (mid <= lo || mid >= hi) break;
      ((cubic(mid) < 0.0) == rising ? lo : hi) = mid;
    }
    best = std::max({best, norm(lo), norm(hi)});
  }
  return best;
}

// How far the polyline of flatten() strays from the curve of q0, q1, q2 (the float control
// points, exactly): for each step k of n, the largest distance between B(t) and the point of the
// polyline at the same fraction of the step, exactly (largest_norm). The distance from the curve
// to the polyline is at most that. D(s) = B(t_k + s h) - ((1 - s) Q_k + s Q_{k+1}) = c0 + c1 s
// + c2 s^2 with c2 = h^2 d, c0 = B(t_k) - Q_k and c0 + c1 + c2 = B(t_{k+1}) - Q_{k+1}. The
// double arithmetic here errs by a few 2^-53 m, far below the slack of path_rounding() (at least
// 0.08 2^-24 m) that keeps a correct flattening away from the tolerance.
double parametric_deviation(P q0, P q1, P q2, const std::vector<Vec2>& points) {
  const std::size_t n = points.size() - 1;
  const double h = 1.0 / static_cast<double>(n);
  const P d{q0.x - 2 * q1.x + q2.x, q0.y - 2 * q1.y + q2.y};
  const P c2{h * h * d.x, h * h * d.y};
  double worst = 0.0;
  P e0{0.0, 0.0};  // B(0) - Q_0: P0 is kept exactly
  for (std::size_t k = 0; k < n; ++k) {
    const P b = bezier(q0, q1, q2, static_cast<double>(k + 1) / static_cast<double>(n));
    const P e1{b.x - points[k + 1].x, b.y - points[k + 1].y};
    worst = std::max(worst, largest_norm(e0, {e1.x - e0.x - c2.x, e1.y - e0.y - c2.y}, c2));
    e0 = e1;
  }
  return worst;
}

// The polyline's point at each of the n + 1 steps. flatten() drops a point equal to the one
// before it (at a cusp two steps' points may round to the same float): at each step the point
// nearer B(t_k) of the current and the next polyline point, so that a dropped repeat comes back.
// Fewer than n + 1 points come back if the polyline does not follow the steps.
std::vector<Vec2> step_points(P q0, P q1, P q2, std::size_t n, const std::vector<Vec2>& polyline) {
  std::vector<Vec2> points{polyline.front()};
  std::size_t j = 0;
  for (std::size_t k = 1; k <= n; ++k) {
    const P b = bezier(q0, q1, q2, static_cast<double>(k) / static_cast<double>(n));
    const auto distance = [&](std::size_t i) {
      return std::hypot(polyline[i].x - b.x, polyline[i].y - b.y);
    };
    if (j + 1 < polyline.size() && distance(j + 1) <= distance(j)) ++j;
    points.push_back(polyline[j]);
  }
  if (j + 1 != polyline.size()) points.pop_back();
  return points;
}

// The least float tolerance flatten() accepts for coordinates up to `magnitude`.
float least_float_tolerance(double magnitude) {
  const double least = least_path_tolerance(magnitude);
  float f = static_cast<float>(least);
  if (f < least) f = std::nextafter(f, std::numeric_limits<float>::infinity());
  return f;
}

// The accepted range, log-spaced from its least value to 64 px (both included), and far beyond.
std::vector<float> tolerances_across_range(double magnitude, int count) {
  const double lo = least_float_tolerance(magnitude), hi = 64.0;
  std::vector<float> tolerances;
  for (int i = 0; i < count; ++i)
    tolerances.push_back(
        i == 0 ? static_cast<float>(lo)
        : i == count - 1
            ? static_cast<float>(hi)
            : static_cast<float>(lo * std::pow(hi / lo, static_cast<double>(i) / (count - 1))));
  tolerances.push_back(std::numeric_limits<float>::max());
  return tolerances;
}

// The flattening's guarantee across the whole accepted range of tolerances, with the rounding
// of its points to float included: quadratics across the guard band (+-32768 px), at the tool's
// sheet's magnitudes (up to 960 px, and its own curves), near the origin, and the one that takes
// the most segments. Tolerances just below the least accepted one, and bad ones, throw.
TEST(Path, FlatteningKeepsEveryToleranceOfItsRange) {
  Random random(81);
  struct Curve {
    P p0, p1, p2;
  };
  std::vector<Curve> curves;
  const auto random_point = [&random](double x0, double x1, double y0, double y1) {
    return P{random.uniform(x0, x1), random.uniform(y0, y1)};
  };
  for (int i = 0; i < 60; ++i) {
    const double band = 32768.0;
    curves.push_back({random_point(-band, band, -band, band),
                      random_point(-band, band, -band, band),
                      random_point(-band, band, -band, band)});
  }
  for (int i = 0; i < 60; ++i) {  // a small curve somewhere in the guard band
    const P at = random_point(-32768, 32768, -32768, 32768);
    const double size = random.log_uniform(1.0, 1000.0);
    const auto near = [&] {
      return P{at.x + random.uniform(-size, size), at.y + random.uniform(-size, size)};
    };
    curves.push_back({near(), near(), near()});
  }
  for (int i = 0; i < 60; ++i) {
    curves.push_back(
        {random_point(0, 960, 0, 540), random_point(0, 960, 0, 540), random_point(0, 960, 0, 540)});
  }
  for (int i = 0; i < 7; ++i) {  // edgewise-strokes' sheet
    const double y = 345.0 + 27.0 * i;
    curves.push_back({{40, y}, {230, y - 100}, {420, y}});
  }
  for (int i = 0; i < 20; ++i) {
    const double size = random.log_uniform(0.01, 10.0);
    curves.push_back({random_point(-size, size, -size, size),
                      random_point(-size, size, -size, size),
                      random_point(-size, size, -size, size)});
  }
  curves.push_back({{32768, 32768}, {-32768, -32768}, {32768, 32768}});  // |d| = 4 sqrt(2) m
  std::size_t most = 0;
  for (std::size_t c = 0; c < curves.size(); ++c) {
    const auto f = [](P p) { return Vec2{static_cast<float>(p.x), static_cast<float>(p.y)}; };
    const Vec2 v0 = f(curves[c].p0), v1 = f(curves[c].p1), v2 = f(curves[c].p2);
    const P q0{v0.x, v0.y}, q1{v1.x, v1.y}, q2{v2.x, v2.y};
    const double m = largest_coordinate(q0, q1, q2);
    Path path;
    path.move_to(v0);
    path.quad_to(v1, v2);
    for (const float tolerance : tolerances_across_range(m, 9)) {
      const std::size_t n = quad_segments(v0, v1, v2, tolerance);
      const std::vector<Polyline> lines = flatten(path, tolerance);
      ASSERT_EQ(lines.size(), 1u);
      ASSERT_LE(n, kMaxQuadSegments);
      most = std::max(most, n);
      const std::vector<Vec2> points = step_points(q0, q1, q2, n, lines[0].points);
      ASSERT_EQ(points.size(), n + 1) << "curve " << c << ", tolerance " << tolerance;
      EXPECT_LE(parametric_deviation(q0, q1, q2, points), tolerance)
          << "curve " << c << " (largest coordinate " << m << "), tolerance " << tolerance << ", "
          << n << " steps";
    }
    // Below the range, and bad tolerances.
    const float below = std::nextafter(least_float_tolerance(m), 0.0f);
    for (const float bad : {below, 0.0f, -1.0f, std::numeric_limits<float>::quiet_NaN(),
                            std::numeric_limits<float>::infinity()}) {
      EXPECT_THROW(quad_segments(v0, v1, v2, bad), std::invalid_argument) << "curve " << c;
      EXPECT_THROW(flatten(path, bad), std::invalid_argument) << "curve " << c;
      EXPECT_THROW(stroke(path, StrokeStyle{}, bad), std::invalid_argument) << "curve " << c;
    }
  }
  // The last curve takes nearly kMaxQuadSegments at its least tolerance: the bound is tight.
  EXPECT_GT(most, kMaxQuadSegments - 10);
}

// Arcs (round joins and caps) keep their tolerance after their corners' rounding, across the
// accepted range: full circles (a dot's round cap) around centres across the guard band and at
// the sheet's magnitudes. Each triangle of the fan is (centre, corner, next corner): the side
// between the corners strays from the circle by at most its corners' distances from it outwards
// (|X - C| is convex along a segment) and by r minus the side's distance from the centre inwards.
TEST(Path, ArcsKeepEveryToleranceOfItsRange) {
  Random random(82);
  for (int trial = 0; trial < 80; ++trial) {
    const double band = trial < 50 ? 32768.0 : 960.0;
    const Vec2 centre{static_cast<float>(random.uniform(-band, band)),
                      static_cast<float>(random.uniform(-band, band))};
    StrokeStyle style;
    style.width = static_cast<float>(random.log_uniform(0.5, 200.0));
    style.cap = LineCap::round;
    Path dot;
    dot.move_to(centre);
    const P c{centre.x, centre.y};
    const double r = 0.5 * style.width;
    const double m = std::max(std::fabs(c.x), std::fabs(c.y)) + r;
    for (const float tolerance : tolerances_across_range(m, 7)) {
      const std::vector<Vec2> triangles = stroke(dot, style, tolerance);
      ASSERT_GE(triangles.size(), 12u);
      double worst = 0.0;
      for (std::size_t t = 0; t < triangles.size(); t += 3) {
        const P a{triangles[t + 1].x, triangles[t + 1].y},
            b{triangles[t + 2].x, triangles[t + 2].y};
        worst = std::max({worst, std::hypot(a.x - c.x, a.y - c.y) - r,
                          std::hypot(b.x - c.x, b.y - c.y) - r, r - distance_to_segment(c, a, b)});
      }
      EXPECT_LE(worst, tolerance) << "trial " << trial << ": centre (" << c.x << ", " << c.y
                                  << "), radius " << r << ", tolerance " << tolerance;
    }
    EXPECT_THROW(stroke(dot, style, std::nextafter(least_float_tolerance(m), 0.0f)),
                 std::invalid_argument)
        << "trial " << trial;
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
