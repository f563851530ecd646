// The float32 interpolators of kernels/interpolation/interpolation-inl.hpp, compiled once per ISA
// with that ISA's flags (fast_interpolation_kernels.cpp), behind plain pointer-taking functions
// the tests can call without SIMD types crossing translation units.
#pragma once

#include <cstddef>
#include <cstdint>

#include "interpolation/screen_triangle.hpp"
#include "edgewise/isa.hpp"

namespace edgewise::test {

struct FastInterpolation {
  Isa isa;
  std::size_t lanes;  // pixels per row evaluation
  // Weights at the pixel centers (origin_x + column + lane + 0.5, origin_y + row + 0.5) for
  // lane = 0 .. lanes - 1, written to weights[i * lanes + lane] for vertex i.
  void (*screen_row)(InterpolationMethod method, const ScreenTriangle& triangle, double origin_x,
                     double origin_y, std::int32_t column, std::int32_t row, float* weights);
  // The same with the perspective step applied.
  void (*perspective_row)(InterpolationMethod method, const ScreenTriangle& triangle,
                          double origin_x, double origin_y, std::int32_t column, std::int32_t row,
                          float* weights);
};

// The ISA's interpolators, or nullptr where this build did not compile them.
const FastInterpolation* fast_interpolation(Isa isa);

}  // namespace edgewise::test
