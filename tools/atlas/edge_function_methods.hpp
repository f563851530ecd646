// The coverage study's measured methods (never the library's default): a triangle's pixel
// centres decided by the edge function E = A x + B y + C of each edge (A, B, C from the snapped
// vertices), evaluated at every centre of the box in one arithmetic:
//   fixed_point  64-bit integers in 1/256 px, which is exact: the library's rule
//                (docs/design/rasterization.md, "Fill rule and watertightness"), written as plainly
//                as the others
//   float64      double
//   float32      float
// The top-left rule decides E == 0 in each: inside is E > 0 once the winding is made positive,
// and an edge whose inward normal (A, B) has A > 0, or A == 0 and B > 0, is a left or top edge.
// A triangle whose doubled area is 0 in the method's arithmetic covers nothing.
#pragma once

#include <cstdint>
#include <span>
#include <string_view>

#include "edgewise/coverage.hpp"

namespace edgewise::atlas {

enum class EdgeArithmetic { fixed_point, float64, float32 };
std::string_view name_of(EdgeArithmetic arithmetic);
inline constexpr EdgeArithmetic kEdgeArithmetics[] = {
    EdgeArithmetic::fixed_point, EdgeArithmetic::float64, EdgeArithmetic::float32};

// Calls covered(x, y) for every pixel of `window` whose centre the triangle covers, in row order.
template <class Covered>
void cover_triangle(EdgeArithmetic arithmetic, const Vec2 (&vertices)[3], const PixelRect& window,
                    Covered&& covered);

}  // namespace edgewise::atlas

#include "atlas/edge_function_methods-inl.hpp"
