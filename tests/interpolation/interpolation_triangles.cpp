#include "interpolation_triangles.hpp"

#include <algorithm>
#include <cmath>
#include <numbers>

namespace edgewise::test {
namespace {

constexpr double kGuardBand = 32768.0;
constexpr double kGrid = 1.0 / 256.0;

double twice_area(const ScreenTriangle& t) {
  return (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
}

// Draws until the snapped triangle has nonzero area.
template <class Draw>
ScreenTriangle nondegenerate(Random& random, Draw draw) {
  for (;;) {
    ScreenTriangle t{};
    for (int i = 0; i < 3; ++i) {
      double x = 0.0, y = 0.0;
      draw(random, i, x, y);
      t.x[i] = snap_to_grid(x);
      t.y[i] = snap_to_grid(y);
      t.w[i] = 1.0;
    }
    if (twice_area(t) != 0.0) return t;
  }
}

ScreenTriangle small(Random& random) {
  const double cx = random.uniform(-1000.0, 1000.0), cy = random.uniform(-1000.0, 1000.0);
  return nondegenerate(random, [&](Random& r, int, double& x, double& y) {
    x = cx + r.uniform(-8.0, 8.0);
    y = cy + r.uniform(-8.0, 8.0);
  });
}

ScreenTriangle large(Random& random) {
  const double cx = random.uniform(-2000.0, 2000.0), cy = random.uniform(-2000.0, 2000.0);
  return nondegenerate(random, [&](Random& r, int, double& x, double& y) {
    x = cx + r.uniform(-1500.0, 1500.0);
    y = cy + r.uniform(-1500.0, 1500.0);
  });
}

// Two vertices far apart and the third within 2^-8 .. 1 px of the line through them.
ScreenTriangle sliver(Random& random) {
  const double x0 = random.uniform(-2000.0, 2000.0), y0 = random.uniform(-2000.0, 2000.0);
  const double angle = random.uniform(0.0, 2.0 * std::numbers::pi);
  const double length = random.log_uniform(16.0, 4000.0);
  const double along = random.uniform(-0.2, 1.2);
  const double offset = random.sign() * random.log_uniform(kGrid, 1.0);
  const double dx = std::cos(angle), dy = std::sin(angle);
  return nondegenerate(random, [&](Random&, int i, double& x, double& y) {
    const double t = i == 0 ? 0.0 : i == 1 ? length : along * length;
    const double n = i == 2 ? offset : 0.0;
    x = x0 + t * dx - n * dy;
    y = y0 + t * dy + n * dx;
  });
}

ScreenTriangle guard_band(Random& random) {
  return nondegenerate(random, [](Random& r, int, double& x, double& y) {
    x = r.uniform(-kGuardBand, kGuardBand);
    y = r.uniform(-kGuardBand, kGuardBand);
  });
}

ScreenTriangle far_corner(Random& random) {
  const double cx = random.sign() * (kGuardBand - random.uniform(0.0, 64.0));
  const double cy = random.sign() * (kGuardBand - random.uniform(0.0, 64.0));
  return nondegenerate(random, [&](Random& r, int, double& x, double& y) {
    x = cx + r.uniform(-32.0, 32.0);
    y = cy + r.uniform(-32.0, 32.0);
  });
}

constexpr InterpolationTriangleSource kSources[] = {
    {"small", &small},           {"large", &large},           {"sliver", &sliver},
    {"guard_band", &guard_band}, {"far_corner", &far_corner},
};

}  // namespace

std::span<const InterpolationTriangleSource> interpolation_triangle_sources() {
  return kSources;
}

double snap_to_grid(double pixels) {
  const double snapped = std::nearbyint(pixels / kGrid) * kGrid;
  return std::clamp(snapped, -kGuardBand, kGuardBand - kGrid);
}

void random_pixel_center(Random& random, const ScreenTriangle& t, double& px, double& py) {
  if (random.chance(0.5)) {
    // A point of the triangle, moved to the center of its pixel (which may lie just outside).
    double a = random.uniform(), b = random.uniform();
    if (a + b > 1.0) {
      a = 1.0 - a;
      b = 1.0 - b;
    }
    px = t.x[0] + a * (t.x[1] - t.x[0]) + b * (t.x[2] - t.x[0]);
    py = t.y[0] + a * (t.y[1] - t.y[0]) + b * (t.y[2] - t.y[0]);
  } else {
    const auto [x_min, x_max] = std::minmax({t.x[0], t.x[1], t.x[2]});
    const auto [y_min, y_max] = std::minmax({t.y[0], t.y[1], t.y[2]});
    px = random.uniform(x_min - 2.0, x_max + 2.0);
    py = random.uniform(y_min - 2.0, y_max + 2.0);
  }
  px = std::clamp(std::floor(px), -kGuardBand, kGuardBand - 1.0) + 0.5;
  py = std::clamp(std::floor(py), -kGuardBand, kGuardBand - 1.0) + 0.5;
}

void assign_depths(Random& random, double depth_ratio, ScreenTriangle& triangle) {
  const int nearest = static_cast<int>(random.integer(0, 2));
  const int farthest = (nearest + 1 + static_cast<int>(random.integer(0, 1))) % 3;
  for (int i = 0; i < 3; ++i)
    triangle.w[i] = random.log_uniform(1.0, depth_ratio);
  triangle.w[nearest] = 1.0;
  triangle.w[farthest] = depth_ratio;
}

}  // namespace edgewise::test
