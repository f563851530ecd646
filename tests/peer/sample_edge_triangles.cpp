#include "sample_edge_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace edgewise::test {
namespace {

constexpr std::int32_t kSixteenth = kFixedOne / 16;

struct Target {
  std::int32_t width, height;
  std::span<const SampleOffset> pattern;

  bool holds(const FixedPoint& p) const {
    return p.x >= 0 && p.y >= 0 && p.x <= width * kFixedOne && p.y <= height * kFixedOne;
  }
};

const SampleOffset& any_sample(Random& random, std::span<const SampleOffset> pattern) {
  return pattern[std::size_t(random.integer(0, std::int64_t(pattern.size()) - 1))];
}

// The x (or y) of a random sample of the pixel column (or row) that holds `near`, clamped to
// the target: a vertical (or horizontal) line through samples.
std::int32_t sample_line(Random& random, const Target& target, std::int32_t near, bool x_axis) {
  const std::int32_t pixels = x_axis ? target.width : target.height;
  const std::int32_t pixel = std::clamp<std::int32_t>(near >> 8, 0, pixels - 1);
  const SampleOffset& s = any_sample(random, target.pattern);
  return pixel * kFixedOne + kFixedOne / 2 + kSixteenth * (x_axis ? s.x : s.y);
}

// The position of a random sample of a random pixel whose column lies in [x_lo, x_hi) and row in
// [y_lo, y_hi).
FixedPoint sample_point(Random& random, const Target& target, std::int32_t x_lo, std::int32_t x_hi,
                        std::int32_t y_lo, std::int32_t y_hi) {
  const SampleOffset& s = any_sample(random, target.pattern);
  return {
      std::int32_t(random.integer(x_lo, x_hi - 1)) * kFixedOne + kFixedOne / 2 + kSixteenth * s.x,
      std::int32_t(random.integer(y_lo, y_hi - 1)) * kFixedOne + kFixedOne / 2 + kSixteenth * s.y};
}

// A length in whole sixteenths of a pixel, log-uniform between lo and hi pixels, at least 1/16.
std::int32_t sixteenths(Random& random, double lo, double hi) {
  return std::max<std::int32_t>(1, std::int32_t(std::lround(random.log_uniform(lo, hi) * 16))) *
         kSixteenth;
}

std::int32_t any_sign(Random& random) {
  return random.chance(0.5) ? 1 : -1;
}

FixedPoint offset(const FixedPoint& p, std::int32_t dx, std::int32_t dy) {
  return {p.x + dx, p.y + dy};
}

// Anywhere on the 1/256 px grid, 1 to 60 px across.
void random_triangle(Random& random, const Target& target, std::vector<FixedTriangle>& out) {
  const double size = random.log_uniform(1.0, 60.0);
  const double cx = random.uniform(size / 2, target.width - size / 2);
  const double cy = random.uniform(size / 2, target.height - size / 2);
  FixedTriangle t;
  for (FixedPoint& p : t) {
    const double angle = random.uniform(0.0, 2 * std::numbers::pi);
    const double radius = size / 2 * std::sqrt(random.uniform());
    p = {std::int32_t(std::lround((cx + radius * std::cos(angle)) * kFixedOne)),
         std::int32_t(std::lround((cy + radius * std::sin(angle)) * kFixedOne))};
  }
  out.push_back(t);
}

// Sides on sample lines: one right triangle, or the rectangle as two along a diagonal.
void rectangle(Random& random, const Target& target, std::vector<FixedTriangle>& out) {
  const std::int32_t x0 = sample_line(
      random, target, std::int32_t(random.integer(0, target.width * kFixedOne - 1)), true);
  const std::int32_t y0 = sample_line(
      random, target, std::int32_t(random.integer(0, target.height * kFixedOne - 1)), false);
  const std::int32_t x1 =
      sample_line(random, target, x0 + any_sign(random) * sixteenths(random, 1.0, 60.0), true);
  const std::int32_t y1 =
      sample_line(random, target, y0 + any_sign(random) * sixteenths(random, 1.0, 60.0), false);
  const FixedPoint a{x0, y0}, b{x1, y0}, c{x1, y1}, d{x0, y1};
  if (random.chance(0.5)) {
    if (random.chance(0.5)) {
      out.push_back({a, b, c});
      out.push_back({a, c, d});
    } else {
      out.push_back({a, b, d});
      out.push_back({b, c, d});
    }
    return;
  }
  const FixedTriangle corners[] = {{b, c, d}, {a, c, d}, {a, b, d}, {a, b, c}};
  out.push_back(corners[random.integer(0, 3)]);
}

// A right isosceles triangle with its legs along the axes and a vertex on a sample: its 45-degree
// edge starts at that sample and passes through the same sample of every pixel it crosses
// diagonally. Half of them come with their mirror image along that edge.
void diagonal(Random& random, const Target& target, std::vector<FixedTriangle>& out) {
  const FixedPoint v = sample_point(random, target, 0, target.width, 0, target.height);
  const std::int32_t leg = sixteenths(random, 1.0, 60.0);
  const std::int32_t dx = any_sign(random) * leg, dy = any_sign(random) * leg;
  const FixedPoint far = offset(v, dx, dy);
  const FixedPoint side = offset(v, dx, 0), other_side = offset(v, 0, dy);
  out.push_back({v, far, side});
  if (random.chance(0.5)) out.push_back({v, other_side, far});
}

// A closed fan of 4 to 8 triangles around a vertex on a sample: each spoke is shared by two
// triangles and the centre by all.
void fan(Random& random, const Target& target, std::vector<FixedTriangle>& out) {
  constexpr std::int32_t kMargin = 31;  // px: the longest spoke is 30
  const FixedPoint centre = sample_point(random, target, kMargin, target.width - kMargin, kMargin,
                                         target.height - kMargin);
  const int spokes = int(random.integer(4, 8));
  const double start = random.uniform(0.0, 2 * std::numbers::pi);
  std::vector<FixedPoint> rim;
  for (int i = 0; i < spokes; ++i) {
    // Gaps below half a turn: the fan stays closed around its centre.
    const double angle = start + 2 * std::numbers::pi * (i + random.uniform(0.0, 0.5)) / spokes;
    const double radius = random.log_uniform(1.0, 30.0);
    rim.push_back(
        {centre.x + std::int32_t(std::lround(radius * std::cos(angle) * 16)) * kSixteenth,
         centre.y + std::int32_t(std::lround(radius * std::sin(angle) * 16)) * kSixteenth});
  }
  for (int i = 0; i < spokes; ++i)
    out.push_back({centre, rim[i], rim[(i + 1) % spokes]});
}

// A 2x2 to 5x5 grid of quads, each cut along a random diagonal. Half are regular with a spacing
// of whole pixels, so every vertex lies on the same sample as the first; the others have any
// spacing in sixteenths and each vertex jittered by up to a quarter of it.
void mesh(Random& random, const Target& target, std::vector<FixedTriangle>& out) {
  const int columns = int(random.integer(2, 5)), rows = int(random.integer(2, 5));
  const bool regular = random.chance(0.5);
  const std::int32_t spacing = regular ? std::int32_t(random.integer(1, 12)) * kFixedOne
                                       : std::int32_t(random.integer(16, 192)) * kSixteenth;
  const std::int32_t jitter = regular ? 0 : spacing / kSixteenth / 4;
  const std::int32_t extent =
      (std::max(columns, rows) * spacing + jitter * kSixteenth) / kFixedOne + 2;
  const FixedPoint origin =
      sample_point(random, target, 1, target.width - extent, 1, target.height - extent);
  std::vector<FixedPoint> grid;
  for (int j = 0; j <= rows; ++j) {
    for (int i = 0; i <= columns; ++i) {
      grid.push_back(
          offset(origin, i * spacing + std::int32_t(random.integer(-jitter, jitter)) * kSixteenth,
                 j * spacing + std::int32_t(random.integer(-jitter, jitter)) * kSixteenth));
    }
  }
  const auto at = [&](int i, int j) { return grid[std::size_t(j * (columns + 1) + i)]; };
  for (int j = 0; j < rows; ++j) {
    for (int i = 0; i < columns; ++i) {
      const FixedPoint a = at(i, j), b = at(i + 1, j), c = at(i + 1, j + 1), d = at(i, j + 1);
      if (random.chance(0.5)) {
        out.push_back({a, b, c});
        out.push_back({a, c, d});
      } else {
        out.push_back({a, b, d});
        out.push_back({b, c, d});
      }
    }
  }
}

// One of the six orders of t's vertices: both windings.
FixedTriangle any_order(Random& random, FixedTriangle t) {
  std::rotate(t.begin(), t.begin() + random.integer(0, 2), t.end());
  if (random.chance(0.5)) std::swap(t[1], t[2]);
  return t;
}

}  // namespace

std::vector<FixedTriangle> sample_edge_triangles(Random& random, std::int32_t width,
                                                 std::int32_t height,
                                                 std::span<const SampleOffset> pattern,
                                                 int shapes) {
  const Target target{width, height, pattern};
  std::vector<FixedTriangle> triangles, shape;
  for (int n = 0; n < shapes; ++n) {
    // Shapes that reach beyond the target are made again.
    do {
      shape.clear();
      const double kind = random.uniform();
      if (kind < 0.35) {
        random_triangle(random, target, shape);
      } else if (kind < 0.6) {
        rectangle(random, target, shape);
      } else if (kind < 0.8) {
        diagonal(random, target, shape);
      } else if (kind < 0.9) {
        fan(random, target, shape);
      } else {
        mesh(random, target, shape);
      }
    } while (!std::all_of(shape.begin(), shape.end(), [&](const FixedTriangle& t) {
      return std::all_of(t.begin(), t.end(), [&](const FixedPoint& p) { return target.holds(p); });
    }));
    for (const FixedTriangle& t : shape)
      triangles.push_back(any_order(random, t));
  }
  return triangles;
}

}  // namespace edgewise::test
