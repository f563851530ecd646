#include "draw/colour_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace edgewise::test {
namespace {

constexpr double kFloatUnit = 0x1.0p-24;

bool usable_w(const ScreenTriangle& t) {
  for (int i = 0; i < 3; ++i) {
    if (!(t.w[i] >= kMinClipW && t.w[i] <= kMaxClipW)) return false;
  }
  return true;
}

// The perspective step on both sides, then the two sides' bounds added.
WeightErrors combine(BoundedWeights fast, BoundedWeights ref, Perspective perspective,
                     const ScreenTriangle& t) {
  if (perspective == Perspective::correct) {
    const bool equal_w = t.w[0] == t.w[1] && t.w[1] == t.w[2];
    const bool usable = usable_w(t);
    // With equal w the fast path keeps the screen weights, which equal the exact
    // perspective-correct ones. With unusable w it divides by 1/w taken as 1 (rounding still
    // applies), while the reference keeps its screen weights exactly.
    ScreenTriangle unit_w = t;
    for (double& w : unit_w.w)
      w = 1.0;
    if (!equal_w) fast = perspective_bounds(Evaluator::float32, fast, usable ? t : unit_w);
    if (usable) ref = perspective_bounds(Evaluator::reference, ref, t);
  }
  WeightErrors e;
  for (int i = 0; i < 3; ++i) {
    e.value[i] = ref.b[i].value;
    e.error[i] = fast.b[i].error + ref.b[i].error;
  }
  return e;
}

}  // namespace

WeightErrors weight_errors(InterpolationMethod method, Perspective perspective,
                           const ScreenTriangle& t, double px, double py) {
  // The fast kernel sets its interpolators up at the pixel corner below the first vertex.
  const double origin_x = std::floor(t.x[0]), origin_y = std::floor(t.y[0]);
  const BoundedWeights fast =
      screen_weight_bounds(method, Evaluator::float32, t, origin_x, origin_y, px, py);
  BoundedWeights ref = screen_weight_bounds(method, Evaluator::reference, t, 0, 0, px, py);
  if (method == InterpolationMethod::inverse_distance) {
    for (Bounded& b : ref.b)
      b.error = reference_inverse_distance_error(b.value);
  }
  return combine(fast, ref, perspective, t);
}

WeightErrors one_hot_weight_errors(int vertex, Perspective perspective, const ScreenTriangle& t) {
  BoundedWeights one_hot;
  for (int i = 0; i < 3; ++i)
    one_hot.b[i] = RoundingModel::exact(i == vertex ? 1.0 : 0.0);
  return combine(one_hot, one_hot, perspective, t);
}

// A colour channel sum(b_i c_i) is off by at most sum(e_i |c_i|) from the weight errors plus
// 6 float roundings of its terms (three products, two sums, one margin); diffuse multiplies it by
// the light, at most 1, and adds the error of max(0, n.l / |n|), at most |e_n| / (|n| - |e_n|)
// + 12 roundings (n's components, the dot products, sqrt, the division), times (1 - ambient),
// plus 4 roundings of the light term, all times the channel's magnitude where it exceeds 1.
// Codes then differ by the value difference times 255, rounded up, plus one for the rounding
// of each side.
double colour_error(const VertexAttributes& triangle, const WeightErrors& e, Shading shading,
                    float ambient) {
  double color_error = 0.0, brightest = 0.0;
  for (int k = 0; k < 4; ++k) {
    double err = 0.0, magnitude = 0.0;
    for (int i = 0; i < 3; ++i) {
      const float c = (&triangle.colors[i].x)[k];
      err += e.error[i] * std::abs(c);
      magnitude += std::abs(e.value[i] * c) + e.error[i] * std::abs(c);
    }
    color_error = std::max(color_error, err + 6.0 * kFloatUnit * magnitude);
    if (k < 3) brightest = std::max(brightest, magnitude);
  }
  if (shading == Shading::diffuse) {
    double normal_error_sq = 0.0, n[3] = {0, 0, 0};
    for (int k = 0; k < 3; ++k) {
      double err = 0.0, magnitude = 0.0;
      for (int i = 0; i < 3; ++i) {
        const float c = (&triangle.normals[i].x)[k];
        err += e.error[i] * std::abs(c);
        magnitude += std::abs(e.value[i] * c) + e.error[i] * std::abs(c);
        n[k] += e.value[i] * c;
      }
      err += 6.0 * kFloatUnit * magnitude;
      normal_error_sq += err * err;
    }
    const double length = std::sqrt(n[0] * n[0] + n[1] * n[1] + n[2] * n[2]);
    const double normal_error = std::sqrt(normal_error_sq);
    const double lambert_error = length > 2.0 * normal_error
                                     ? normal_error / (length - normal_error) + 12.0 * kFloatUnit
                                     : 1.0;
    color_error = color_error +
                  ((1.0 - ambient) * lambert_error + 4.0 * kFloatUnit) * std::max(1.0, brightest);
  }
  return color_error;
}

int allowed_codes(const VertexAttributes& triangle, const WeightErrors& e, Shading shading,
                  float ambient) {
  const double codes = std::ceil(255.0 * colour_error(triangle, e, shading, ambient));
  return codes < 254.0 ? 1 + static_cast<int>(codes) : 255;  // NaN: unbounded
}

namespace {

// A plane through (x_i, y_i, f_i) evaluated as the kernels do it, relative to vertex 0:
//   value = fl(fl(f0 + fl(gy * dy)) + fl(gx * dx)),
// with f0, gx, gy rounded to float once from their double setup (dx and dy are exact). Against
// the exact plane, the three coefficient roundings and three operation roundings each add at
// most u times a bound on a term's magnitude, with M = |f0| + |gx dx| + |gy dy| bounding them
// all (magnitudes taken from |f1 y2| + |f2 y1| and the like, which also bound the double setup's
// own error, at most 2^-50 M): 6 u M + 2^-50 M <= 7 u M.
struct PlaneValue {
  double value, error;
};

PlaneValue plane_value(const ScreenTriangle& t, const double f[3], double px, double py) {
  const double x1 = t.x[1] - t.x[0], y1 = t.y[1] - t.y[0];
  const double x2 = t.x[2] - t.x[0], y2 = t.y[2] - t.y[0];
  const double area = x1 * y2 - y1 * x2;
  const double f1 = f[1] - f[0], f2 = f[2] - f[0];
  const double dx = px - t.x[0], dy = py - t.y[0];
  const double gx = (f1 * y2 - f2 * y1) / area, gy = (f2 * x1 - f1 * x2) / area;
  const double gx_size = (std::abs(f1 * y2) + std::abs(f2 * y1)) / std::abs(area);
  const double gy_size = (std::abs(f2 * x1) + std::abs(f1 * x2)) / std::abs(area);
  const double magnitude = std::abs(f[0]) + gx_size * std::abs(dx) + gy_size * std::abs(dy);
  // The kernels hold the plane in float: a value or slope beyond float's range becomes infinite
  // there (and infinity times a zero offset NaN), which no rounding bound covers.
  constexpr double kFloatMax = std::numeric_limits<float>::max();
  if (!(std::abs(f[0]) < kFloatMax && std::abs(gx) < kFloatMax && std::abs(gy) < kFloatMax)) {
    return {f[0] + gx * dx + gy * dy, std::numeric_limits<double>::infinity()};
  }
  return {f[0] + gx * dx + gy * dy, 7.0 * 0x1p-24 * magnitude};
}

}  // namespace

double plane_colour_error(const ScreenTriangle& t, const VertexAttributes& attributes,
                          Perspective perspective, double px, double py) {
  bool usable_w = true;
  for (double w : t.w)
    usable_w = usable_w && w >= kMinClipW && w <= kMaxClipW;
  const bool divide =
      perspective == Perspective::correct && usable_w && !(t.w[0] == t.w[1] && t.w[1] == t.w[2]);
  double inverse_w[3] = {1.0, 1.0, 1.0};
  if (divide) {
    for (int i = 0; i < 3; ++i)
      inverse_w[i] = 1.0 / t.w[i];
  }
  PlaneValue q{1.0, 0.0};
  if (divide) {
    q = plane_value(t, inverse_w, px, py);
    // Both sides keep the interpolated 1 / w at least the smallest vertex 1 / w, s (the kernels
    // with s rounded to float, within 2^-24 s): max(a, b) moves by at most the larger of its
    // arguments' moves, so max(q, s) carries the larger of the two errors. Inside the triangle
    // q >= s exactly; outside (a multisampled pixel's centre) it may not be.
    const double s = std::min({inverse_w[0], inverse_w[1], inverse_w[2]});
    q.error = std::max(q.error, 0x1p-24 * s);
    q.value = std::max(q.value, s);
  }
  double worst = 0.0;
  for (int k = 0; k < 4; ++k) {
    double f[3];
    for (int i = 0; i < 3; ++i)
      f[i] = 255.0 * static_cast<double>((&attributes.colors[i].x)[k]) * inverse_w[i];
    const PlaneValue p = plane_value(t, f, px, py);
    double error = p.error;
    if (divide) {
      // p / q with both off by their bounds, then 1/q and the product each rounded once.
      if (!(q.value - q.error > 0.0)) return std::numeric_limits<double>::infinity();
      const double ratio = (std::abs(p.value) + p.error) / (q.value - q.error);
      error = (p.error + ratio * q.error) / (q.value - q.error) + 2.0 * 0x1p-24 * ratio;
    }
    worst = std::max(worst, error);
  }
  return std::isnan(worst) ? std::numeric_limits<double>::infinity() : worst / 255.0;
}

int plane_colour_codes(const ScreenTriangle& t, const VertexAttributes& attributes,
                       Perspective perspective, double px, double py) {
  return plane_shading_codes(t, attributes, perspective, Shading::gouraud, 0.0f, px, py);
}

// The light's error: the normal planes p_k (of n_k / w when perspective-correct, else of n_k)
// carry the plane errors E_k of plane_value(); exactly, p = q n with q > 0 the plane of 1 / w, so
// p / |p| is the reference's n / |n|. A vector off by |E| moves its direction by at most
// |E| / (|p| - |E|); the dot product, the squared length, the square root and the division add
// 12 roundings, as in colour_error(). The kernels scale each triangle's normal planes by one
// factor in double (a relative rounding of 2^-53 per coefficient, within the 2^-50 M the plane
// bound allows for its double set-up), which changes neither the direction nor, relatively, the
// errors; it only keeps float32 away from overflow, so a plane beyond float's range here is not
// one there: the bound is then unbounded, which is safe.
double plane_shading_error(const ScreenTriangle& t, const VertexAttributes& attributes,
                           Perspective perspective, Shading shading, float ambient, double px,
                           double py) {
  const double colour = plane_colour_error(t, attributes, perspective, px, py);
  if (shading != Shading::diffuse) return colour;
  bool usable_w = true;
  for (double w : t.w)
    usable_w = usable_w && w >= kMinClipW && w <= kMaxClipW;
  const bool divide =
      perspective == Perspective::correct && usable_w && !(t.w[0] == t.w[1] && t.w[1] == t.w[2]);
  double error_sq = 0.0, length_sq = 0.0;
  for (int k = 0; k < 3; ++k) {
    double f[3];
    for (int i = 0; i < 3; ++i)
      f[i] = static_cast<double>((&attributes.normals[i].x)[k]) * (divide ? 1.0 / t.w[i] : 1.0);
    const PlaneValue p = plane_value(t, f, px, py);
    error_sq += p.error * p.error;
    length_sq += p.value * p.value;
  }
  const double error = std::sqrt(error_sq), length = std::sqrt(length_sq);
  const double lambert_error =
      length > 2.0 * error ? error / (length - error) + 12.0 * kFloatUnit : 1.0;
  // The lit channels: the colour's error (the light is at most 1) plus the light's error times
  // the colour's magnitude where it exceeds 1, as colour_error() counts them.
  double brightest = 0.0;
  for (int k = 0; k < 3; ++k) {
    for (int i = 0; i < 3; ++i)
      brightest = std::max(brightest, std::abs(static_cast<double>((&attributes.colors[i].x)[k])));
  }
  const double total = colour + ((1.0 - ambient) * lambert_error + 4.0 * kFloatUnit) *
                                    std::max(1.0, brightest + colour);
  return std::isnan(total) ? std::numeric_limits<double>::infinity() : total;
}

int plane_shading_codes(const ScreenTriangle& t, const VertexAttributes& attributes,
                        Perspective perspective, Shading shading, float ambient, double px,
                        double py) {
  const double worst =
      255.0 * plane_shading_error(t, attributes, perspective, shading, ambient, px, py);
  // The reference's own double error is below 2^-40 of a code here.
  if (!std::isfinite(worst) || worst > 254.0) return 255;
  return 1 + static_cast<int>(std::ceil(worst));
}

}  // namespace edgewise::test
