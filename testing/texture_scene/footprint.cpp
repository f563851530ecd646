#include "texture_scene/footprint.hpp"

#include <algorithm>
#include <cmath>
#include <limits>

namespace edgewise::texture_scene {

FootprintShape footprint_shape(const ScreenJacobian& jacobian, std::int32_t texture_width,
                               std::int32_t texture_height) {
  const double ux = jacobian.dsdx * texture_width, vx = jacobian.dtdx * texture_height;
  const double uy = jacobian.dsdy * texture_width, vy = jacobian.dtdy * texture_height;
  // Singular values of a 2x2 matrix: s1^2 + s2^2 = the squared Frobenius norm, s1 s2 = |det|.
  const double frobenius2 = ux * ux + uy * uy + vx * vx + vy * vy;
  const double det = std::abs(ux * vy - uy * vx);
  const double spread = std::sqrt(std::max(0.0, frobenius2 * frobenius2 - 4.0 * det * det));
  const double major = std::sqrt((frobenius2 + spread) / 2.0);
  // From the product, not the difference, which would cancel for thin footprints.
  const double minor = major > 0.0 ? det / major : 0.0;
  const double px = std::hypot(ux, vx), py = std::hypot(uy, vy);
  const double infinity = std::numeric_limits<double>::infinity();
  return {major, minor, minor > 0.0 ? major / minor : infinity,
          std::min(px, py) > 0.0 ? std::max(px, py) / std::min(px, py) : infinity,
          std::log2(std::max(px, py))};
}

}  // namespace edgewise::texture_scene
