// Random triangles of one exact area, placed fully inside a target: the workload of the coverage
// benchmark and of the demo's throughput table.
//
// Shapes vary in orientation, aspect ratio and skew (not only right triangles), windings are
// mixed half and half, and the sequence depends only on the seed, so runs compare across ISAs,
// commits and machines.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <numbers>
#include <random>
#include <stdexcept>
#include <string>
#include <utility>
#include <vector>

#include "edgewise/coverage.hpp"

namespace edgewise::workload {

// Twice the signed area, in double precision, of the triangle as stored (float vertices).
inline double doubled_signed_area(const Vec2& a, const Vec2& b, const Vec2& c) {
  return (double(b.x) - a.x) * (double(c.y) - a.y) - (double(b.y) - a.y) * (double(c.x) - a.x);
}

// Three vertices per triangle, `count` triangles of area `area` px^2 inside width x height.
inline std::vector<Vec2> exact_area_triangles(std::size_t count, double area, int width, int height,
                                              std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  auto uniform = [&rng](double lo, double hi) {
    return std::uniform_real_distribution<double>(lo, hi)(rng);
  };
  // Unit-base triangle (0,0) (1,0) (apex_x, apex_y): the apex range keeps the aspect ratio
  // within about 1:8 and allows obtuse, acute and right shapes.
  constexpr double kApexXMin = -0.5, kApexXMax = 1.5, kApexYMin = 0.25, kApexYMax = 1.5;
  constexpr int kMaxAttempts = 1000;
  constexpr double kAreaTolerance = 1e-4;  // relative; float rounding of the placed vertices

  std::vector<Vec2> vertices;
  vertices.reserve(3 * count);
  for (std::size_t t = 0; t < count; ++t) {
    bool placed = false;
    for (int attempt = 0; attempt < kMaxAttempts && !placed; ++attempt) {
      // Shape: scale the unit-base triangle (area apex_y / 2) to the requested area.
      const double apex_x = uniform(kApexXMin, kApexXMax);
      const double apex_y = uniform(kApexYMin, kApexYMax);
      const double scale = std::sqrt(2.0 * area / apex_y);
      const double angle = uniform(0.0, 2.0 * std::numbers::pi);
      const double cos_a = std::cos(angle), sin_a = std::sin(angle);
      double px[3] = {0.0, scale, apex_x * scale}, py[3] = {0.0, 0.0, apex_y * scale};
      for (int v = 0; v < 3; ++v) {
        const double x = px[v] * cos_a - py[v] * sin_a, y = px[v] * sin_a + py[v] * cos_a;
        px[v] = x;
        py[v] = y;
      }
      // Position: anywhere that keeps the whole triangle inside the target.
      const auto [min_x, max_x] = std::minmax({px[0], px[1], px[2]});
      const auto [min_y, max_y] = std::minmax({py[0], py[1], py[2]});
      const double span_x = width - (max_x - min_x), span_y = height - (max_y - min_y);
      if (span_x <= 0.0 || span_y <= 0.0) continue;  // too large at this angle: reshape
      const double dx = uniform(0.0, span_x) - min_x, dy = uniform(0.0, span_y) - min_y;
      Vec2 tri[3];
      for (int v = 0; v < 3; ++v) {
        tri[v] = {static_cast<float>(px[v] + dx), static_cast<float>(py[v] + dy)};
      }
      if (uniform(0.0, 1.0) < 0.5) std::swap(tri[1], tri[2]);  // the other winding
      // Rounding to float may push a vertex past the border or change the area slightly.
      bool inside = true;
      for (const Vec2& p : tri) {
        inside =
            inside && p.x >= 0.0f && p.x <= float(width) && p.y >= 0.0f && p.y <= float(height);
      }
      const double placed_area = 0.5 * std::abs(doubled_signed_area(tri[0], tri[1], tri[2]));
      if (!inside || std::abs(placed_area - area) > kAreaTolerance * area) continue;
      vertices.insert(vertices.end(), tri, tri + 3);
      placed = true;
    }
    if (!placed) {
      throw std::invalid_argument("no triangle of area " + std::to_string(area) + " fits in " +
                                  std::to_string(width) + "x" + std::to_string(height));
    }
  }
  return vertices;
}

}  // namespace edgewise::workload
