// The per-query bounds of the fast texture filters against the reference (sample_bounds.hpp).
#include "texture/sample_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace edgewise::test {
namespace {

constexpr double kPositionError = 0x1p-21;
constexpr double kLodError = 0x1p-13;
constexpr double kAnisotropyScale = 0x1p-18;

bool finite_query(const TextureQuery& q) {
  return std::isfinite(q.s) && std::isfinite(q.t) && std::isfinite(q.dsdx) &&
         std::isfinite(q.dtdx) && std::isfinite(q.dsdy) && std::isfinite(q.dtdy);
}

// The Lipschitz factor of a filter's weights (see the header comment).
double weight_lipschitz(TextureFilter filter) {
  switch (filter) {
    case TextureFilter::bicubic_catmull_rom:
      return 3.78 / 2 * 1.25;
    case TextureFilter::bicubic_bspline:
      return 2.34 / 2;
    default:
      return 1.0;
  }
}

bool uses_lod(TextureFilter filter) {
  return filter == TextureFilter::mip_nearest || filter == TextureFilter::trilinear ||
         filter == TextureFilter::ripmap || filter == TextureFilter::anisotropic ||
         filter == TextureFilter::ewa;
}

bool has_taps(TextureFilter filter) {
  return filter == TextureFilter::supersample || filter == TextureFilter::anisotropic;
}

// EWA: a weighted mean of the n texels inside the ellipse, w(Q) = exp(-2 Q) - exp(-2). Moving
// the centre by d texels moves each Q by at most 2 d (|grad Q| <= 2 sqrt(Q max(A, C)) <= 2 inside,
// the normalized A, C being at most 1), and each weight by |w'| <= 2 times that; the float
// roundings of Q (a few operations on terms below 1) move it by at most 16 u more. The mean then
// moves by at most sum |dw| R / sum w, and sum w >= exp(-1) - exp(-2) > 0.232 (the ellipse holds
// a texel centre at Q <= 1/2). n is at most the box of the finer level read (the work bound may
// have moved it up from floor(lambda)), (2 sqrt(au^2 + bu^2 + 1) + 1) (2 sqrt(av^2 + bv^2 + 1)
// + 1) in its texels.
double ewa_bound(const Texture& texture, const TextureExtremes& t, const SamplerOptions& options,
                 const TextureQuery& q, double position, double rounding) {
  const reference::EwaFootprint f = reference::ewa_footprint(texture, options, q);
  const std::size_t l0 = reference::ewa_levels(texture, options, f).level;
  const double n = reference::ewa_box_texels(texture, texture.mip_levels()[l0], f);
  const double weight_change = 2.0 * (2.0 * 2.0 * position + 16.0 * 0x1p-24);
  return n * weight_change * t.range / 0.232 + kLodError * t.range + (2 * n) * 0x1p-24 * t.largest +
         rounding;
}

}  // namespace

TextureExtremes texture_extremes(const Texture& texture) {
  double lo = std::numeric_limits<double>::infinity(), hi = -lo, largest = 0;
  const auto scan = [&](std::span<const TextureLevel> levels) {
    for (const TextureLevel& level : levels) {
      for (std::int32_t y = 0; y < level.height; ++y) {
        for (std::int32_t x = 0; x < level.width; ++x) {
          float rgba[4];
          texture.linear_texel(level, x, y, rgba);
          for (float c : rgba) {
            lo = std::min(lo, double(c));
            hi = std::max(hi, double(c));
            largest = std::max(largest, std::fabs(double(c)));
          }
        }
      }
    }
  };
  scan(texture.mip_levels());
  scan(texture.ripmap_levels());
  return {hi - lo, largest};
}

double sample_bound(const Texture& texture, const TextureExtremes& t, const SamplerOptions& options,
                    const TextureQuery& q) {
  // Stored texels decode within 2^-24 relative; (0, 0, 0, 0) for a bad position is exact.
  const double rounding = 64.0 * 0x1p-24 * t.largest;
  const bool reads_derivatives = uses_lod(options.filter) || has_taps(options.filter);
  if (!std::isfinite(q.s) || !std::isfinite(q.t) || (reads_derivatives && !finite_query(q))) {
    return rounding;
  }
  const double w = std::max(texture.width(), texture.height());
  double position = kPositionError * w;
  if (has_taps(options.filter)) {
    const double m = std::fabs(double(q.s)) + std::fabs(double(q.t)) + std::fabs(double(q.dsdx)) +
                     std::fabs(double(q.dtdx)) + std::fabs(double(q.dsdy)) +
                     std::fabs(double(q.dtdy));
    position += 3.0 * 0x1p-24 * m * w;
  }
  if (options.filter == TextureFilter::summed_area) {
    // Double throughout (the table is), with the box's corners exact: only the order of the 64
    // double products differs from the reference. Each term is |w_x w_y| S with sum |w_x| <=
    // 4 (3 + 2 hu / W) and S scale <= T W H, over the box area 4 hu hv, hu >= 1/2: the sum's
    // rounding is below 128 2^-53 16 (3 + 2 hu / W)(3 + 2 hv / H) T W H / (4 hu hv)
    // <= 2^-44 T (6 W + 2)(6 H + 2). The final rounding to float is in `rounding`.
    const double width = texture.width(), height = texture.height();
    return rounding + 0x1p-44 * t.largest * (6 * width + 2) * (6 * height + 2);
  }
  if (options.filter == TextureFilter::ewa)
    return ewa_bound(texture, t, options, q, position, rounding);
  double error = 2.0 * position * weight_lipschitz(options.filter) * t.range;
  if (uses_lod(options.filter)) {
    error += (options.filter == TextureFilter::ripmap ? 2.0 : 1.0) * kLodError * t.range;
  }
  const double taps = options.filter == TextureFilter::supersample
                          ? double(options.supersample_taps) * options.supersample_taps
                          : 0.0;
  const double probes = options.filter == TextureFilter::anisotropic ? options.max_anisotropy : 0.0;
  error += rounding + (taps + probes) * 0x1p-24 * t.largest;
  if (effective_precision(texture, options) == FilterPrecision::fixed16) {
    // Each tap weight rounded to a multiple of 2^-15 (or 1 made 32767 / 32768): off by at most
    // 2^-15, so the exact integer sum by at most 2^-15 T per weight. Supersample and ripmap
    // average bilinear results (4 weights each) with float weights adding up to 1; trilinear
    // has 8 weights, and so has each anisotropic probe, summed at full weight and then averaged.
    const bool eight =
        options.filter == TextureFilter::trilinear || options.filter == TextureFilter::anisotropic;
    const double weights = eight ? 8.0 : 4.0;
    error += weights * 0x1p-15 * t.largest;
  }
  return error;
}

// The reference results the fast one may be compared with: the query itself and, across the
// filter's discontinuities, its neighbours within the fast path's input error.
std::vector<reference::Rgba> accepted_references(const Texture& texture,
                                                 const SamplerOptions& options,
                                                 const TextureQuery& q) {
  std::vector<reference::Rgba> results{reference::sample(texture, options, q)};
  // nearest reads no derivative: its neighbours need only a finite position.
  if (options.filter == TextureFilter::nearest && std::isfinite(q.s) && std::isfinite(q.t)) {
    // The position error in texture units, plus the float spacing near c; both coordinates
    // may move at once (a query near a texel corner).
    const auto moved = [](float c, int sign) {
      const double step = kPositionError + 2.0 * std::fabs(double(c)) * 0x1p-24;
      return static_cast<float>(double(c) + sign * step);
    };
    for (int ds = -1; ds <= 1; ++ds) {
      for (int dt = -1; dt <= 1; ++dt) {
        if (ds == 0 && dt == 0) continue;
        TextureQuery near = q;
        if (ds != 0) near.s = moved(q.s, ds);
        if (dt != 0) near.t = moved(q.t, dt);
        results.push_back(reference::sample(texture, options, near));
      }
    }
  }
  if (!finite_query(q)) return results;
  if (options.filter == TextureFilter::mip_nearest) {
    for (double sign : {-1.0, 1.0}) {
      SamplerOptions moved = options;
      moved.lod_bias = static_cast<float>(options.lod_bias + sign * kLodError);
      results.push_back(reference::sample(texture, moved, q));
    }
  }
  // The probe count (anisotropic) and the eccentricity clamp (ewa) switch at a length ratio.
  if (options.filter == TextureFilter::anisotropic || options.filter == TextureFilter::ewa) {
    for (double scale : {1.0 - kAnisotropyScale, 1.0 + kAnisotropyScale}) {
      for (int axis = 0; axis < 2; ++axis) {
        TextureQuery moved = q;
        float* d = axis == 0 ? &moved.dsdx : &moved.dsdy;
        d[0] = static_cast<float>(d[0] * scale);
        d[1] = static_cast<float>(d[1] * scale);
        results.push_back(reference::sample(texture, options, moved));
      }
    }
    // The ratio folds at 1: axes within the scale of each other may count as equal (one probe,
    // lambda from Pmax), which no scaled neighbour above reaches; max_anisotropy 1 gives it.
    if (options.filter == TextureFilter::anisotropic) {
      const double w = texture.width(), h = texture.height();
      const double ux = q.dsdx * w, vx = q.dtdx * h, uy = q.dsdy * w, vy = q.dtdy * h;
      const bool exact = options.lod == LodFormula::exact;
      const double px = exact ? std::hypot(ux, vx) : std::max(std::fabs(ux), std::fabs(vx));
      const double py = exact ? std::hypot(uy, vy) : std::max(std::fabs(uy), std::fabs(vy));
      if (std::max(px, py) <= std::min(px, py) * (1.0 + kAnisotropyScale)) {
        SamplerOptions one = options;
        one.max_anisotropy = 1;
        results.push_back(reference::sample(texture, one, q));
      }
    }
    // EWA's clamp applies when |minor| M < |major|; float lengths a few ulps apart may land on
    // the equality, which leaves the ellipse unclamped. Scaling an axis cannot reach that side
    // when M = 1 (any inequality clamps), so near the boundary the reference with M raised,
    // which leaves this ellipse unclamped, is accepted too.
    if (options.filter == TextureFilter::ewa && options.max_anisotropy < kMaxAnisotropyLimit) {
      const double w = texture.width(), h = texture.height();
      const double a = std::hypot(q.dsdx * w, q.dtdx * h), b = std::hypot(q.dsdy * w, q.dtdy * h);
      const double major = std::max(a, b), minor = std::min(a, b);
      const double m = options.max_anisotropy;
      if (std::fabs(minor * m - major) <= kAnisotropyScale * major) {
        SamplerOptions unclamped = options;
        unclamped.max_anisotropy = kMaxAnisotropyLimit;
        results.push_back(reference::sample(texture, unclamped, q));
      }
    }
  }
  return results;
}

double distance_to_reference(const Texture& texture, const SamplerOptions& options,
                             const TextureQuery& query, const Vec4& got) {
  const float values[4] = {got.x, got.y, got.z, got.w};
  double best = std::numeric_limits<double>::infinity();
  for (const reference::Rgba& want : accepted_references(texture, options, query)) {
    double worst = 0;
    for (int k = 0; k < 4; ++k)
      worst = std::max(worst, std::fabs(double(values[k]) - want[k]));
    best = std::min(best, worst);
  }
  return best;
}

}  // namespace edgewise::test
