// How far a fast ISA's colour may be from the shading reference's at one pixel: the rounding-error
// bounds of the interpolation weights (tests/interpolation/error_bounds.hpp) carried through the
// shading models of draw() (draw.hpp), then to 8-bit codes.
#pragma once

#include "interpolation/screen_triangle.hpp"
#include "edgewise/draw.hpp"
#include "edgewise/vector.hpp"
#include "interpolation/error_bounds.hpp"

namespace edgewise::test {

// The reference's weights at a pixel, and a bound on the distance between the fast weights and
// the reference's (each side's bound on its distance from the exact weights, added).
struct WeightErrors {
  double value[3];
  double error[3];
};

// For every method but nearest vertex, at the pixel center (px, py) of a screen triangle as the
// shading kernels receive it (snapped positions, clip-space w). Follows the kernels' rules: the
// fast path skips the perspective step when the three w are equal, and a w outside
// [kMinClipW, kMaxClipW] makes both sides affine (the fast path still divides, by 1).
WeightErrors weight_errors(InterpolationMethod method, Perspective perspective,
                           const ScreenTriangle& triangle, double px, double py);

// Nearest vertex where both sides pick `vertex`: exact one-hot screen weights, then the same
// perspective step as above.
WeightErrors one_hot_weight_errors(int vertex, Perspective perspective,
                                   const ScreenTriangle& triangle);

// The attributes of the triangle's three vertices, as the shading kernels receive them.
struct VertexAttributes {
  Vec4 colors[3];
  Vec3 normals[3];
};

// The largest difference in 8-bit codes between the fast and the reference colour of a pixel
// whose weights carry the errors `e`, for Gouraud or diffuse shading with ambient in [0, 1];
// 255 (any colour) where the bound is unbounded. Flat shading is the Gouraud case of one-hot
// weights on vertex 0 without the perspective step.
int allowed_codes(const VertexAttributes& triangle, const WeightErrors& e, Shading shading,
                  float ambient);
// The same bound before rounding to codes: the largest difference of a linear colour channel.
double colour_error(const VertexAttributes& triangle, const WeightErrors& e, Shading shading,
                    float ambient);

// Gouraud colour by plane equations (the kernels' fast path for that method and model): each
// channel, scaled to 0 .. 255, is its own plane, and perspective-correct a plane of value / w
// divided by the plane of 1 / w. The largest difference in codes from the reference at pixel
// center (px, py), or 255 where the bound is unbounded (a plane value or slope beyond float's
// range, which the kernels cannot hold).
int plane_colour_codes(const ScreenTriangle& triangle, const VertexAttributes& attributes,
                       Perspective perspective, double px, double py);
// The same bound as a linear channel difference before rounding (infinite where unbounded).
double plane_colour_error(const ScreenTriangle& triangle, const VertexAttributes& attributes,
                          Perspective perspective, double px, double py);

// Diffuse by plane equations (the kernels' path for that method and model): the colour planes
// above, lit by normals that are planes of their own (of n / w, perspective-correct), never
// divided. As plane_colour_codes() and plane_colour_error() for `shading` Gouraud or diffuse.
int plane_shading_codes(const ScreenTriangle& triangle, const VertexAttributes& attributes,
                        Perspective perspective, Shading shading, float ambient, double px,
                        double py);
double plane_shading_error(const ScreenTriangle& triangle, const VertexAttributes& attributes,
                           Perspective perspective, Shading shading, float ambient, double px,
                           double py);

}  // namespace edgewise::test
