// Terms the scalar reference sampler's filters share (sample_reference.cpp, ewa_reference.cpp):
// weighted sums of texels, the footprint in level-0 texels, and coordinates reduced by whole
// periods.
#pragma once

#include <cmath>
#include <cstdint>

#include "sample_reference.hpp"

namespace edgewise::reference::sample_terms {

inline void add_scaled(Rgba& sum, const Rgba& value, double weight) {
  for (int c = 0; c < 4; ++c)
    sum[c] += weight * value[c];
}

inline Rgba scaled(const Rgba& value, double factor) {
  Rgba out{};
  add_scaled(out, value, factor);
  return out;
}

// The footprint in level-0 texels per pixel.
struct TexelDerivatives {
  double ux, vx, uy, vy;
};

inline TexelDerivatives texel_derivatives(const Texture& texture, const TextureQuery& q) {
  const double w = texture.width(), h = texture.height();
  return {double{q.dsdx} * w, double{q.dtdx} * h, double{q.dsdy} * w, double{q.dtdy} * h};
}

// Moves the texel-space coordinate x on an axis of n texels by a whole number of texels so that
// it is small, without changing the texel any index floor(x) + d, |d| <= reach, wraps to, nor
// x's fraction. fmod is exact, and the period divides the shift: n for repeat, 2n for mirror.
// For clamp_to_edge every index beyond n + reach reads the border texel, so x only has to stay
// beyond it.
inline double reduce_texel_coordinate(double x, std::int64_t n, WrapMode mode, double reach) {
  switch (mode) {
    case WrapMode::repeat:
      return std::fmod(x, static_cast<double>(n));
    case WrapMode::mirror:
      return std::fmod(x, 2.0 * static_cast<double>(n));
    case WrapMode::clamp_to_edge: {
      const double bound = static_cast<double>(n) + std::ceil(reach);
      const double fraction = x - std::floor(x);  // exact
      if (x > bound) return bound + fraction;
      if (x < -bound) return -bound - 1.0 + fraction;
      return x;
    }
  }
  return x;
}

}  // namespace edgewise::reference::sample_terms
