#include "texture_scene/view_mesh.hpp"

#include <algorithm>

namespace edgewise::texture_scene {

ViewMesh view_mesh(const TextureView& view) {
  const double width = view.width(), height = view.height();
  const double corners[4][2] = {{0, 0}, {width, 0}, {0, height}, {width, height}};
  double w[4];
  for (int c = 0; c < 4; ++c) {
    const auto& row = view.map().w_row;
    w[c] = 1.0 / (row[0] * corners[c][0] + row[1] * corners[c][1] + row[2]);
  }
  const double largest = *std::max_element(w, w + 4);  // only ratios matter: scale to <= 1
  ViewMesh mesh;
  for (int c : {0, 1, 2, 1, 3, 2}) {  // clockwise on screen, as any winding is drawn
    const double x = corners[c][0], y = corners[c][1], clip_w = w[c] / largest;
    const double ndc_x = 2.0 * x / width - 1.0, ndc_y = 1.0 - 2.0 * y / height;
    mesh.positions.push_back({static_cast<float>(ndc_x * clip_w),
                              static_cast<float>(ndc_y * clip_w), static_cast<float>(clip_w)});
    const TexturePoint p = view.point(x, y);
    mesh.uvs.push_back({static_cast<float>(p.s), static_cast<float>(p.t)});
  }
  mesh.transform = {{{1, 0, 0, 0}, {0, 1, 0, 0}, {0, 0, 0.5f, 0}, {0, 0, 1, 0}}};
  return mesh;
}

}  // namespace edgewise::texture_scene
