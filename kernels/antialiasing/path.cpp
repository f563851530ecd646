// Paths and their flattening (path.hpp).
#include <algorithm>
#include <cmath>
#include <sstream>
#include <stdexcept>
#include <string>

#include "edgewise/path.hpp"

namespace edgewise {
namespace {

bool finite(Vec2 p) {
  return std::isfinite(p.x) && std::isfinite(p.y);
}

void check_tolerance(float tolerance, const char* what) {
  if (!(tolerance > 0.0f) || !std::isfinite(tolerance)) {
    throw std::invalid_argument(std::string(what) + ": tolerance " + std::to_string(tolerance) +
                                " is not positive and finite");
  }
}

// The fewest equal steps of t that keep the quadratic's float polyline within `tolerance`
// (path.hpp, "Flattening"); `what` names the caller in the errors.
std::size_t segments_within(Vec2 p0, Vec2 p1, Vec2 p2, float tolerance, const char* what) {
  check_tolerance(tolerance, what);
  double magnitude = 0.0;
  for (const Vec2 p : {p0, p1, p2})
    magnitude = std::max({magnitude, std::fabs(double{p.x}), std::fabs(double{p.y})});
  const double least = least_path_tolerance(magnitude);
  if (tolerance < least) {
    std::ostringstream message;
    message << what << ": tolerance " << tolerance << " px is below " << least
            << " px, the least that float points with coordinates up to " << magnitude
            << " px can keep";
    throw std::invalid_argument(message.str());
  }
  // What the chords may use: at least half the tolerance.
  const double budget = tolerance - path_rounding(magnitude);
  // In double: |P0 - 2 P1 + P2| exactly enough that n is the formula's. This arithmetic may leave
  // a chord over the budget by a few ulps only where |d| is about 4 budget n^2 >= 2 tolerance,
  // so m >= |d| / (4 sqrt(2)) >= tolerance / (2 sqrt(2)): path_rounding()'s slack, 0.08 2^-24 m,
  // covers that.
  const double dx = static_cast<double>(p0.x) - 2.0 * p1.x + p2.x;
  const double dy = static_cast<double>(p0.y) - 2.0 * p1.y + p2.y;
  const double n = std::ceil(std::sqrt(std::hypot(dx, dy) / (4.0 * budget)));
  return n < 1.0 ? 1 : static_cast<std::size_t>(n);  // at most kMaxQuadSegments (path.hpp)
}

// Appends p unless it repeats the last point.
void append(Polyline& line, Vec2 p) {
  if (!line.points.empty() && line.points.back().x == p.x && line.points.back().y == p.y) return;
  line.points.push_back(p);
}

}  // namespace

void Path::move_to(Vec2 p) {
  commands_.push_back({Verb::move, {p, p}});
  open_ = true;
  start_ = p;
}

void Path::line_to(Vec2 p) {
  if (!open_) move_to(start_);
  commands_.push_back({Verb::line, {p, p}});
}

void Path::quad_to(Vec2 control, Vec2 end) {
  if (!open_) move_to(start_);
  commands_.push_back({Verb::quad, {control, end}});
}

void Path::close() {
  if (!open_) return;
  commands_.push_back({Verb::close, {}});
  open_ = false;
}

double path_rounding(double magnitude) {
  return 0x1.8p-24 * magnitude + 0x1p-149;
}

double least_path_tolerance(double magnitude) {
  return 2.0 * path_rounding(magnitude);
}

std::size_t quad_segments(Vec2 p0, Vec2 p1, Vec2 p2, float tolerance) {
  return segments_within(p0, p1, p2, tolerance, "quad_segments");
}

std::vector<Polyline> flatten(const Path& path, float tolerance) {
  check_tolerance(tolerance, "flatten");
  std::vector<Polyline> lines;
  Vec2 current{0.0f, 0.0f};
  for (const Path::Command& c : path.commands()) {
    for (int i = 0; i < (c.verb == Path::Verb::quad    ? 2
                         : c.verb == Path::Verb::close ? 0
                                                       : 1);
         ++i) {
      if (!finite(c.points[i])) throw std::invalid_argument("flatten: a path point is not finite");
    }
    switch (c.verb) {
      case Path::Verb::move:
        lines.push_back({});
        current = c.points[0];
        append(lines.back(), current);
        break;
      case Path::Verb::line:
        current = c.points[0];
        append(lines.back(), current);
        break;
      case Path::Verb::quad: {
        const Vec2 p0 = current, p1 = c.points[0], p2 = c.points[1];
        const std::size_t n = segments_within(p0, p1, p2, tolerance, "flatten");
        for (std::size_t k = 1; k <= n; ++k) {
          // B(t) in double, each point rounded to float once; the last is P2 itself.
          const double t = static_cast<double>(k) / static_cast<double>(n), u = 1.0 - t;
          const Vec2 p =
              k == n ? p2
                     : Vec2{static_cast<float>(u * u * p0.x + 2.0 * t * u * p1.x + t * t * p2.x),
                            static_cast<float>(u * u * p0.y + 2.0 * t * u * p1.y + t * t * p2.y)};
          append(lines.back(), p);
        }
        current = p2;
        break;
      }
      case Path::Verb::close: {
        Polyline& line = lines.back();
        line.closed = true;
        // The closing segment is implicit: a last point equal to the first is dropped.
        if (line.points.size() > 1 && line.points.back().x == line.points.front().x &&
            line.points.back().y == line.points.front().y) {
          line.points.pop_back();
        }
        current = line.points.front();
        break;
      }
    }
  }
  return lines;
}

}  // namespace edgewise
