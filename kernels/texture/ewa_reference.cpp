// The scalar reference's elliptical weighted average (sample_reference.hpp): Heckbert's ellipse
// per level, its Gaussian weights from a table, and the levels it blends, in double precision.
#include <algorithm>
#include <array>
#include <cmath>
#include <span>
#include <stdexcept>

#include "level_of_detail.hpp"
#include "sample_reference.hpp"
#include "sample_reference_terms.hpp"

namespace edgewise::reference {

using namespace sample_terms;

namespace {

std::array<double, kEwaWeightCount> make_ewa_weights() {
  std::array<double, kEwaWeightCount> table{};
  for (int i = 0; i < kEwaWeightCount; ++i) {
    const double r2 = static_cast<double>(i) / (kEwaWeightCount - 1);
    table[static_cast<std::size_t>(i)] = std::exp(-2.0 * r2) - std::exp(-2.0);
  }
  return table;
}

// The table interpolated linearly at Q (entry i sits at Q = i / 127), so that a weight changes
// continuously with the texel's position: 0 at the ellipse's edge, no steps between bins.
double ewa_weight(std::span<const double> table, double Q) {
  const double position = Q * (kEwaWeightCount - 1);
  const auto i = std::min(static_cast<std::size_t>(position), std::size_t{kEwaWeightCount - 2});
  const double f = position - static_cast<double>(i);
  return table[i] * (1 - f) + table[i + 1] * f;
}

// The ellipse in a level (Heckbert): Q(du, dv) = A du^2 + B du dv + C dv^2 < 1, normalized so
// that F = 1, and the half extents of its bounding box.
struct EwaEllipse {
  double A, B, C;
  double eu, ev;
};

// The footprint's axes scaled to `level`'s texels.
struct LevelAxes {
  double au, av, bu, bv;
};

LevelAxes level_axes(const Texture& texture, const TextureLevel& level, const EwaFootprint& f) {
  const double scale_u = static_cast<double>(level.width) / texture.width();
  const double scale_v = static_cast<double>(level.height) / texture.height();
  return {f.major_u * scale_u, f.major_v * scale_v, f.minor_u * scale_u, f.minor_v * scale_v};
}

EwaEllipse ewa_ellipse(const LevelAxes& x) {
  // The unit reconstruction disk is added to the footprint (the + 1 terms).
  double A = x.av * x.av + x.bv * x.bv + 1;
  double B = -2 * (x.au * x.av + x.bu * x.bv);
  double C = x.au * x.au + x.bu * x.bu + 1;
  const double F = A * C - B * B / 4;
  A /= F;
  B /= F;
  C /= F;
  const double det = 4 * A * C - B * B;
  return {A, B, C, 2 * std::sqrt(det * C) / det, 2 * std::sqrt(det * A) / det};
}

// Whether the ellipse's bounding box in `level` holds at most `limit` texels: false for a box
// of +inf or NaN texels too.
bool ewa_box_fits(const Texture& texture, const TextureLevel& level, const EwaFootprint& f,
                  double limit) {
  return ewa_box_texels(texture, level, f) <= limit;
}

}  // namespace

EwaFootprint ewa_footprint(const Texture& texture, const SamplerOptions& options,
                           const TextureQuery& query) {
  const TexelDerivatives d = texel_derivatives(texture, query);
  const bool a_is_major = std::hypot(d.ux, d.vx) >= std::hypot(d.uy, d.vy);
  EwaFootprint f;
  f.major_u = a_is_major ? d.ux : d.uy;
  f.major_v = a_is_major ? d.vx : d.vy;
  f.minor_u = a_is_major ? d.uy : d.ux;
  f.minor_v = a_is_major ? d.vy : d.vx;
  const double major_length = std::hypot(f.major_u, f.major_v);
  const double max_anisotropy = options.max_anisotropy;
  // Clamp the eccentricity: a minor axis too short (or zero) becomes major's perpendicular,
  // (-major_v, major_u) / |major| times |major| / M.
  if (std::hypot(f.minor_u, f.minor_v) * max_anisotropy < major_length) {
    f.minor_u = -f.major_v / max_anisotropy;
    f.minor_v = f.major_u / max_anisotropy;
  }
  f.lambda = std::log2(std::hypot(f.minor_u, f.minor_v)) + double{options.lod_bias};
  return f;
}

double ewa_box_limit(int max_anisotropy) {
  const double m = max_anisotropy;
  return 2 * (4 * m + 3) * (4 * m + 3);
}

// The half extents are what ewa_ellipse's formulas reduce to, computed here without their
// cancellation so that a huge footprint cannot slip through as NaN.
double ewa_box_texels(const Texture& texture, const TextureLevel& level,
                      const EwaFootprint& footprint) {
  const LevelAxes x = level_axes(texture, level, footprint);
  const double eu = std::sqrt(x.au * x.au + x.bu * x.bu + 1);
  const double ev = std::sqrt(x.av * x.av + x.bv * x.bv + 1);
  return (2 * eu + 1) * (2 * ev + 1);
}

EwaLevels ewa_levels(const Texture& texture, const SamplerOptions& options,
                     const EwaFootprint& footprint) {
  const std::span<const TextureLevel> levels = texture.mip_levels();
  const double lambda_c = clamp_level_of_detail(texture, footprint.lambda);
  EwaLevels chosen{static_cast<std::size_t>(std::floor(lambda_c)), 0};
  chosen.blend = lambda_c - static_cast<double>(chosen.level);
  const double limit = ewa_box_limit(options.max_anisotropy);
  while (chosen.level + 1 < levels.size() &&
         !ewa_box_fits(texture, levels[chosen.level], footprint, limit)) {
    ++chosen.level;
    chosen.blend = 0;
  }
  return chosen;
}

Rgba ewa_level(const Texture& texture, const TextureLevel& level, WrapMode wrap_s, WrapMode wrap_t,
               double s, double t, const EwaFootprint& footprint) {
  if (!ewa_box_fits(texture, level, footprint, ewa_box_limit(kMaxAnisotropyLimit))) {
    throw std::invalid_argument("reference::ewa_level: the ellipse covers too many texels");
  }
  const EwaEllipse e = ewa_ellipse(level_axes(texture, level, footprint));
  const double cu = reduce_texel_coordinate(s * level.width, level.width, wrap_s, e.eu + 1) - 0.5;
  const double cv = reduce_texel_coordinate(t * level.height, level.height, wrap_t, e.ev + 1) - 0.5;
  const std::span<const double> weights = ewa_weight_table();
  Rgba sum{};
  double weight_sum = 0;
  const auto y_last = static_cast<std::int64_t>(std::floor(cv + e.ev));
  const auto x_last = static_cast<std::int64_t>(std::floor(cu + e.eu));
  for (auto y = static_cast<std::int64_t>(std::ceil(cv - e.ev)); y <= y_last; ++y) {
    for (auto x = static_cast<std::int64_t>(std::ceil(cu - e.eu)); x <= x_last; ++x) {
      const double du = static_cast<double>(x) - cu, dv = static_cast<double>(y) - cv;
      const double Q = e.A * du * du + e.B * du * dv + e.C * dv * dv;
      if (Q >= 1) continue;
      const double weight = ewa_weight(weights, Q);
      add_scaled(sum, texel(texture, level, wrap_s, wrap_t, x, y), weight);
      weight_sum += weight;
    }
  }
  return scaled(sum, 1.0 / weight_sum);
}

Rgba ewa(const Texture& texture, const SamplerOptions& options, const TextureQuery& query) {
  const std::span<const TextureLevel> levels = texture.mip_levels();
  const WrapMode ws = options.wrap_s, wt = options.wrap_t;
  const double s = query.s, t = query.t;
  const EwaFootprint footprint = ewa_footprint(texture, options, query);
  if (std::hypot(footprint.major_u, footprint.major_v) == 0) {
    return bilinear(texture, levels.front(), ws, wt, s, t);  // no footprint: magnify
  }
  const EwaLevels chosen = ewa_levels(texture, options, footprint);
  if (chosen.level + 1 == levels.size()) return coarsest_texel(texture);
  const Rgba fine = ewa_level(texture, levels[chosen.level], ws, wt, s, t, footprint);
  if (chosen.blend == 0) return fine;
  Rgba out = scaled(fine, 1 - chosen.blend);
  add_scaled(out, ewa_level(texture, levels[chosen.level + 1], ws, wt, s, t, footprint),
             chosen.blend);
  return out;
}

std::span<const double> ewa_weight_table() {
  static const std::array<double, kEwaWeightCount> table = make_ewa_weights();
  return table;
}

}  // namespace edgewise::reference
