// The exact-area reference: how much of a pixel's square a snapped triangle covers. It is the
// ground truth for every anti-aliasing mode (docs/design/anti-aliasing.md).
//
// The pixel's square is clipped by the triangle's three edges, one half-plane at a time
// (Sutherland-Hodgman), in double precision in the pixel's own frame, and the area of what is
// left is taken by the shoelace formula. It shares no code with the fast kernels.
//
// Error: within kPixelAreaErrorBound of the exact area of square and snapped triangle (the
// derivation is beside the constant in pixel_area_reference.cpp).
#pragma once

#include <cstdint>

#include "../coverage/coverage_reference.hpp"

namespace edgewise::reference {

// |pixel_area() - exact area| never exceeds this, in square pixels.
inline constexpr double kPixelAreaErrorBound = 0x1p-44;

// The area of the square [px, px + 1) x [py, py + 1) inside the triangle, in square pixels:
// 0 .. 1. The triangle must have nonzero area (snap_and_classify() returned drawn or
// culled_winding).
double pixel_area(const SnappedTriangle& tri, std::int32_t px, std::int32_t py);

// The exact area of the snapped triangle, in square pixels (positive for either winding).
double triangle_area(const SnappedTriangle& tri);

}  // namespace edgewise::reference
