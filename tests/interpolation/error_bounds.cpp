#include "error_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace edgewise::test {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

const RoundingModel& model_for(Evaluator evaluator) {
  static const RoundingModel float32(0x1.0p-24);
  static const RoundingModel float64(0x1.0p-53);
  return evaluator == Evaluator::float32 ? float32 : float64;
}

// Setup values computed in double (the references use them as they are; the float32
// evaluators round them once more).
Bounded setup_value(Evaluator evaluator, Bounded in_double) {
  return evaluator == Evaluator::float32 ? model_for(Evaluator::float32).rounded(in_double)
                                         : in_double;
}

double twice_area(const ScreenTriangle& t) {
  return (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
}

bool finite(const ScreenTriangle& t) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(t.x[i]) || !std::isfinite(t.y[i])) return false;
  }
  return true;
}

BoundedWeights centroid(Evaluator evaluator) {
  const Bounded third = setup_value(evaluator, Bounded{1.0 / 3.0, 0x1.0p-54});
  return {{third, third, third}};
}

// The coordinates each evaluator computes with: relative to the origin for float32 (exact,
// see interpolation-inl.hpp), absolute for the references (exact doubles).
struct Frame {
  double x[3], y[3];
  double px, py;
};

Frame frame_for(Evaluator evaluator, const ScreenTriangle& t, double origin_x, double origin_y,
                double px, double py) {
  if (evaluator == Evaluator::reference) origin_x = origin_y = 0.0;
  Frame f;
  for (int i = 0; i < 3; ++i) {
    f.x[i] = t.x[i] - origin_x;
    f.y[i] = t.y[i] - origin_y;
  }
  f.px = px - origin_x;
  f.py = py - origin_y;
  return f;
}

BoundedWeights inverse_distance(Evaluator evaluator, const Frame& f) {
  const RoundingModel& m = model_for(evaluator);
  Bounded squared[3];
  for (int i = 0; i < 3; ++i) {
    const Bounded dx = m.sub(RoundingModel::exact(f.px), RoundingModel::exact(f.x[i]));
    const Bounded dy = m.sub(RoundingModel::exact(f.py), RoundingModel::exact(f.y[i]));
    squared[i] = m.add(m.mul(dx, dx), m.mul(dy, dy));
  }
  Bounded distance[3];
  for (int i = 0; i < 3; ++i)
    distance[i] = m.sqrt(squared[i]);
  const Bounded products[3] = {m.mul(distance[1], distance[2]), m.mul(distance[0], distance[2]),
                               m.mul(distance[0], distance[1])};
  const Bounded sum = m.add(m.add(products[0], products[1]), products[2]);
  BoundedWeights result;
  for (int i = 0; i < 3; ++i)
    result.b[i] = m.div(products[i], sum);
  return result;
}

BoundedWeights subtriangle_areas(Evaluator evaluator, const Frame& f, double area) {
  const RoundingModel& m = model_for(evaluator);
  Bounded to_x[3], to_y[3];
  for (int i = 0; i < 3; ++i) {
    to_x[i] = m.sub(RoundingModel::exact(f.x[i]), RoundingModel::exact(f.px));
    to_y[i] = m.sub(RoundingModel::exact(f.y[i]), RoundingModel::exact(f.py));
  }
  const Bounded cross0 = m.sub(m.mul(to_x[1], to_y[2]), m.mul(to_y[1], to_x[2]));
  const Bounded cross1 = m.sub(m.mul(to_x[2], to_y[0]), m.mul(to_y[2], to_x[0]));
  Bounded b0, b1;
  if (evaluator == Evaluator::float32) {
    // Multiplied by 1/area, computed in double and rounded to float at setup.
    const Bounded inverse_area =
        setup_value(evaluator, Bounded{1.0 / area, 0x1.0p-53 / std::abs(area)});
    b0 = m.mul(cross0, inverse_area);
    b1 = m.mul(cross1, inverse_area);
  } else {
    b0 = m.div(cross0, RoundingModel::exact(area));
    b1 = m.div(cross1, RoundingModel::exact(area));
  }
  return {{b0, b1, m.sub(m.sub(RoundingModel::exact(1.0), b0), b1)}};
}

BoundedWeights edge_functions(Evaluator evaluator, const Frame& f, const ScreenTriangle& t) {
  const RoundingModel& m = model_for(evaluator);
  BoundedWeights result;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int k = (i + 2) % 3;
    // Edge vectors and F_jk(v_i) are exact in double for grid vertices.
    const double edge_x = t.x[k] - t.x[j];
    const double edge_y = t.y[k] - t.y[j];
    const double at_opposite = edge_x * (t.y[i] - t.y[j]) - edge_y * (t.x[i] - t.x[j]);
    const Bounded ex = setup_value(evaluator, RoundingModel::exact(edge_x));
    const Bounded ey = setup_value(evaluator, RoundingModel::exact(edge_y));
    const Bounded to_y = m.sub(RoundingModel::exact(f.py), RoundingModel::exact(f.y[j]));
    const Bounded to_x = m.sub(RoundingModel::exact(f.px), RoundingModel::exact(f.x[j]));
    const Bounded edge = m.sub(m.mul(ex, to_y), m.mul(ey, to_x));
    if (evaluator == Evaluator::float32) {
      const Bounded inverse =
          setup_value(evaluator, Bounded{1.0 / at_opposite, 0x1.0p-53 / std::abs(at_opposite)});
      result.b[i] = m.mul(edge, inverse);
    } else {
      result.b[i] = m.div(edge, RoundingModel::exact(at_opposite));
    }
  }
  return result;
}

BoundedWeights scanline(Evaluator evaluator, const Frame& f) {
  const RoundingModel& m = model_for(evaluator);
  int order[3] = {0, 1, 2};
  std::stable_sort(order, order + 3, [&](int a, int b) { return f.y[a] < f.y[b]; });
  const int top = order[0], mid = order[1], bottom = order[2];
  // The reference's choice of short edge (interpolation_reference.cpp, use_upper_edge).
  bool upper = f.py < f.y[mid];
  if (f.py == f.y[top]) upper = false;
  if (f.py == f.y[bottom]) upper = true;
  if (f.y[mid] == f.y[bottom]) upper = true;
  if (f.y[mid] == f.y[top]) upper = false;
  const int from[2] = {top, upper ? top : mid};
  const int to[2] = {bottom, upper ? mid : bottom};

  Bounded x_at[2];
  Bounded at[2][3];
  for (int s = 0; s < 2; ++s) {
    // Heights and runs are exact in float and double (differences of grid values below 2^16).
    const Bounded along =
        m.div(m.sub(RoundingModel::exact(f.py), RoundingModel::exact(f.y[from[s]])),
              RoundingModel::exact(f.y[to[s]] - f.y[from[s]]));
    x_at[s] = m.add(RoundingModel::exact(f.x[from[s]]),
                    m.mul(along, RoundingModel::exact(f.x[to[s]] - f.x[from[s]])));
    for (Bounded& weight : at[s])
      weight = RoundingModel::exact(0.0);
    at[s][from[s]] = m.sub(RoundingModel::exact(1.0), along);
    at[s][to[s]] = along;
  }
  // The span is never 0 for nonzero area; where rounding could make it so, div is unbounded.
  const Bounded span = m.sub(x_at[1], x_at[0]);
  const Bounded across =
      m.mul(m.sub(RoundingModel::exact(f.px), x_at[0]), m.div(RoundingModel::exact(1.0), span));
  BoundedWeights result;
  for (int i = 0; i < 3; ++i) {
    result.b[i] = m.add(m.mul(across, m.sub(at[1][i], at[0][i])), at[0][i]);
  }
  return result;
}

// b_i = b_i(anchor) + db_i/dy * dy + db_i/dx * dx. The reference anchors at vertex 0 with the
// pixel's offsets from it; the float32 evaluator anchors at the origin's first pixel center
// (value computed in double, then rounded) with the pixel's integer offsets from it.
BoundedWeights plane_equations(Evaluator evaluator, const ScreenTriangle& t, double origin_x,
                               double origin_y, double px, double py) {
  const RoundingModel& m = model_for(evaluator);
  const RoundingModel& setup = model_for(Evaluator::reference);
  const double area = twice_area(t);
  const double anchor_dx = origin_x + 0.5 - t.x[0];
  const double anchor_dy = origin_y + 0.5 - t.y[0];
  BoundedWeights result;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int k = (i + 2) % 3;
    // Gradients: an exact difference divided by the exact area, in double.
    const Bounded gradient_x =
        setup.div(RoundingModel::exact(-(t.y[k] - t.y[j])), RoundingModel::exact(area));
    const Bounded gradient_y =
        setup.div(RoundingModel::exact(t.x[k] - t.x[j]), RoundingModel::exact(area));
    const Bounded at_vertex0 = RoundingModel::exact(i == 0 ? 1.0 : 0.0);
    if (evaluator == Evaluator::reference) {
      const Bounded dy = RoundingModel::exact(py - t.y[0]);
      const Bounded dx = RoundingModel::exact(px - t.x[0]);
      result.b[i] = m.add(m.add(at_vertex0, m.mul(gradient_y, dy)), m.mul(gradient_x, dx));
    } else {
      const Bounded c0 =
          setup.add(setup.add(at_vertex0, setup.mul(gradient_y, RoundingModel::exact(anchor_dy))),
                    setup.mul(gradient_x, RoundingModel::exact(anchor_dx)));
      const Bounded column = RoundingModel::exact(px - 0.5 - origin_x);
      const Bounded row = RoundingModel::exact(py - 0.5 - origin_y);
      const Bounded row_start =
          m.add(m.mul(setup_value(evaluator, gradient_y), row), setup_value(evaluator, c0));
      result.b[i] = m.add(m.mul(setup_value(evaluator, gradient_x), column), row_start);
    }
  }
  return result;
}

bool exactly(Bounded a, double value) {
  return a.value == value && a.error == 0.0;
}

// x * y for error terms, where 0 times an unbounded error is 0 (an exact zero stays zero).
double times(double x, double y) {
  return x == 0.0 || y == 0.0 ? 0.0 : x * y;
}

}  // namespace

Bounded RoundingModel::rounded(Bounded a) const {
  return {a.value, a.error + u_ * (std::abs(a.value) + a.error)};
}

Bounded RoundingModel::add(Bounded a, Bounded b) const {
  // Adding an exact zero is exact.
  if (exactly(a, 0.0)) return b;
  if (exactly(b, 0.0)) return a;
  const double value = a.value + b.value;
  const double propagated = a.error + b.error;
  return {value, propagated + u_ * (std::abs(value) + propagated)};
}

Bounded RoundingModel::sub(Bounded a, Bounded b) const {
  return add(a, Bounded{-b.value, b.error});
}

Bounded RoundingModel::mul(Bounded a, Bounded b) const {
  // Multiplying by an exact zero or one is exact (the computed factor is finite).
  if (exactly(a, 0.0) || exactly(b, 0.0)) return exact(0.0);
  if (exactly(a, 1.0)) return b;
  if (exactly(b, 1.0)) return a;
  const double value = a.value * b.value;
  const double propagated = times(std::abs(a.value), b.error) + times(std::abs(b.value), a.error) +
                            times(a.error, b.error);
  return {value, propagated + u_ * (std::abs(value) + propagated)};
}

Bounded RoundingModel::div(Bounded a, Bounded b) const {
  const double value = a.value / b.value;
  const double denominator = std::abs(b.value) - b.error;
  if (!(denominator > 0.0)) return {value, kInfinity};
  const double quotient = (std::abs(a.value) + a.error) / denominator;
  const double propagated = (a.error + quotient * b.error) / denominator;
  return {value, propagated + u_ * quotient};
}

Bounded RoundingModel::sqrt(Bounded a) const {
  const double value = std::sqrt(std::max(a.value, 0.0));
  const double low = std::abs(a.value) - a.error;
  double propagated = std::sqrt(a.error);
  if (low > 0.0) propagated = std::min(propagated, a.error / std::sqrt(low));
  return {value, propagated + u_ * std::sqrt(std::abs(a.value) + a.error)};
}

Bounded RoundingModel::max(Bounded a, Bounded b) {
  return {std::max(a.value, b.value), std::max(a.error, b.error)};
}

BoundedWeights screen_weight_bounds(InterpolationMethod method, Evaluator evaluator,
                                    const ScreenTriangle& triangle, double origin_x,
                                    double origin_y, double px, double py) {
  const Frame f = frame_for(evaluator, triangle, origin_x, origin_y, px, py);
  if (!finite(triangle)) return centroid(evaluator);
  if (method == InterpolationMethod::inverse_distance) {
    if (evaluator == Evaluator::float32) return inverse_distance(evaluator, f);
    const reference::Weights weights = reference::screen_weights(method, triangle, px, py);
    BoundedWeights result;
    for (int i = 0; i < 3; ++i)
      result.b[i] = {weights.b[i], reference_inverse_distance_error(weights.b[i])};
    return result;
  }
  if (twice_area(triangle) == 0.0) return centroid(evaluator);
  switch (method) {
    case InterpolationMethod::subtriangle_areas:
      return subtriangle_areas(evaluator, f, twice_area(triangle));
    case InterpolationMethod::edge_functions:
      return edge_functions(evaluator, f, triangle);
    case InterpolationMethod::scanline:
      return scanline(evaluator, f);
    case InterpolationMethod::plane_equations:
      return plane_equations(evaluator, triangle, origin_x, origin_y, px, py);
    default:
      break;
  }
  const Bounded unbounded{0.0, kInfinity};
  return {{unbounded, unbounded, unbounded}};
}

void squared_distance_bounds(Evaluator evaluator, const ScreenTriangle& triangle, double origin_x,
                             double origin_y, double px, double py, Bounded squared[3]) {
  const RoundingModel& m = model_for(evaluator);
  const Frame f = frame_for(evaluator, triangle, origin_x, origin_y, px, py);
  for (int i = 0; i < 3; ++i) {
    const Bounded dx = m.sub(RoundingModel::exact(f.px), RoundingModel::exact(f.x[i]));
    const Bounded dy = m.sub(RoundingModel::exact(f.py), RoundingModel::exact(f.y[i]));
    squared[i] = m.add(m.mul(dx, dx), m.mul(dy, dy));
  }
}

BoundedWeights perspective_bounds(Evaluator evaluator, const BoundedWeights& screen,
                                  const ScreenTriangle& triangle) {
  const RoundingModel& m = model_for(evaluator);
  const RoundingModel& setup = model_for(Evaluator::reference);
  Bounded over_w[3];
  Bounded smallest{kInfinity, 0.0};
  for (int i = 0; i < 3; ++i) {
    const Bounded inverse_w =
        setup.div(RoundingModel::exact(1.0), RoundingModel::exact(triangle.w[i]));
    if (evaluator == Evaluator::float32) {
      over_w[i] = m.mul(screen.b[i], setup_value(evaluator, inverse_w));
    } else {
      over_w[i] = m.div(screen.b[i], RoundingModel::exact(triangle.w[i]));
    }
    if (inverse_w.value < smallest.value) smallest = setup_value(evaluator, inverse_w);
  }
  const Bounded inverse_w =
      RoundingModel::max(m.add(m.add(over_w[0], over_w[1]), over_w[2]), smallest);
  BoundedWeights result;
  if (evaluator == Evaluator::float32) {
    const Bounded w = m.div(RoundingModel::exact(1.0), inverse_w);
    for (int i = 0; i < 3; ++i)
      result.b[i] = m.mul(over_w[i], w);
  } else {
    for (int i = 0; i < 3; ++i)
      result.b[i] = m.div(over_w[i], inverse_w);
  }
  return result;
}

ExactWeights exact_weights_with_error(const ScreenTriangle& triangle, double px, double py) {
  // exact_weights: exact edge functions, then b_i = F_i / (2A) and q_i = b_i / w_i (two
  // roundings), s = q0 + q1 + q2 (two, error at most 4 * 2^-64 * sum |q|), the clamp (no
  // error), B_i = q_i / s (one): relative error at most 2^-61 (1 + sum |q| / s). The final
  // rounding to double adds 2^-53 |B_i|. Long double has at least 64 significand bits.
  ExactWeights result;
  const ScreenTriangle flat{{triangle.x[0], triangle.x[1], triangle.x[2]},
                            {triangle.y[0], triangle.y[1], triangle.y[2]},
                            {1.0, 1.0, 1.0}};
  result.screen = reference::exact_weights(flat, px, py);
  double w[3];
  reference::usable_clip_w(triangle, w);
  const bool affine = w[0] == 1.0 && w[1] == 1.0 && w[2] == 1.0;
  result.correct = affine ? result.screen : reference::exact_weights(triangle, px, py);
  auto conditioning = [&](const double(&v)[3]) {
    double sum = 0.0, sum_abs = 0.0, smallest = kInfinity;
    for (int i = 0; i < 3; ++i) {
      sum += result.screen.b[i] / v[i];
      sum_abs += std::abs(result.screen.b[i] / v[i]);
      smallest = std::min(smallest, 1.0 / v[i]);
    }
    // Computed in double, itself within a few ulps: the factor 2 covers that.
    return 2.0 * sum_abs / std::max(sum, smallest);
  };
  const double one[3] = {1.0, 1.0, 1.0};
  const double screen_conditioning = conditioning(one);
  const double correct_conditioning = conditioning(w);
  for (int i = 0; i < 3; ++i) {
    result.screen_error[i] =
        std::abs(result.screen.b[i]) * (0x1.0p-53 + 0x1.0p-61 * (1.0 + screen_conditioning));
    result.correct_error[i] =
        std::abs(result.correct.b[i]) * (0x1.0p-53 + 0x1.0p-61 * (1.0 + correct_conditioning));
  }
  return result;
}

}  // namespace edgewise::test
