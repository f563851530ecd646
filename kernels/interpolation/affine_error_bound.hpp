// How far affine weights may put an interpolated value from the perspective-correct one: the
// bound that lets a caller take the cheaper affine interpolation where it is within tolerance.
//
// With screen-space (affine) weights b_i and u_i = 1 / w_i, the perspective-correct weights are
// b'_i = b_i u_i / S, S = sum_j b_j u_j. Both sum to 1, so for vertex values a_i
//     sum_i (b'_i - b_i) a_i = sum_i (b'_i - b_i) (a_i - min a),
// whose positive terms add up to at most T (max a - min a) and negative ones to at least minus
// that, T = sum over b'_i > b_i of (b'_i - b_i) (the total variation of the two weightings).
// Let P be the weight b of the vertices with u_i > S, and m+ and m- the b-weighted means of u
// above and below S: then T = P (1 - P) (m+ - m-) / S with S = P m+ + (1 - P) m-, which grows
// with m+ and falls with m- (d/dm+ of (m+ - m-) / S is m- / S^2 > 0, d/dm- is -m+ / S^2 < 0),
// so it is largest at m+ = u_max, m- = u_min: with r = u_max / u_min = w_max / w_min,
//     T <= P (1 - P) (r - 1) / (1 + P (r - 1)),
// largest at P = 1 / (sqrt(r) + 1), where it equals (sqrt(r) - 1) / (sqrt(r) + 1). The bound is
// reached on an edge whose end points have w_min and w_max, at that P. It is the exact
// arithmetic's; the float32 weights add their own rounding, which the colour bounds of
// tests/draw account for.
#pragma once

#include <cmath>

namespace edgewise::detail {

// |affine - perspective-correct| <= value range * affine_weight_error_bound(w_min, w_max), for
// 0 < w_min <= w_max (clip w of the triangle's vertices).
inline double affine_weight_error_bound(double w_min, double w_max) {
  const double root = std::sqrt(w_max / w_min);
  return (root - 1.0) / (root + 1.0);
}

// The largest w_max / w_min whose bound is at most `tolerance` for values spanning `range`:
// ((1 + t) / (1 - t))^2 with t = tolerance / range (infinite from t >= 1 on).
inline double affine_safe_depth_ratio(double tolerance, double range) {
  const double t = tolerance / range;
  if (t >= 1.0) return INFINITY;
  const double root = (1.0 + t) / (1.0 - t);
  return root * root;
}

}  // namespace edgewise::detail
