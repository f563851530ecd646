// The interpolation methods in float32, one row of Batch::size consecutive pixel centers at a
// time: the three screen-space weights of every method, and the perspective step.
//
// Each method has a setup, made once per triangle from its double snapped coordinates relative
// to an origin (a pixel corner, such as the corner of the first tile the triangle touches), and
// a row evaluation: row(column, row) gives the weights at the pixel centers
// (origin_x + column + lane + 0.5, origin_y + row + 0.5), lane = 0 .. Batch::size - 1.
// Coordinates relative to the origin keep float32 exact: snapped vertices are multiples of 2^-8
// in the guard band [-32768, 32768), so a difference of two is below 2^16 and fits float's 24
// significand bits. Row evaluation has no branch per pixel and allocates nothing.
//
// Degenerate input gets the reference's results
// (kernels/interpolation/interpolation_reference.hpp): centroid weights for non-finite coordinates
// and, for the barycentric methods, for zero area.
//
// Rounding: every operation is a single float32 operation in the order written. xsimd::fma
// fuses on fma3<avx2> and NEON and is a multiply then an add on SSE2/SSE4.1; error bounds hold
// for the unfused form, which is never more accurate.
#pragma once

#include <cmath>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "screen_triangle.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// The three weights of Batch::size consecutive pixels.
template <class Arch>
struct WeightRow {
  xsimd::batch<float, Arch> b[3];
};

namespace interpolation_detail {

template <class Arch>
inline WeightRow<Arch> centroid_row() {
  const xsimd::batch<float, Arch> third(1.0f / 3.0f);
  return {{third, third, third}};
}

// column + lane for each lane, plus `offset` (exact in float for |column| < 2^22).
template <class Arch>
inline xsimd::batch<float, Arch> lane_columns(std::int32_t column, float offset) {
  using Floats = xsimd::batch<float, Arch>;
  alignas(64) static constexpr float kLane[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  static_assert(Floats::size <= 8);
  return Floats::load_aligned(kLane) + Floats(static_cast<float>(column) + offset);
}

// Pixel-center x of each lane relative to the origin: column + lane + 0.5.
template <class Arch>
inline xsimd::batch<float, Arch> lane_centers(std::int32_t column) {
  return lane_columns<Arch>(column, 0.5f);
}

inline float row_center(std::int32_t row) {
  return static_cast<float>(row) + 0.5f;
}

inline bool finite_triangle(const ScreenTriangle& t) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(t.x[i]) || !std::isfinite(t.y[i])) return false;
  }
  return true;
}

// Twice the signed area, from the snapped doubles: exact in double (products of 25-bit
// differences).
inline double twice_area(const ScreenTriangle& t) {
  return (t.x[1] - t.x[0]) * (t.y[2] - t.y[0]) - (t.y[1] - t.y[0]) * (t.x[2] - t.x[0]);
}

// The vertices relative to the origin, exact in float32 (see the top of this file).
struct RelativeVertices {
  float x[3] = {0.0f, 0.0f, 0.0f};
  float y[3] = {0.0f, 0.0f, 0.0f};
  RelativeVertices() = default;
  RelativeVertices(const ScreenTriangle& t, double origin_x, double origin_y) {
    for (int i = 0; i < 3; ++i) {
      x[i] = static_cast<float>(t.x[i] - origin_x);
      y[i] = static_cast<float>(t.y[i] - origin_y);
    }
  }
};

// The methods that work from distances to the vertices: the vertices relative to the origin,
// and the squared distances from each lane's pixel center in (column, row) to them. Unusable
// (non-finite) triangles get the centroid weights.
template <class Arch>
class VertexDistances {
 public:
  using Floats = xsimd::batch<float, Arch>;
  VertexDistances(const ScreenTriangle& t, double origin_x, double origin_y)
      : usable_(finite_triangle(t)) {
    if (usable_) vertices_ = {t, origin_x, origin_y};
  }

 protected:
  void squared_distances(std::int32_t column, std::int32_t row, Floats squared[3]) const {
    const Floats x = lane_centers<Arch>(column);
    const float y = row_center(row);
    for (int i = 0; i < 3; ++i) {
      const Floats dx = x - Floats(vertices_.x[i]);
      const Floats dy(y - vertices_.y[i]);
      squared[i] = dx * dx + dy * dy;
    }
  }
  bool usable_;
  RelativeVertices vertices_;
};

}  // namespace interpolation_detail

template <class Arch, InterpolationMethod Method>
class ScreenInterpolator;

// One-hot on the closest vertex, ties to the lowest index (squared distances compared).
template <class Arch>
class ScreenInterpolator<Arch, InterpolationMethod::nearest_vertex>
    : interpolation_detail::VertexDistances<Arch> {
 public:
  using Floats = xsimd::batch<float, Arch>;
  using interpolation_detail::VertexDistances<Arch>::VertexDistances;

  WeightRow<Arch> row(std::int32_t column, std::int32_t row) const {
    if (!this->usable_) return interpolation_detail::centroid_row<Arch>();
    Floats squared[3];
    this->squared_distances(column, row, squared);
    const auto pick0 = (squared[0] <= squared[1]) & (squared[0] <= squared[2]);
    const auto pick1 = ~pick0 & (squared[1] <= squared[2]);
    const auto pick2 = ~pick0 & ~pick1;
    const Floats one(1.0f), zero(0.0f);
    return {{xsimd::select(pick0, one, zero), xsimd::select(pick1, one, zero),
             xsimd::select(pick2, one, zero)}};
  }
};

// Weights 1/d_i normalized, written as b_i = d_j d_k / (d1 d2 + d0 d2 + d0 d1) (numerator and
// denominator multiplied by d0 d1 d2): no division by a distance, so a sample on a vertex
// gets that vertex's one-hot weights without a branch. Only when two coincident vertices share
// the sample is the denominator 0; the lowest such vertex then takes the weight.
template <class Arch>
class ScreenInterpolator<Arch, InterpolationMethod::inverse_distance>
    : interpolation_detail::VertexDistances<Arch> {
 public:
  using Floats = xsimd::batch<float, Arch>;
  static_assert(kInverseDistancePower == 1);
  using interpolation_detail::VertexDistances<Arch>::VertexDistances;

  WeightRow<Arch> row(std::int32_t column, std::int32_t row) const {
    if (!this->usable_) return interpolation_detail::centroid_row<Arch>();
    Floats distance[3];
    this->squared_distances(column, row, distance);
    for (Floats& d : distance)
      d = xsimd::sqrt(d);
    const Floats products[3] = {distance[1] * distance[2], distance[0] * distance[2],
                                distance[0] * distance[1]};
    const Floats sum = products[0] + products[1] + products[2];
    const Floats zero(0.0f), one(1.0f);
    const auto shared_vertex = sum == zero;
    const Floats denominator = xsimd::select(shared_vertex, one, sum);
    const auto at0 = distance[0] == zero;
    const auto at1 = ~at0 & (distance[1] == zero);
    const auto at2 = ~at0 & ~at1;
    const Floats fallback[3] = {xsimd::select(at0, one, zero), xsimd::select(at1, one, zero),
                                xsimd::select(at2, one, zero)};
    WeightRow<Arch> result;
    for (int i = 0; i < 3; ++i) {
      result.b[i] = xsimd::select(shared_vertex, fallback[i], products[i] / denominator);
    }
    return result;
  }
};

// The course's cross products: b0 = cross(v1 - p, v2 - p) / A, b1 = cross(v2 - p, v0 - p) / A,
// b2 = 1 - b0 - b1, with 1/A rounded once at setup.
template <class Arch>
class ScreenInterpolator<Arch, InterpolationMethod::subtriangle_areas> {
 public:
  using Floats = xsimd::batch<float, Arch>;
  ScreenInterpolator(const ScreenTriangle& t, double origin_x, double origin_y) {
    const double area =
        interpolation_detail::finite_triangle(t) ? interpolation_detail::twice_area(t) : 0.0;
    usable_ = area != 0.0;
    if (usable_) {
      vertices_ = {t, origin_x, origin_y};
      inverse_area_ = static_cast<float>(1.0 / area);
    }
  }

  WeightRow<Arch> row(std::int32_t column, std::int32_t row) const {
    if (!usable_) return interpolation_detail::centroid_row<Arch>();
    const Floats x = interpolation_detail::lane_centers<Arch>(column);
    const float y = interpolation_detail::row_center(row);
    Floats to_x[3];
    Floats to_y[3];
    for (int i = 0; i < 3; ++i) {
      to_x[i] = Floats(vertices_.x[i]) - x;
      to_y[i] = Floats(vertices_.y[i] - y);
    }
    const Floats inverse_area(inverse_area_);
    const Floats b0 = (to_x[1] * to_y[2] - to_y[1] * to_x[2]) * inverse_area;
    const Floats b1 = (to_x[2] * to_y[0] - to_y[2] * to_x[0]) * inverse_area;
    return {{b0, b1, Floats(1.0f) - b0 - b1}};
  }

 private:
  bool usable_ = false;
  interpolation_detail::RelativeVertices vertices_;
  float inverse_area_ = 0.0f;
};

// b_i = F_jk(p) / F_jk(v_i) for the edge (j, k) opposite vertex i, each edge normalized on its
// own: F_jk(p) = (x_k - x_j)(y - y_j) - (y_k - y_j)(x - x_j), edge vectors and 1/F_jk(v_i)
// rounded once at setup.
template <class Arch>
class ScreenInterpolator<Arch, InterpolationMethod::edge_functions> {
 public:
  using Floats = xsimd::batch<float, Arch>;
  ScreenInterpolator(const ScreenTriangle& t, double origin_x, double origin_y) {
    usable_ = interpolation_detail::finite_triangle(t);
    if (!usable_) return;
    const interpolation_detail::RelativeVertices v(t, origin_x, origin_y);
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const int k = (i + 2) % 3;
      const double edge_x = t.x[k] - t.x[j];
      const double edge_y = t.y[k] - t.y[j];
      const double at_opposite = edge_x * (t.y[i] - t.y[j]) - edge_y * (t.x[i] - t.x[j]);
      usable_ = usable_ && at_opposite != 0.0;
      edge_x_[i] = static_cast<float>(edge_x);
      edge_y_[i] = static_cast<float>(edge_y);
      start_x_[i] = v.x[j];
      start_y_[i] = v.y[j];
      inverse_[i] = static_cast<float>(1.0 / at_opposite);
    }
  }

  WeightRow<Arch> row(std::int32_t column, std::int32_t row) const {
    if (!usable_) return interpolation_detail::centroid_row<Arch>();
    const Floats x = interpolation_detail::lane_centers<Arch>(column);
    const float y = interpolation_detail::row_center(row);
    WeightRow<Arch> result;
    for (int i = 0; i < 3; ++i) {
      const Floats edge =
          Floats(edge_x_[i] * (y - start_y_[i])) - Floats(edge_y_[i]) * (x - Floats(start_x_[i]));
      result.b[i] = edge * Floats(inverse_[i]);
    }
    return result;
  }

 private:
  bool usable_ = false;
  float edge_x_[3] = {}, edge_y_[3] = {}, start_x_[3] = {}, start_y_[3] = {}, inverse_[3] = {};
};

// The scan-line method: per row, the weights where the row crosses the long edge (top to
// bottom vertex) and the short edge spanning the row, then linear in x across the span:
// b_i = b_i(long) + (x - x_long) / (x_short - x_long) * (b_i(short) - b_i(long)).
// Per-row work is scalar float (two divisions); per pixel it is one subtract, one multiply and
// three FMAs.
template <class Arch>
class ScreenInterpolator<Arch, InterpolationMethod::scanline> {
 public:
  using Floats = xsimd::batch<float, Arch>;
  ScreenInterpolator(const ScreenTriangle& t, double origin_x, double origin_y) {
    usable_ = interpolation_detail::finite_triangle(t) && interpolation_detail::twice_area(t) != 0;
    if (!usable_) return;
    vertices_ = {t, origin_x, origin_y};
    // Order by y, ties by index (the reference's order).
    for (int pass = 0; pass < 2; ++pass) {
      for (int i = 0; i + 1 < 3; ++i) {
        if (t.y[order_[i + 1]] < t.y[order_[i]]) {
          const int swapped = order_[i];
          order_[i] = order_[i + 1];
          order_[i + 1] = swapped;
        }
      }
    }
    // Edges: 0 = long (top to bottom), 1 = upper (top to middle), 2 = lower (middle to bottom).
    const int from[3] = {order_[0], order_[0], order_[1]};
    const int to[3] = {order_[2], order_[1], order_[2]};
    for (int e = 0; e < 3; ++e) {
      from_[e] = from[e];
      to_[e] = to[e];
      // Both differences are exact in float (below 2^16, multiples of 2^-8).
      height_[e] = static_cast<float>(t.y[to[e]] - t.y[from[e]]);
      run_[e] = static_cast<float>(t.x[to[e]] - t.x[from[e]]);
    }
  }

  WeightRow<Arch> row(std::int32_t column, std::int32_t row) const {
    if (!usable_) return interpolation_detail::centroid_row<Arch>();
    const float y = interpolation_detail::row_center(row);
    const float top = vertices_.y[order_[0]], middle = vertices_.y[order_[1]],
                bottom = vertices_.y[order_[2]];
    // The upper edge serves rows above the middle vertex, the lower one the rest; never a
    // horizontal edge, nor the one meeting the long edge on this row (the reference's rule).
    bool upper = y < middle;
    if (y == top) upper = false;
    if (y == bottom) upper = true;
    if (middle == bottom) upper = true;
    if (middle == top) upper = false;
    const int short_edge = upper ? 1 : 2;

    float along[2], x_at[2];
    float at[2][3] = {{0.0f, 0.0f, 0.0f}, {0.0f, 0.0f, 0.0f}};  // weights at the crossings
    const int edges[2] = {0, short_edge};
    for (int s = 0; s < 2; ++s) {
      const int e = edges[s];
      // A division, not a multiply by 1/height: along is exactly 1 on the far vertex's row, so
      // both crossings land exactly on that vertex and the span is exactly 0 there.
      along[s] = (y - vertices_.y[from_[e]]) / height_[e];
      x_at[s] = vertices_.x[from_[e]] + along[s] * run_[e];
      at[s][from_[e]] = 1.0f - along[s];
      at[s][to_[e]] = along[s];
    }
    // The span is nonzero in exact arithmetic; rounded, a nonzero one is at least about 2^-57 px
    // (crossings are sums of multiples of 2^-8 and products of a 2^-9-grid height fraction and
    // a 2^-8-grid run), so 1/span and the weights stay far below float's overflow.
    const float span = x_at[1] - x_at[0];
    const float inverse_span = span != 0.0f ? 1.0f / span : 0.0f;

    const Floats x = interpolation_detail::lane_centers<Arch>(column);
    const Floats across = (x - Floats(x_at[0])) * Floats(inverse_span);
    WeightRow<Arch> result;
    for (int i = 0; i < 3; ++i) {
      result.b[i] = xsimd::fma(across, Floats(at[1][i] - at[0][i]), Floats(at[0][i]));
    }
    return result;
  }

 private:
  bool usable_ = false;
  interpolation_detail::RelativeVertices vertices_;
  int order_[3] = {0, 1, 2};
  int from_[3] = {}, to_[3] = {};
  float height_[3] = {1.0f, 1.0f, 1.0f}, run_[3] = {};
};

// Plane equations, the production method: b_i = c0_i + cx_i * (column + lane) + cy_i * row,
// coefficients computed in double at setup (c0_i at the origin's first pixel center) and
// rounded once; one FMA per row and one per pixel for each weight.
template <class Arch>
class ScreenInterpolator<Arch, InterpolationMethod::plane_equations> {
 public:
  using Floats = xsimd::batch<float, Arch>;
  ScreenInterpolator(const ScreenTriangle& t, double origin_x, double origin_y) {
    const double area =
        interpolation_detail::finite_triangle(t) ? interpolation_detail::twice_area(t) : 0.0;
    if (area == 0.0) return;  // constant planes at the centroid weights
    const double dx = origin_x + 0.5 - t.x[0];
    const double dy = origin_y + 0.5 - t.y[0];
    for (int i = 0; i < 3; ++i) {
      const int j = (i + 1) % 3;
      const int k = (i + 2) % 3;
      const double gradient_x = -(t.y[k] - t.y[j]) / area;
      const double gradient_y = (t.x[k] - t.x[j]) / area;
      c0_[i] = static_cast<float>((i == 0 ? 1.0 : 0.0) + gradient_y * dy + gradient_x * dx);
      cx_[i] = static_cast<float>(gradient_x);
      cy_[i] = static_cast<float>(gradient_y);
    }
  }

  WeightRow<Arch> row(std::int32_t column, std::int32_t row) const {
    const Floats x = interpolation_detail::lane_columns<Arch>(column, 0.0f);
    const Floats y(static_cast<float>(row));
    WeightRow<Arch> result;
    for (int i = 0; i < 3; ++i) {
      const Floats row_start = xsimd::fma(Floats(cy_[i]), y, Floats(c0_[i]));
      result.b[i] = xsimd::fma(Floats(cx_[i]), x, row_start);
    }
    return result;
  }

  // The coefficients, for callers that interpolate attributes by their own planes.
  float c0(int i) const { return c0_[i]; }
  float cx(int i) const { return cx_[i]; }
  float cy(int i) const { return cy_[i]; }

 private:
  float c0_[3] = {1.0f / 3.0f, 1.0f / 3.0f, 1.0f / 3.0f};
  float cx_[3] = {}, cy_[3] = {};
};

// The perspective step: B_i = (b_i / w_i) / max(sum_j b_j / w_j, min_j 1/w_j), 1/w_i rounded
// once at setup. The clamp only acts outside the triangle, where the interpolated 1/w can reach
// 0; w outside [kMinClipW, kMaxClipW] leaves the weights affine (the reference's rules).
template <class Arch>
class PerspectiveDivide {
 public:
  using Floats = xsimd::batch<float, Arch>;
  explicit PerspectiveDivide(const ScreenTriangle& t) {
    bool usable = true;
    for (int i = 0; i < 3; ++i) {
      usable = usable && t.w[i] >= kMinClipW && t.w[i] <= kMaxClipW;
    }
    double smallest = 1.0;
    for (int i = 0; i < 3; ++i) {
      const double inverse = usable ? 1.0 / t.w[i] : 1.0;
      inverse_w_[i] = static_cast<float>(inverse);
      smallest = i == 0 ? inverse : std::fmin(smallest, inverse);
    }
    smallest_inverse_w_ = static_cast<float>(smallest);
  }

  WeightRow<Arch> apply(const WeightRow<Arch>& screen) const {
    Floats over_w[3];
    for (int i = 0; i < 3; ++i)
      over_w[i] = screen.b[i] * Floats(inverse_w_[i]);
    const Floats inverse_w =
        xsimd::max(over_w[0] + over_w[1] + over_w[2], Floats(smallest_inverse_w_));
    const Floats w = Floats(1.0f) / inverse_w;
    return {{over_w[0] * w, over_w[1] * w, over_w[2] * w}};
  }

  float inverse_w(int i) const { return inverse_w_[i]; }

 private:
  float inverse_w_[3] = {};
  float smallest_inverse_w_ = 1.0f;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
