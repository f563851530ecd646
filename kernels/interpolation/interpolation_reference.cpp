#include "interpolation_reference.hpp"

#include <cmath>
#include <limits>

namespace edgewise::reference {
namespace {

static_assert(std::numeric_limits<long double>::digits >= 64,
              "exact_weights needs a long double of at least 64 significand bits");

bool finite_triangle(const ScreenTriangle& t) {
  for (int i = 0; i < 3; ++i) {
    if (!std::isfinite(t.x[i]) || !std::isfinite(t.y[i])) return false;
  }
  return true;
}

// Twice the signed area of (a, b, c): cross(b - a, c - a).
double cross(double ax, double ay, double bx, double by, double cx, double cy) {
  return (bx - ax) * (cy - ay) - (by - ay) * (cx - ax);
}

double twice_area(const ScreenTriangle& t) {
  return cross(t.x[0], t.y[0], t.x[1], t.y[1], t.x[2], t.y[2]);
}

Weights one_hot(int vertex) {
  Weights result{{0.0, 0.0, 0.0}};
  result.b[vertex] = 1.0;
  return result;
}

double squared_distance(const ScreenTriangle& t, int i, double px, double py) {
  const double dx = px - t.x[i];
  const double dy = py - t.y[i];
  return dx * dx + dy * dy;
}

Weights nearest_vertex(const ScreenTriangle& t, double px, double py) {
  int nearest = 0;
  for (int i = 1; i < 3; ++i) {
    if (squared_distance(t, i, px, py) < squared_distance(t, nearest, px, py)) nearest = i;
  }
  return one_hot(nearest);
}

Weights inverse_distance(const ScreenTriangle& t, double px, double py) {
  static_assert(kInverseDistancePower == 1);
  double inverse[3];
  for (int i = 0; i < 3; ++i) {
    inverse[i] = 1.0 / std::sqrt(squared_distance(t, i, px, py));
    // At a vertex (or so close that 1/d overflows) the vertex's value is the answer.
    if (!std::isfinite(inverse[i])) return one_hot(i);
  }
  const double sum = inverse[0] + inverse[1] + inverse[2];
  return {{inverse[0] / sum, inverse[1] / sum, inverse[2] / sum}};
}

// The course's formulation: areas of the sub-triangles the sample makes with each edge.
Weights subtriangle_areas(const ScreenTriangle& t, double px, double py) {
  const double area = twice_area(t);
  const double b0 = cross(px, py, t.x[1], t.y[1], t.x[2], t.y[2]) / area;
  const double b1 = cross(px, py, t.x[2], t.y[2], t.x[0], t.y[0]) / area;
  return {{b0, b1, 1.0 - b0 - b1}};
}

// F_jk(x, y): the edge function of the edge from vertex j to vertex k.
double edge_function(const ScreenTriangle& t, int j, int k, double x, double y) {
  return (t.x[k] - t.x[j]) * (y - t.y[j]) - (t.y[k] - t.y[j]) * (x - t.x[j]);
}

Weights edge_functions(const ScreenTriangle& t, double px, double py) {
  Weights result;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int k = (i + 2) % 3;
    result.b[i] = edge_function(t, j, k, px, py) / edge_function(t, j, k, t.x[i], t.y[i]);
  }
  return result;
}

// Which short edge serves the row y: the upper one (top to middle vertex) above the middle
// vertex, the lower one from there down. A horizontal short edge is never chosen, and neither is
// the short edge that meets the long edge on this row (on the top and bottom vertices' rows),
// where both crossings would be the same point: the other one, extended, crosses the row
// elsewhere for any triangle of nonzero area.
bool use_upper_edge(double top, double mid, double bottom, double y) {
  if (mid == top) return false;
  if (mid == bottom) return true;
  if (y == top) return false;
  if (y == bottom) return true;
  return y < mid;
}

// Along the long edge (top to bottom) and the short edge crossing the row, then across in x.
Weights scanline(const ScreenTriangle& t, double px, double py) {
  int order[3] = {0, 1, 2};  // by y, ties by index
  for (int pass = 0; pass < 2; ++pass) {
    for (int i = 0; i + 1 < 3; ++i) {
      if (t.y[order[i + 1]] < t.y[order[i]]) {
        const int swapped = order[i];
        order[i] = order[i + 1];
        order[i + 1] = swapped;
      }
    }
  }
  const int top = order[0], mid = order[1], bottom = order[2];
  const bool upper = use_upper_edge(t.y[top], t.y[mid], t.y[bottom], py);
  const int s0 = upper ? top : mid;
  const int s1 = upper ? mid : bottom;

  const double along_long = (py - t.y[top]) / (t.y[bottom] - t.y[top]);
  const double x_long = t.x[top] + along_long * (t.x[bottom] - t.x[top]);
  const double along_short = (py - t.y[s0]) / (t.y[s1] - t.y[s0]);
  const double x_short = t.x[s0] + along_short * (t.x[s1] - t.x[s0]);

  Weights at_long{{0.0, 0.0, 0.0}}, at_short{{0.0, 0.0, 0.0}};
  at_long.b[top] = 1.0 - along_long;
  at_long.b[bottom] = along_long;
  at_short.b[s0] = 1.0 - along_short;
  at_short.b[s1] = along_short;

  // Nonzero for nonzero area (see use_upper_edge); the guard keeps off-grid input finite.
  const double span = x_short - x_long;
  const double across = span != 0.0 ? (px - x_long) / span : 0.0;
  Weights result;
  for (int i = 0; i < 3; ++i) {
    result.b[i] = at_long.b[i] + across * (at_short.b[i] - at_long.b[i]);
  }
  return result;
}

// The plane of each weight through vertex 0: b_i = b_i(v0) + db_i/dy (y - y0) + db_i/dx (x - x0).
Weights plane_equations(const ScreenTriangle& t, double px, double py) {
  const double area = twice_area(t);
  const double dx = px - t.x[0];
  const double dy = py - t.y[0];
  Weights result;
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int k = (i + 2) % 3;
    const double gradient_x = -(t.y[k] - t.y[j]) / area;
    const double gradient_y = (t.x[k] - t.x[j]) / area;
    result.b[i] = (i == 0 ? 1.0 : 0.0) + gradient_y * dy + gradient_x * dx;
  }
  return result;
}

bool barycentric(InterpolationMethod method) {
  return method != InterpolationMethod::nearest_vertex &&
         method != InterpolationMethod::inverse_distance;
}

bool zero_area(const ScreenTriangle& t, InterpolationMethod method) {
  if (method == InterpolationMethod::edge_functions) {
    // Each edge is normalized on its own: any zero normalizer is degenerate.
    for (int i = 0; i < 3; ++i) {
      if (edge_function(t, (i + 1) % 3, (i + 2) % 3, t.x[i], t.y[i]) == 0.0) return true;
    }
    return false;
  }
  return twice_area(t) == 0.0;
}

}  // namespace

void usable_clip_w(const ScreenTriangle& triangle, double w[3]) {
  bool usable = true;
  for (int i = 0; i < 3; ++i) {
    usable = usable && triangle.w[i] >= kMinClipW && triangle.w[i] <= kMaxClipW;
  }
  for (int i = 0; i < 3; ++i)
    w[i] = usable ? triangle.w[i] : 1.0;
}

Weights screen_weights(InterpolationMethod method, const ScreenTriangle& triangle, double px,
                       double py) {
  if (!finite_triangle(triangle) || !std::isfinite(px) || !std::isfinite(py)) {
    return kCentroidWeights;
  }
  if (barycentric(method) && zero_area(triangle, method)) return kCentroidWeights;
  switch (method) {
    case InterpolationMethod::nearest_vertex:
      return nearest_vertex(triangle, px, py);
    case InterpolationMethod::inverse_distance:
      return inverse_distance(triangle, px, py);
    case InterpolationMethod::subtriangle_areas:
      return subtriangle_areas(triangle, px, py);
    case InterpolationMethod::edge_functions:
      return edge_functions(triangle, px, py);
    case InterpolationMethod::scanline:
      return scanline(triangle, px, py);
    case InterpolationMethod::plane_equations:
      return plane_equations(triangle, px, py);
  }
  return kCentroidWeights;
}

Weights perspective_correct(const Weights& screen, const double w[3]) {
  for (int i = 0; i < 3; ++i) {
    if (!(w[i] >= kMinClipW && w[i] <= kMaxClipW)) return screen;  // affine, as documented
  }
  double over_w[3];
  double smallest_inverse_w = 1.0 / w[0];
  double inverse_w = 0.0;  // the interpolated 1/w
  for (int i = 0; i < 3; ++i) {
    over_w[i] = screen.b[i] / w[i];
    inverse_w += over_w[i];
    smallest_inverse_w = std::fmin(smallest_inverse_w, 1.0 / w[i]);
  }
  inverse_w = std::fmax(inverse_w, smallest_inverse_w);
  return {{over_w[0] / inverse_w, over_w[1] / inverse_w, over_w[2] / inverse_w}};
}

Weights interpolation_weights(InterpolationMethod method, Perspective perspective,
                              const ScreenTriangle& triangle, double px, double py) {
  const Weights screen = screen_weights(method, triangle, px, py);
  if (perspective == Perspective::affine) return screen;
  double w[3];
  usable_clip_w(triangle, w);
  return perspective_correct(screen, w);
}

Weights exact_weights(const ScreenTriangle& triangle, double px, double py) {
  using Exact = long double;
  if (!finite_triangle(triangle) || !std::isfinite(px) || !std::isfinite(py) ||
      twice_area(triangle) == 0.0) {
    return kCentroidWeights;
  }
  double w[3];
  usable_clip_w(triangle, w);
  Exact edge[3];
  for (int i = 0; i < 3; ++i) {
    const int j = (i + 1) % 3;
    const int k = (i + 2) % 3;
    edge[i] = (Exact{triangle.x[k]} - triangle.x[j]) * (Exact{py} - triangle.y[j]) -
              (Exact{triangle.y[k]} - triangle.y[j]) * (Exact{px} - triangle.x[j]);
  }
  const Exact area = edge[0] + edge[1] + edge[2];  // twice the signed area, exactly
  if (area == 0) return kCentroidWeights;          // off-grid input only
  Exact over_w[3];
  Exact inverse_w = 0;
  Exact smallest_inverse_w = 1 / Exact{w[0]};
  for (int i = 0; i < 3; ++i) {
    over_w[i] = edge[i] / area / w[i];
    inverse_w += over_w[i];
    smallest_inverse_w = std::fmin(smallest_inverse_w, 1 / Exact{w[i]});
  }
  inverse_w = std::fmax(inverse_w, smallest_inverse_w);
  Weights result;
  for (int i = 0; i < 3; ++i)
    result.b[i] = static_cast<double>(over_w[i] / inverse_w);
  return result;
}

}  // namespace edgewise::reference
