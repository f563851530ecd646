// A view: the exact mapping from screen positions to texture coordinates of a textured plane
// seen through a pinhole camera, in double precision. The sampler's queries and the ground
// truth both come from it, so a filter is scored on exactly the footprint it was given.
//
// Screen conventions (docs/DESIGN.md): origin top-left, y down; pixel (i, j) is the square
// [i, i+1) x [j, j+1), sampled at its centre (i + 0.5, j + 0.5).
#pragma once

#include <array>
#include <cstdint>
#include <vector>

#include "edgewise/sample.hpp"

namespace edgewise::texture_scene {

// A plane under perspective projection maps the screen to texture space projectively:
//   s = (s_row . (x, y, 1)) / (w_row . (x, y, 1)),   t = (t_row . (x, y, 1)) / (w_row . (x, y, 1)).
struct ProjectiveMap {
  std::array<double, 3> s_row;
  std::array<double, 3> t_row;
  std::array<double, 3> w_row;
};

struct TexturePoint {
  double s, t;
};

// Texture-coordinate units per pixel, the sampler's derivatives.
struct ScreenJacobian {
  double dsdx, dtdx, dsdy, dtdy;
};

// A screen rectangle of pixels [x0, x0 + width) x [y0, y0 + height).
struct ScreenRegion {
  std::int32_t x0 = 0, y0 = 0, width = 0, height = 0;
};

class TextureView {
 public:
  // Throws std::invalid_argument for a size outside [1, 32768], a non-finite coefficient, or a
  // denominator w_row . (x, y, 1) that is not positive over the whole closed screen rectangle
  // [0, width] x [0, height] (being linear, it is checked at the four corners): the plane must
  // lie in front of the camera everywhere on screen, so that the mapping and its Jacobian are
  // finite and smooth there.
  TextureView(std::int32_t width, std::int32_t height, const ProjectiveMap& map);

  std::int32_t width() const { return width_; }
  std::int32_t height() const { return height_; }
  ScreenRegion screen() const { return {0, 0, width_, height_}; }
  const ProjectiveMap& map() const { return map_; }

  TexturePoint point(double x, double y) const;
  // The exact partial derivatives of point(x, y): for s = n / w, ds/dx = (n_x w - n w_x) / w^2.
  ScreenJacobian jacobian(double x, double y) const;

  // One query at pixel (i, j)'s centre: point and Jacobian rounded once to float (magnitudes
  // beyond float's range become infinities). Throws std::invalid_argument for a pixel outside
  // the screen.
  TextureQuery query(std::int32_t i, std::int32_t j) const;
  // One query per pixel, row-major, over the whole screen or a region of it (which must lie
  // inside the screen: std::invalid_argument otherwise).
  std::vector<TextureQuery> queries() const { return queries(screen()); }
  std::vector<TextureQuery> queries(const ScreenRegion& region) const;

  // Throws std::invalid_argument unless the region is non-empty and inside the screen.
  void check_region(const ScreenRegion& region) const;

 private:
  std::int32_t width_;
  std::int32_t height_;
  ProjectiveMap map_;
};

}  // namespace edgewise::texture_scene
