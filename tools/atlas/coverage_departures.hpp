// How a coverage method departs from the library's exact coverage, in the atlas's coverage
// study: per triangle, the pixels decided differently, and over a window, holes and double hits.
#pragma once

#include <cstdint>
#include <vector>

#include "atlas/edge_function_methods.hpp"
#include "edgewise/coverage.hpp"

namespace edgewise::atlas {

// The inexact arithmetics the study measures, in the order of Departures::method.
inline constexpr EdgeArithmetic kInexact[] = {EdgeArithmetic::float64, EdgeArithmetic::float32};

// How a method's coverage departs from the exact one.
struct Departure {
  std::uint64_t covered = 0;    // (triangle, pixel) pairs of the exact coverage
  std::uint64_t differing = 0;  // pairs in one coverage and not the other
  std::uint64_t holes = 0;      // pixels the exact union covers and the method's does not
  std::uint64_t doubles = 0;    // pixels the method covers more often than the exact coverage
  void add(const Departure& d) {
    covered += d.covered;
    differing += d.differing;
    holes += d.holes;
    doubles += d.doubles;
  }
};

struct Departures {
  Departure method[2];
  void add(const Departures& d) {
    method[0].add(d.method[0]);
    method[1].add(d.method[1]);
  }
};

// The departures of float64 and float32 (in kInexact's order) from the library's coverage
// of `vertices` (three per triangle) in `window`.
// The study's own fixed-point loop must match the library pixel for pixel: if it does not, the
// harness (snapping, fill rule, box) is wrong and so would be every figure.
Departures measure_departures(const std::vector<Vec2>& vertices, const PixelRect& window);

}  // namespace edgewise::atlas
