// cover_triangle() (edge_function_methods.hpp), per arithmetic.
#pragma once

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <type_traits>

namespace edgewise::atlas {
namespace detail {

// Snapped as the library snaps: v * 256 rounded to the nearest integer, ties to even.
inline std::int64_t snap(float v) {
  return static_cast<std::int64_t>(std::nearbyint(static_cast<double>(v) * 256.0));
}

// T holds the coordinates: int64 in 1/256 px, else pixels (exact in double; in float for
// snapped values below 2^15 px, 24 bits).
template <class T, class Covered>
void cover_in(const std::int64_t (&x)[3], const std::int64_t (&y)[3], const PixelRect& window,
              Covered& covered) {
  constexpr bool kFixed = std::is_integral_v<T>;
  const auto value = [](std::int64_t v) {
    if constexpr (kFixed) {
      return v;
    } else {
      return static_cast<T>(static_cast<double>(v) / 256.0);
    }
  };
  T vx[3], vy[3];
  for (int i = 0; i < 3; ++i) {
    vx[i] = value(x[i]);
    vy[i] = value(y[i]);
  }
  T a[3], b[3], c[3];
  for (int i = 0; i < 3; ++i) {
    const int j = i == 2 ? 0 : i + 1;
    a[i] = vy[i] - vy[j];
    b[i] = vx[j] - vx[i];
    c[i] = vx[i] * vy[j] - vy[i] * vx[j];
  }
  // Twice the area, in the same arithmetic (the sum of the C's is its exact expansion).
  const T doubled_area = c[0] + c[1] + c[2];
  if (doubled_area == T(0)) return;
  bool top_left[3];
  for (int i = 0; i < 3; ++i) {
    if (doubled_area < T(0)) {
      a[i] = -a[i];
      b[i] = -b[i];
      c[i] = -c[i];
    }
    top_left[i] = a[i] > T(0) || (a[i] == T(0) && b[i] > T(0));
  }
  // The box of the snapped vertices, in pixels whose centres it may hold.
  const auto floor_px = [](std::int64_t v) { return static_cast<std::int32_t>(v >> 8); };
  const std::int32_t x0 = std::max(window.x0, floor_px(std::min({x[0], x[1], x[2]})) - 1);
  const std::int32_t x1 = std::min(window.x1, floor_px(std::max({x[0], x[1], x[2]})) + 2);
  const std::int32_t y0 = std::max(window.y0, floor_px(std::min({y[0], y[1], y[2]})) - 1);
  const std::int32_t y1 = std::min(window.y1, floor_px(std::max({y[0], y[1], y[2]})) + 2);
  for (std::int32_t py = y0; py < y1; ++py) {
    const T cy = kFixed ? T(std::int64_t{py} * 256 + 128) : T(py) + T(0.5);
    for (std::int32_t px = x0; px < x1; ++px) {
      const T cx = kFixed ? T(std::int64_t{px} * 256 + 128) : T(px) + T(0.5);
      bool inside = true;
      for (int i = 0; i < 3; ++i) {
        const T e = a[i] * cx + b[i] * cy + c[i];
        inside = inside && (e > T(0) || (e == T(0) && top_left[i]));
      }
      if (inside) covered(px, py);
    }
  }
}

}  // namespace detail

inline std::string_view name_of(EdgeArithmetic arithmetic) {
  switch (arithmetic) {
    case EdgeArithmetic::float64:
      return "float64";
    case EdgeArithmetic::float32:
      return "float32";
    case EdgeArithmetic::fixed_point:
      break;
  }
  return "fixed point";
}

template <class Covered>
void cover_triangle(EdgeArithmetic arithmetic, const Vec2 (&vertices)[3], const PixelRect& window,
                    Covered&& covered) {
  std::int64_t x[3], y[3];
  for (int i = 0; i < 3; ++i) {
    x[i] = detail::snap(vertices[i].x);
    y[i] = detail::snap(vertices[i].y);
  }
  switch (arithmetic) {
    case EdgeArithmetic::fixed_point:
      detail::cover_in<std::int64_t>(x, y, window, covered);
      break;
    case EdgeArithmetic::float64:
      detail::cover_in<double>(x, y, window, covered);
      break;
    case EdgeArithmetic::float32:
      detail::cover_in<float>(x, y, window, covered);
      break;
  }
}

}  // namespace edgewise::atlas
