// Scalar references for interpolation, in double precision: each method's screen-space weights,
// the perspective division, and the exact perspective-correct barycentrics that every method is
// measured against. Written to be read, not to be fast.
//
// Finite results for every input, by these rules:
// - A triangle with a non-finite coordinate, or a sample that is not finite: every method
//   returns the centroid weights (1/3, 1/3, 1/3).
// - A triangle of zero area (its vertices collinear or coincident): the barycentric methods
//   (sub-triangle areas, edge functions, scan-line, plane equations) and exact_weights return the
//   centroid weights; nearest vertex and inverse distance need no area and work as usual.
// - Inverse distance at a vertex (distance 0) returns that vertex's one-hot weights (the lowest
//   index when coincident vertices share the sample).
// - Scan-line: a row never uses a horizontal edge, nor the short edge that meets the long edge
//   on that row (the top and bottom vertices' rows), so its span has nonzero width; were it 0
//   (off-grid input), the sample takes the weights where the row crosses the long edge.
// - Outside the triangle the barycentric methods extrapolate linearly. The perspective step
//   divides by the interpolated 1/w, which beyond the triangle can reach 0 (where the triangle's
//   plane passes through the eye); it is clamped to at least min(1/w_i), the smallest value it
//   takes on the triangle, so the weights stay finite (and no longer sum to 1 there).
// - A w outside [kMinClipW, kMaxClipW] (or NaN) makes the triangle affine: every w taken as 1.
#pragma once

#include "screen_triangle.hpp"

namespace edgewise::reference {

using edgewise::ScreenTriangle;

// Weights on the three vertex values; they sum to 1 except where the rules above say otherwise.
struct Weights {
  double b[3];
};

// The method's weights in screen space at the sample (px, py), in pixels.
Weights screen_weights(InterpolationMethod method, const ScreenTriangle& triangle, double px,
                       double py);

// Perspective-correct weights from screen-space ones: b_i / w_i, renormalized. A w outside
// [kMinClipW, kMaxClipW] returns the screen weights unchanged (affine).
Weights perspective_correct(const Weights& screen, const double w[3]);

// The method's weights with the perspective step applied or not.
Weights interpolation_weights(InterpolationMethod method, Perspective perspective,
                              const ScreenTriangle& triangle, double px, double py);

// Ground truth: the exact perspective-correct barycentrics at (px, py). For vertices on the
// 1/256 pixel grid inside the guard band and samples on it (pixel centers are), the edge
// functions are exact: differences are multiples of 2^-8 below 2^17 (25 bits) and their
// products below 2^50 units of 2^-16, so they, and sums of three, fit long double's 64 bits (and
// double's 53). The remaining divisions are made in long double (64-bit significand on x86-64,
// 113 on AArch64), then rounded once to double: relative error at most 2^-53 + 2^-61 except
// where the sum of b_i / w_i cancels outside the triangle.
Weights exact_weights(const ScreenTriangle& triangle, double px, double py);

// The weights a degenerate input receives.
inline constexpr Weights kCentroidWeights = {{1.0 / 3.0, 1.0 / 3.0, 1.0 / 3.0}};

// The w the interpolators use: the triangle's own, or all 1 if any is outside
// [kMinClipW, kMaxClipW].
void usable_clip_w(const ScreenTriangle& triangle, double w[3]);

}  // namespace edgewise::reference
