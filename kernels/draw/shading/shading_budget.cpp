// The error budget's choices and bounds for untextured shading (shading_budget.hpp states them;
// texture_budget.cpp has the textured tiles').
#include "shading_budget.hpp"

#include <algorithm>
#include <bit>
#include <cmath>
#include <limits>

#include "budget_intervals.hpp"
#include "../../texture/level_of_detail.hpp"

namespace edgewise::detail {

using namespace budget;
namespace {

// The magnitude of a plane's terms as the kernels evaluate it, (f0 + gy dy) + gx dx at a covered
// pixel (|dx| <= X, |dy| <= Y, the largest |x_i - x_0| and |y_i - y_0|):
//   M = |f0| + |gx| X + |gy| Y <= |f0| + max(|f1 - f0|, |f2 - f0|) G,
//   G = ((|y1| + |y2|) X + (|x1| + |x2|) Y) / |area|,
// from gx = ((f1 - f0) y2 - (f2 - f0) y1) / area and the like (relative to vertex 0). The float
// evaluation is within 7 u M of the exact plane (tests/draw/colour_bounds.cpp derives it, with M
// also bounding the double set-up's error). One G serves every plane of the triangle.
struct PlaneGeometry {
  double spread = 0.0;  // G; infinite for a zero-area triangle
};

PlaneGeometry plane_geometry(const Vec2 p[3]) {
  const double x1 = static_cast<double>(p[1].x) - p[0].x, y1 = static_cast<double>(p[1].y) - p[0].y;
  const double x2 = static_cast<double>(p[2].x) - p[0].x, y2 = static_cast<double>(p[2].y) - p[0].y;
  const double area = std::abs(x1 * y2 - y1 * x2);
  const double reach_x = std::max(std::abs(x1), std::abs(x2));
  const double reach_y = std::max(std::abs(y1), std::abs(y2));
  if (!(area > 0.0)) return {kInfinity};
  return {((std::abs(y1) + std::abs(y2)) * reach_x + (std::abs(x1) + std::abs(x2)) * reach_y) /
          area};
}

// M for the plane through f; infinite where the kernels' float plane could leave float's range
// (snapped offsets are at least 1/256 px, so |gx|, |gy| <= 256 M).
double plane_magnitude(const PlaneGeometry& g, const double f[3]) {
  const double m =
      std::abs(f[0]) + std::max(std::abs(f[1] - f[0]), std::abs(f[2] - f[0])) * g.spread;
  return m < 0x1p100 ? m : kInfinity;
}

double dot(const Vec3& a, const Vec3& b) {
  return static_cast<double>(a.x) * b.x + static_cast<double>(a.y) * b.y +
         static_cast<double>(a.z) * b.z;
}

// The light's interval and the exact path's error on it (times the lit colour's magnitude),
// for diffuse shading; false where no bound holds.
struct LightBound {
  double low, high;  // a + (1 - a) max(0, n . l / |n|) over the triangle
  double error;      // of max(0, n . l / |n|) in float32, before (1 - a)
};

bool light_interval(const BudgetTriangle& t, const ShadeBatch& batch, double& r_low,
                    LightBound& out) {
  const auto same = [](const Vec3& a, const Vec3& b) {
    return a.x == b.x && a.y == b.y && a.z == b.z;
  };
  if (same(t.normal[0], t.normal[1]) && same(t.normal[0], t.normal[2])) {
    // One normal: one light (the general bounds below would give it too, with more work).
    const double length = std::sqrt(dot(t.normal[0], t.normal[0]));
    if (!(length > 0.0) || !std::isfinite(length)) return false;
    const double a = batch.ambient;
    out.low = out.high = a + (1.0 - a) * std::max(0.0, dot(t.normal[0], batch.light) / length);
    r_low = length;
    return std::isfinite(out.low);
  }
  double length[3];
  double m[3] = {0.0, 0.0, 0.0};
  for (int i = 0; i < 3; ++i) {
    length[i] = std::sqrt(dot(t.normal[i], t.normal[i]));
    if (!(length[i] > 0.0) || !std::isfinite(length[i])) return false;
    m[0] += t.normal[i].x / length[i];
    m[1] += t.normal[i].y / length[i];
    m[2] += t.normal[i].z / length[i];
  }
  const double m_length = std::sqrt(m[0] * m[0] + m[1] * m[1] + m[2] * m[2]);
  if (!(m_length > 0.0)) return false;
  double r_high = 0.0, d_low = kInfinity, d_high = -kInfinity;
  r_low = kInfinity;
  for (int i = 0; i < 3; ++i) {
    const Vec3& n = t.normal[i];
    r_low = std::min(r_low, (n.x * m[0] + n.y * m[1] + n.z * m[2]) / m_length);
    r_high = std::max(r_high, length[i]);
    const double d = dot(n, batch.light);
    d_low = std::min(d_low, d);
    d_high = std::max(d_high, d);
  }
  // r_low bounds |n| below only where the normals lie within a half space.
  if (!(r_low > 0.0)) return false;
  const double facing_high = d_high > 0.0 ? std::min(1.0, d_high / r_low) : d_high / r_high;
  const double facing_low = d_low >= 0.0 ? d_low / r_high : std::max(-1.0, d_low / r_low);
  const double a = batch.ambient;
  const double light_a = a + (1.0 - a) * std::max(0.0, facing_low);
  const double light_b = a + (1.0 - a) * std::max(0.0, facing_high);
  out.low = std::min(light_a, light_b);
  out.high = std::max(light_a, light_b);
  return std::isfinite(out.low) && std::isfinite(out.high);
}

bool light_error(const BudgetTriangle& t, const PlaneGeometry& geometry, bool divides,
                 const double inverse_w[3], double smallest_inverse_w, double r_low,
                 LightBound& out) {
  // The normal planes (of n / w when dividing) at the pixel: |p| >= q r_low >= s r_low, off by
  // |E| at most; the direction then moves by |E| / (|p| - |E|), plus 12 roundings.
  double error_sq = 0.0;
  for (int k = 0; k < 3; ++k) {
    double f[3];
    for (int i = 0; i < 3; ++i)
      f[i] = static_cast<double>((&t.normal[i].x)[k]) * inverse_w[i];
    const double e = 7.0 * kUnit * plane_magnitude(geometry, f);
    error_sq += e * e;
  }
  const double error = std::sqrt(error_sq);
  const double smallest = (divides ? smallest_inverse_w : 1.0) * r_low;
  if (!(smallest > 2.0 * error)) return false;
  out.error = error / (smallest - error) + 12.0 * kUnit;
  return std::isfinite(out.error);
}

}  // namespace

int budget_codes(const std::optional<float>& budget) {
  if (!budget || !(*budget > 0.0f)) return 0;
  // A budget within 2^-20 of k / 255 counts as k codes: 1/255 written as a decimal or as float
  // often lands a hair below it.
  const double codes = std::floor(255.0 * static_cast<double>(*budget) * (1.0 + 0x1p-20));
  return codes < 255.0 ? static_cast<int>(codes) : 255;
}

bool budget_shades(const ShadeBatch& batch) {
  const bool planes = batch.shading == Shading::gouraud || batch.shading == Shading::diffuse;
  const bool textured_flat = batch.texture != nullptr && batch.shading == Shading::flat;
  return batch.budget_codes > 0 && (planes || textured_flat);
}

bool budget_tiles(const ShadeBatch& batch) {
  if (!budget_shades(batch) || batch.texture == nullptr) return false;
  switch (batch.sampler.filter) {
    case TextureFilter::nearest:
    case TextureFilter::bilinear:
    case TextureFilter::mip_nearest:
    case TextureFilter::trilinear:
      return true;
    default:
      return false;
  }
}

namespace {

// Flat shading: 255 c in float, one rounding.
ShadeInterval flat_interval(const BudgetTriangle& t) {
  ShadeInterval out;
  for (int k = 0; k < 4; ++k) {
    out.low[k] = out.high[k] = (&t.colour[0].x)[k];
    out.rounding[k] = 2.0 * kUnit * std::abs(out.low[k]);
    if (!std::isfinite(out.low[k])) return out;
  }
  out.bounded = true;
  return out;
}

// The model's colour ranges: each channel's least and greatest vertex value into `out`, the
// larger magnitude of the two into colour_abs; returns the largest of R, G and B.
double colour_ranges(const BudgetTriangle& t, ShadeInterval& out, double (&colour_abs)[4]) {
  double brightest = 0.0;
  for (int k = 0; k < 4; ++k) {
    double low = kInfinity, high = -kInfinity;
    for (int i = 0; i < 3; ++i) {
      const double c = (&t.colour[i].x)[k];
      low = std::min(low, c);
      high = std::max(high, c);
    }
    out.low[k] = low;
    out.high[k] = high;
    colour_abs[k] = std::max(std::abs(low), std::abs(high));
    if (k < 3) brightest = std::max(brightest, colour_abs[k]);
  }
  return brightest;
}

// The exact path's float32 rounding of each colour plane (scaled to 0 .. 255), divided by the
// plane of 1 / w where the triangle divides, into out.rounding; returns false where the plane of
// 1 / w cannot be kept from 0.
bool planar_rounding(const BudgetTriangle& t, const PlaneGeometry& geometry, bool divides,
                     const double (&inverse_w)[3], const double (&colour_abs)[4],
                     ShadeInterval& out) {
  const double s = std::min({inverse_w[0], inverse_w[1], inverse_w[2]});
  // The plane of 1 / w, kept from falling below s: its error bound as the kernels hold it.
  double q_error = 0.0;
  if (divides) {
    q_error = std::max(7.0 * kUnit * plane_magnitude(geometry, inverse_w), kUnit * s);
    if (!(s - q_error > 0.0)) return false;
  }
  const double inverse_margin = divides ? 1.0 / (s - q_error) : 1.0;
  for (int k = 0; k < 4; ++k) {
    double f[3];
    for (int i = 0; i < 3; ++i)
      f[i] = 255.0 * static_cast<double>((&t.colour[i].x)[k]) * inverse_w[i];
    const double p_error = 7.0 * kUnit * plane_magnitude(geometry, f);
    double error = p_error;
    if (divides) {
      // p / q with |p / q| <= 255 c_abs exactly: worst where q is least, s.
      const double ratio = (s * 255.0 * colour_abs[k] + p_error) * inverse_margin;
      error = (p_error + ratio * q_error) * inverse_margin + 2.0 * kUnit * ratio;
    }
    out.rounding[k] = error / 255.0;
  }
  return true;
}

}  // namespace

ShadeInterval shade_interval(const BudgetTriangle& t, const ShadeBatch& batch) {
  if (batch.shading == Shading::flat) return flat_interval(t);
  const double width_limit =
      batch.texture != nullptr ? kInfinity : untextured_width_limit(batch.budget_codes);
  ShadeInterval out;
  // The model first: the colours' and the light's ranges, cheap, and often enough to decide.
  double colour_abs[4];
  const double brightest = colour_ranges(t, out, colour_abs);
  LightBound light{};
  double r_low = 0.0;
  if (batch.shading == Shading::diffuse) {
    if (!light_interval(t, batch, r_low, light)) return out;
    for (int k = 0; k < 3; ++k)
      multiply(out.low[k], out.high[k], light.low, light.high, out.low[k], out.high[k]);
  }
  for (int k = 0; k < 4; ++k) {
    if (!(clamp01(out.high[k]) - clamp01(out.low[k]) < width_limit)) return out;
  }
  // Then the exact path's float32 rounding.
  const PlaneGeometry geometry = plane_geometry(t.position);
  const bool divides = texture_divides(batch.perspective, t.w);
  double inverse_w[3] = {1.0, 1.0, 1.0};
  if (divides) {
    for (int i = 0; i < 3; ++i)
      inverse_w[i] = 1.0 / t.w[i];
  }
  if (!planar_rounding(t, geometry, divides, inverse_w, colour_abs, out)) return out;
  double worst_colour = 0.0;
  for (int k = 0; k < 3; ++k)
    worst_colour = std::max(worst_colour, out.rounding[k]);
  if (batch.shading == Shading::diffuse) {
    const double s = std::min({inverse_w[0], inverse_w[1], inverse_w[2]});
    if (!light_error(t, geometry, divides, inverse_w, s, r_low, light)) return out;
    const double lit_error =
        (std::abs(1.0 - static_cast<double>(batch.ambient)) * light.error + 4.0 * kUnit) *
        std::max(1.0, brightest + worst_colour);
    for (int k = 0; k < 3; ++k)
      out.rounding[k] = worst_colour + lit_error;
  }
  bool finite = true;
  for (int k = 0; k < 4; ++k)
    finite = finite && std::isfinite(out.low[k]) && std::isfinite(out.high[k]) &&
             std::isfinite(out.rounding[k]);
  out.bounded = finite;
  return out;
}

std::optional<std::uint32_t> constant_colour(const ShadeInterval& shade, int codes) {
  if (!shade.bounded || codes <= 0) return std::nullopt;
  std::uint32_t packed = 0;
  for (int k = 0; k < 4; ++k) {
    const double low = clamp01(shade.low[k]), high = clamp01(shade.high[k]);
    const double error = (high - low) / 2.0 + shade.rounding[k];
    if (!(255.0 * error < codes)) return std::nullopt;
    packed |= to_byte((low + high) / 2.0) << (8 * k);
  }
  return packed;
}

}  // namespace edgewise::detail
