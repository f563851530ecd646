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

#include "edgewise/names.hpp"

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

// Names of the values (names.hpp).
std::string_view name_of(InterpolationMethod value);
template <>
std::span<const InterpolationMethod> values_of<InterpolationMethod>();
std::string_view name_of(Perspective value);
template <>
std::span<const Perspective> values_of<Perspective>();

}  // namespace edgewise
