// Interval arithmetic of the error budget's bounds (shading_budget.cpp, texture_budget.cpp):
// float32's unit roundoff, magnitudes over an interval, products of intervals, and colours to
// 8-bit codes as the kernels pack them.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <limits>

namespace edgewise::detail::budget {

inline constexpr double kUnit = 0x1p-24;  // float32's unit roundoff
inline constexpr double kInfinity = std::numeric_limits<double>::infinity();

// The least magnitude over [low, high]: 0 where it holds 0.
inline double least_magnitude(double low, double high) {
  return low > 0.0 ? low : high < 0.0 ? -high : 0.0;
}

inline double clamp01(double v) {
  return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
}

inline std::uint32_t to_byte(double v) {
  return static_cast<std::uint32_t>(std::lrint(clamp01(v) * 255.0));
}

// [a_lo, a_hi] times [b_lo, b_hi].
inline void multiply(double a_lo, double a_hi, double b_lo, double b_hi, double& lo, double& hi) {
  const double p[4] = {a_lo * b_lo, a_lo * b_hi, a_hi * b_lo, a_hi * b_hi};
  lo = std::min({p[0], p[1], p[2], p[3]});
  hi = std::max({p[0], p[1], p[2], p[3]});
}

}  // namespace edgewise::detail::budget
