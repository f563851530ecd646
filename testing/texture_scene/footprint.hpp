// The shape of a pixel's footprint in level-0 texels, from a view's Jacobian: how anisotropic
// and how large it is, to describe a view's range (and to choose views that exercise filters).
#pragma once

#include <cstdint>

#include "texture_scene/texture_view.hpp"

namespace edgewise::texture_scene {

struct FootprintShape {
  // The singular values of the Jacobian in texels, J = [[ux, uy], [vx, vy]] with ux = dsdx W,
  // vx = dtdx H, uy = dsdy W, vy = dtdy H: the axis lengths of the ellipse that is the image of
  // the pixel's inscribed circle (diameter 1), major >= minor >= 0.
  double major_texels;
  double minor_texels;
  // major / minor: the true eccentricity (+inf when minor is 0).
  double anisotropy;
  // Pmax / Pmin of the GPU-style anisotropic filter (P = the lengths of the two screen axes'
  // images, hypot(ux, vx) and hypot(uy, vy)): at most `anisotropy`, lower when the axes are
  // not perpendicular.
  double axis_ratio;
  // log2 of the exact level-of-detail rho = max(hypot(ux, vx), hypot(uy, vy)), no bias.
  double lambda;
};

FootprintShape footprint_shape(const ScreenJacobian& jacobian, std::int32_t texture_width,
                               std::int32_t texture_height);

}  // namespace edgewise::texture_scene
