// Random triangles for the interpolation tests, snapped to the 1/256 pixel grid inside the guard
// band as the rasterizer delivers them, and samples at pixel centers near them.
#pragma once

#include <span>
#include <string_view>

#include "interpolation/screen_triangle.hpp"
#include "random.hpp"

namespace edgewise::test {

struct InterpolationTriangleSource {
  std::string_view name;
  // A triangle with w = 1 at every vertex and nonzero area.
  ScreenTriangle (*make)(Random& random);
};

// small, large, sliver, guard_band (anywhere in it, up to its full size), far_corner (small,
// at the guard band's corners).
std::span<const InterpolationTriangleSource> interpolation_triangle_sources();

// Snapped to 1/256 px, ties to even, and kept inside the guard band [-32768, 32768).
double snap_to_grid(double pixels);

// A pixel center: inside the triangle half of the time, else anywhere in its bounding box
// grown by 2 px (clipped to the guard band).
void random_pixel_center(Random& random, const ScreenTriangle& triangle, double& px, double& py);

// Log-uniform w in [1, depth_ratio] at each vertex, with w = 1 and w = depth_ratio both present.
void assign_depths(Random& random, double depth_ratio, ScreenTriangle& triangle);

}  // namespace edgewise::test
