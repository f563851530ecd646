// A triangle as the interpolators take it, and the clip-space w they accept: shared by the
// interpolation kernels, their reference and draw()'s shading, not part of the public API.
#pragma once

#include "edgewise/interpolation.hpp"

namespace edgewise {

// Clip-space w the interpolators accept. Clipping keeps w in this range for any camera whose
// near and far planes are within it; a triangle with any other w (zero, negative, NaN, inf) is
// interpolated affinely, as if every w were 1, so results stay finite.
inline constexpr double kMinClipW = 0x1.0p-32;
inline constexpr double kMaxClipW = 0x1.0p+32;

// A triangle as the interpolators take it: snapped screen positions in pixels
// (docs/design/rasterization.md, "Coordinates and snapping") and each vertex's clip-space w. w = 1
// at all three vertices means no perspective.
struct ScreenTriangle {
  double x[3];
  double y[3];
  double w[3];
};

}  // namespace edgewise
