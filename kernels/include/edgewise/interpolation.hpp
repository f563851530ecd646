// How values given at a triangle's three vertices are carried to its pixels.
//
// Every method is a set of three weights on the vertex values (b0 + b1 + b2 = 1 wherever the
// method defines one). The weights are computed in screen space; perspective-correct
// interpolation then divides them by each vertex's clip-space w and renormalizes, which is what
// interpolating attribute/w and 1/w in screen space amounts to.
//
// Thread safety: plain functions of their arguments; call them from any thread.
#pragma once

#include <cstdint>
#include <optional>
#include <string_view>

namespace edgewise {

enum class InterpolationMethod : std::uint8_t {
  nearest_vertex,     // the value of the closest vertex (ties to the lowest index)
  inverse_distance,   // weights 1 / distance^kInverseDistancePower, normalized
  subtriangle_areas,  // area(p, p1, p2) / area(p0, p1, p2) by cross products; b2 = 1 - b0 - b1
  edge_functions,     // F_bc(x, y) / F_bc(x_a, y_a), each edge normalized on its own
  scanline,           // along the two edges crossing the row, then across the row in x
  plane_equations,    // b = c0 + cx * x + cy * y, set up once per triangle (production method)
};

inline constexpr InterpolationMethod kInterpolationMethods[] = {
    InterpolationMethod::nearest_vertex,    InterpolationMethod::inverse_distance,
    InterpolationMethod::subtriangle_areas, InterpolationMethod::edge_functions,
    InterpolationMethod::scanline,          InterpolationMethod::plane_equations,
};

// The course's inverse-distance weighting uses 1 / norm(p - p_i): power 1.
inline constexpr int kInverseDistancePower = 1;

enum class Perspective : std::uint8_t {
  correct,  // attribute/w and 1/w interpolated in screen space, then divided
  affine,   // screen-space weights used as they are (exact only when w is constant)
};

// Clip-space w the interpolators accept. Clipping keeps w in this range for any camera whose
// near and far planes are within it; a triangle with any other w (zero, negative, NaN, inf) is
// interpolated affinely, as if every w were 1, so results stay finite.
inline constexpr double kMinClipW = 0x1.0p-32;
inline constexpr double kMaxClipW = 0x1.0p+32;

// A triangle as the interpolators take it: snapped screen positions in pixels (docs/DESIGN.md,
// "Coordinates and snapping") and each vertex's clip-space w. w = 1 at all three vertices means
// no perspective.
struct ScreenTriangle {
  double x[3];
  double y[3];
  double w[3];
};

constexpr std::string_view interpolation_method_name(InterpolationMethod method) {
  switch (method) {
    case InterpolationMethod::nearest_vertex:
      return "nearest_vertex";
    case InterpolationMethod::inverse_distance:
      return "inverse_distance";
    case InterpolationMethod::subtriangle_areas:
      return "subtriangle_areas";
    case InterpolationMethod::edge_functions:
      return "edge_functions";
    case InterpolationMethod::scanline:
      return "scanline";
    case InterpolationMethod::plane_equations:
      return "plane_equations";
  }
  return "unknown";
}

constexpr std::optional<InterpolationMethod> parse_interpolation_method(std::string_view name) {
  for (InterpolationMethod method : kInterpolationMethods) {
    if (interpolation_method_name(method) == name) return method;
  }
  return std::nullopt;
}

constexpr std::string_view perspective_name(Perspective perspective) {
  switch (perspective) {
    case Perspective::correct:
      return "correct";
    case Perspective::affine:
      return "affine";
  }
  return "unknown";
}

constexpr std::optional<Perspective> parse_perspective(std::string_view name) {
  for (Perspective perspective : {Perspective::correct, Perspective::affine}) {
    if (perspective_name(perspective) == name) return perspective;
  }
  return std::nullopt;
}

}  // namespace edgewise
