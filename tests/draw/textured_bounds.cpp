// The per-pixel bound of textured draws (textured_bounds.hpp).
#include "draw/textured_bounds.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace edgewise::test {
namespace {

constexpr double kInfinity = std::numeric_limits<double>::infinity();

struct Interval {
  double lo, hi;
};

// Every value x y with x in a and y in b; everything where an end is NaN (infinity times 0).
Interval product(Interval a, Interval b) {
  const double p[4] = {a.lo * b.lo, a.lo * b.hi, a.hi * b.lo, a.hi * b.hi};
  Interval r{p[0], p[0]};
  for (double v : p) {
    if (std::isnan(v)) return {-kInfinity, kInfinity};
    r.lo = std::min(r.lo, v);
    r.hi = std::max(r.hi, v);
  }
  return r;
}

double clamp_code(double v) {
  return std::clamp(v, 0.0, 255.0);
}

}  // namespace

ShadedRange shaded_range(const VertexAttributes& triangle, Shading shading, float ambient) {
  ShadedRange range;
  // The light is ambient + (1 - ambient) lambert with lambert in [0, |l|], and the light
  // direction l is a unit vector rounded to float: |l| <= 1 + 2^-24 (2^-23 covers the double
  // division too).
  const double a = ambient, full = a + (1.0 - a) * (1.0 + 0x1p-23);
  const Interval light{std::min(a, full), std::max(a, full)};
  for (int k = 0; k < 4; ++k) {
    Interval hull{kInfinity, -kInfinity};
    for (int i = 0; i < 3; ++i) {
      const double c = (&triangle.colors[i].x)[k];
      hull = {std::min(hull.lo, c), std::max(hull.hi, c)};
    }
    if (shading == Shading::diffuse && k < 3) hull = product(hull, light);
    const double margin = 0x1p-40 * std::max(std::abs(hull.lo), std::abs(hull.hi));
    range.lo[k] = hull.lo - margin;
    range.hi[k] = hull.hi + margin;
  }
  return range;
}

TexturedPixelCheck::TexturedPixelCheck(const Texture& texture, const SamplerOptions& sampler)
    : texture_(texture), sampler_(sampler), extremes_(texture_extremes(texture)) {}

double TexturedPixelCheck::texel_bound(const TextureQuery& query) const {
  return sample_bound(texture_, extremes_, sampler_, query);
}

std::vector<CodeRanges> TexturedPixelCheck::allowed(const TextureQuery& query,
                                                    const std::uint8_t untextured[4],
                                                    const ShadedRange& shaded,
                                                    double colour_error) const {
  const double b = texel_bound(query);
  // C_r from the untextured code, unbounded on a clamped side, and from the vertex colours.
  Interval colour[4];
  for (int k = 0; k < 4; ++k) {
    const double r0 = untextured[k];
    const double lo = r0 == 0.0 ? -kInfinity : (r0 - 0.5) / 255.0;
    const double hi = r0 == 255.0 ? kInfinity : (r0 + 0.5) / 255.0;
    colour[k] = {std::max(lo, shaded.lo[k]) - colour_error,
                 std::min(hi, shaded.hi[k]) + colour_error};
  }
  std::vector<CodeRanges> ranges;
  for (const reference::Rgba& texel : accepted_references(texture_, sampler_, query)) {
    CodeRanges r;
    for (int k = 0; k < 4; ++k) {
      const Interval p =
          product({255.0 * colour[k].lo, 255.0 * colour[k].hi}, {texel[k] - b, texel[k] + b});
      r.lo[k] = clamp_code(p.lo - 0x1p-23 * std::abs(p.lo)) - 0.5;
      r.hi[k] = clamp_code(p.hi + 0x1p-23 * std::abs(p.hi)) + 0.5;
    }
    ranges.push_back(r);
  }
  return ranges;
}

double TexturedPixelCheck::excess(std::span<const CodeRanges> allowed, const std::uint8_t fast[4]) {
  double best = kInfinity;
  for (const CodeRanges& r : allowed) {
    double worst = -kInfinity;
    for (int k = 0; k < 4; ++k) {
      const double f = fast[k];
      worst = std::max({worst, r.lo[k] - f, f - r.hi[k]});
    }
    best = std::min(best, worst);
  }
  return best;
}

}  // namespace edgewise::test
