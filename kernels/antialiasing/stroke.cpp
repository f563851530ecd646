// Strokes of flattened paths as triangles (path.hpp): a rectangle per segment, a join at each
// turn, a cap at each open end. The geometry is computed in double and rounded to float once per
// point.
#include <algorithm>
#include <cmath>
#include <numbers>
#include <sstream>
#include <stdexcept>
#include <string>

#include "edgewise/path.hpp"

namespace edgewise {
namespace {

struct Point {
  double x, y;
};

Point operator+(Point a, Point b) {
  return {a.x + b.x, a.y + b.y};
}
Point operator-(Point a, Point b) {
  return {a.x - b.x, a.y - b.y};
}
Point operator*(double s, Point a) {
  return {s * a.x, s * a.y};
}
double dot(Point a, Point b) {
  return a.x * b.x + a.y * b.y;
}
double cross(Point a, Point b) {
  return a.x * b.y - a.y * b.x;
}
Point perpendicular(Point d) {
  return {-d.y, d.x};
}
Point rotated(Point v, double angle) {
  const double c = std::cos(angle), s = std::sin(angle);
  return {c * v.x - s * v.y, s * v.x + c * v.y};
}
Point unit(Point d) {
  const double length = std::hypot(d.x, d.y);
  return {d.x / length, d.y / length};
}

class StrokeBuilder {
 public:
  StrokeBuilder(const StrokeStyle& style, float tolerance, std::vector<Vec2>& out)
      : style_(style), half_(0.5 * style.width), tolerance_(tolerance), out_(out) {}

  void polyline(const Polyline& line) {
    std::vector<Point> p;
    for (const Vec2& v : line.points)
      p.push_back({v.x, v.y});
    const std::size_t n = p.size();
    if (n == 1) return dot_at(p[0]);
    const std::size_t segments = line.closed ? n : n - 1;
    if (line.closed && n == 2) {  // there and back: two segments over one line, no turn to fill
      segment(p[0], p[1]);
      return;
    }
    for (std::size_t i = 0; i < segments; ++i)
      segment(p[i], p[(i + 1) % n]);
    for (std::size_t i = line.closed ? 0 : 1; i < (line.closed ? n : n - 1); ++i)
      join(p[(i + n - 1) % n], p[i], p[(i + 1) % n]);
    if (!line.closed) {
      cap(p[0], unit(p[0] - p[1]));
      cap(p[n - 1], unit(p[n - 1] - p[n - 2]));
    }
  }

 private:
  void triangle(Point a, Point b, Point c) {
    for (Point q : {a, b, c})
      out_.push_back({static_cast<float>(q.x), static_cast<float>(q.y)});
  }

  void segment(Point a, Point b) {
    const Point offset = half_ * perpendicular(unit(b - a));
    triangle(a + offset, b + offset, b - offset);
    triangle(a + offset, b - offset, a - offset);
  }

  // Triangles around `centre` from centre + from, turning by `angle` (signed), each side within
  // the tolerance of the circle of radius |from| = half_ once its corners are rounded to float.
  void fan(Point centre, Point from, double angle) {
    const int steps = std::max(1, static_cast<int>(std::ceil(std::fabs(angle) / max_step(centre))));
    Point previous = centre + from;
    for (int k = 1; k <= steps; ++k) {
      const Point next = centre + rotated(from, angle * k / steps);
      triangle(centre, previous, next);
      previous = next;
    }
  }

  // The outer side of the turn at v, from the segment a -> v to v -> b.
  void join(Point a, Point v, Point b) {
    const Point d1 = unit(v - a), d2 = unit(b - v);
    const double turn = std::atan2(cross(d1, d2), dot(d1, d2));  // signed, in [-pi, pi]
    if (turn == 0.0) return;                                     // straight on
    // The path turns towards +perpendicular when turn > 0: the outer side is the other one.
    const double side = turn > 0.0 ? -1.0 : 1.0;
    const Point n1 = side * half_ * perpendicular(d1), n2 = side * half_ * perpendicular(d2);
    switch (style_.join) {
      case LineJoin::round:
        return fan(v, n1, turn);
      case LineJoin::miter: {
        // The miter's tip: where the two outer edges meet, |tip - v| = r sqrt(2 / (1 + n1.n2)).
        const double c = dot(n1, n2) / (half_ * half_);
        if (c > -1.0 && 2.0 / (1.0 + c) <= static_cast<double>(style_.miter_limit) *
                                               static_cast<double>(style_.miter_limit)) {
          const Point tip = v + (1.0 / (1.0 + c)) * (n1 + n2);
          triangle(v, v + n1, tip);
          triangle(v, tip, v + n2);
          return;
        }
        [[fallthrough]];  // beyond the limit: a bevel
      }
      case LineJoin::bevel:
        triangle(v, v + n1, v + n2);
        return;
    }
  }

  // The cap at an open end e, `out` the unit direction leaving the stroke there.
  void cap(Point e, Point out) {
    const Point n = half_ * perpendicular(out), o = half_ * out;
    switch (style_.cap) {
      case LineCap::butt:
        return;
      case LineCap::square:
        triangle(e + n, e + n + o, e - n + o);
        triangle(e + n, e - n + o, e - n);
        return;
      case LineCap::round:
        // From +n through the outward direction to -n: a half turn whose sign passes `out`.
        return fan(e, n, cross(n, o) > 0.0 ? std::numbers::pi : -std::numbers::pi);
    }
  }

  // A subpath of one point: the cap's shape on its own.
  void dot_at(Point e) {
    switch (style_.cap) {
      case LineCap::butt:
        return;
      case LineCap::square: {
        const Point a{e.x - half_, e.y - half_}, b{e.x + half_, e.y - half_};
        const Point c{e.x + half_, e.y + half_}, d{e.x - half_, e.y + half_};
        triangle(a, b, c);
        triangle(a, c, d);
        return;
      }
      case LineCap::round:
        return fan(e, {half_, 0.0}, 2.0 * std::numbers::pi);
    }
  }

  // The largest angle an arc's side around `centre` may span. An inscribed polygon's side of
  // angle a misses its circle by r (1 - cos(a / 2)) (the sagitta), and rounding its corners to
  // float moves it by at most path_rounding(m) more, m bounding the arc's coordinates (path.hpp,
  // "Stroking"): a <= 2 acos(1 - (tolerance - path_rounding(m)) / r) keeps it within the
  // tolerance. No side spans more than a quarter turn, whatever the tolerance. The least
  // tolerance leaves at least half of it to the sagitta, so a full circle takes at most
  // pi sqrt(2^24 / 3), about 7,400, sides.
  double max_step(Point centre) const {
    const double magnitude = std::max(std::fabs(centre.x), std::fabs(centre.y)) + half_;
    const double least = least_path_tolerance(magnitude);
    if (tolerance_ < least) {
      std::ostringstream message;
      message << "stroke: tolerance " << tolerance_ << " px is below " << least
              << " px, the least that float points with coordinates up to " << magnitude
              << " px (an arc of radius " << half_ << " around (" << centre.x << ", " << centre.y
              << ")) can keep";
      throw std::invalid_argument(message.str());
    }
    const double ratio = (tolerance_ - path_rounding(magnitude)) / half_;
    return ratio < 1.0 ? std::min(2.0 * std::acos(1.0 - ratio), std::numbers::pi / 2)
                       : std::numbers::pi / 2;
  }

  StrokeStyle style_;
  double half_;       // half the width: the stroke's reach from the path
  double tolerance_;  // how far an arc's sides may stray from their circle
  std::vector<Vec2>& out_;
};

}  // namespace

std::vector<Vec2> stroke(const Path& path, const StrokeStyle& style, float tolerance) {
  if (!(style.width > 0.0f) || !std::isfinite(style.width)) {
    throw std::invalid_argument("stroke: width " + std::to_string(style.width) +
                                " is not positive and finite");
  }
  if (!(style.miter_limit >= 1.0f) || !std::isfinite(style.miter_limit)) {
    throw std::invalid_argument("stroke: miter limit " + std::to_string(style.miter_limit) +
                                " is not finite and at least 1");
  }
  std::vector<Vec2> triangles;
  StrokeBuilder builder(style, tolerance, triangles);
  for (const Polyline& line : flatten(path, tolerance))
    builder.polyline(line);
  return triangles;
}

}  // namespace edgewise
