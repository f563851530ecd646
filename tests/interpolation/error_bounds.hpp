// Rounding-error bounds for every interpolation method, derived by running error analysis
// (Higham, "Accuracy and Stability of Numerical Algorithms", 2nd ed., section 3.3).
//
// Each method's computation is replayed in double, in the evaluator's operation order, on values
// that carry a bound on their distance from the exact value. The model: a floating-point
// operation returns (a op b)(1 + d) with |d| <= u, so an operation adds u times a bound on the
// magnitude of its result to the propagated input errors:
//   a + b:  e_a + e_b                                   + u (|a + b| + e_a + e_b)
//   a * b:  |a| e_b + |b| e_a + e_a e_b                 + u (|a b| + that)
//   a / b:  (e_a + q e_b) / (|b| - e_b), q = (|a| + e_a) / (|b| - e_b)   + u q
//   sqrt a: min(sqrt(e_a), e_a / sqrt(|a| - e_a))        + u sqrt(|a| + e_a)
//   max:    max(e_a, e_b) (max is 1-Lipschitz; no rounding)
// A fused multiply-add rounds once where this counts two, so the bounds hold for both.
// The replayed values are themselves double: they differ from the exact ones by the same
// expressions with u = 2^-53, at most 2^-29 of the float32 bound; u is inflated by 2^-20 of
// itself to cover that, and the double-then-float rounding of setup values (2^-24 + 2^-53).
// For the double references, the replay is the computation itself and |value| + e bounds the
// exact magnitude, which the formulas already use.
#pragma once

#include "edgewise/interpolation.hpp"
#include "interpolation/interpolation_reference.hpp"

namespace edgewise::test {

// The methods the course calls equivalent: their exact value is the barycentric coordinates.
inline constexpr InterpolationMethod kBarycentricMethods[] = {
    InterpolationMethod::subtriangle_areas, InterpolationMethod::edge_functions,
    InterpolationMethod::scanline, InterpolationMethod::plane_equations};

struct Bounded {
  double value;
  double error;  // bound on |computed - exact|
};

class RoundingModel {
 public:
  explicit RoundingModel(double unit_roundoff) : u_(unit_roundoff * (1.0 + 0x1.0p-20)) {}
  double unit_roundoff() const { return u_; }
  static Bounded exact(double value) { return {value, 0.0}; }
  // An exact value, or one already carrying an error, rounded once.
  Bounded rounded(double value) const { return rounded(exact(value)); }
  Bounded rounded(Bounded a) const;
  Bounded add(Bounded a, Bounded b) const;
  Bounded sub(Bounded a, Bounded b) const;
  Bounded mul(Bounded a, Bounded b) const;
  Bounded div(Bounded a, Bounded b) const;
  Bounded sqrt(Bounded a) const;
  static Bounded max(Bounded a, Bounded b);

 private:
  double u_;
};

// The float32 evaluators of kernels/interpolation/interpolation-inl.hpp, or the double references.
enum class Evaluator { float32, reference };

struct BoundedWeights {
  Bounded b[3];
};

// Each weight's value and the bound on its distance from the exact screen-space weight of the
// method (the exact barycentrics for the barycentric methods, the exact inverse-distance
// weights for inverse distance) at the pixel center (px, py). The float32 evaluator is set up at
// (origin_x, origin_y); the references ignore the origin. Not for nearest vertex. The inverse
// distance reference's bound is reference_inverse_distance_error (its 1/d form is not replayed).
BoundedWeights screen_weight_bounds(InterpolationMethod method, Evaluator evaluator,
                                    const ScreenTriangle& triangle, double origin_x,
                                    double origin_y, double px, double py);

// The squared distances nearest vertex compares, with their bounds.
void squared_distance_bounds(Evaluator evaluator, const ScreenTriangle& triangle, double origin_x,
                             double origin_y, double px, double py, Bounded squared[3]);

// The perspective step applied to bounded screen weights (w in [kMinClipW, kMaxClipW]).
BoundedWeights perspective_bounds(Evaluator evaluator, const BoundedWeights& screen,
                                  const ScreenTriangle& triangle);

// reference::exact_weights at (px, py), with a bound on each weight's distance from the true
// value (long double steps, then one rounding to double); also the exact screen-space
// barycentrics (w = 1) with theirs.
struct ExactWeights {
  reference::Weights correct;
  double correct_error[3];
  reference::Weights screen;
  double screen_error[3];
};
ExactWeights exact_weights_with_error(const ScreenTriangle& triangle, double px, double py);

// The double reference's inverse-distance weights are within 8 * 2^-53 of the exact ones,
// relatively: the squared distance is exact for grid inputs, then sqrt, 1/d, two additions of
// positive terms and a division each add one rounding (7 in all).
inline double reference_inverse_distance_error(double weight) {
  return 8.0 * 0x1.0p-53 * (weight < 0 ? -weight : weight);
}

}  // namespace edgewise::test
