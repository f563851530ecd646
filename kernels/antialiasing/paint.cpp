// paint_triangles(): 2D triangles in pixel coordinates through draw() (path.hpp).
#include <stdexcept>
#include <string>
#include <vector>

#include "edgewise/path.hpp"

namespace edgewise {

DrawReport paint_triangles(Framebuffer& target, std::span<const Vec2> triangles, const Vec4& color,
                           std::optional<Isa> isa) {
  if (triangles.size() % 3 != 0) {
    throw std::invalid_argument("paint_triangles: " + std::to_string(triangles.size()) +
                                " points is not a multiple of 3");
  }
  // Pixel (x, y) to NDC: the inverse of the viewport mapping (camera.hpp), x right, y down.
  const float sx = 2.0f / static_cast<float>(target.width() > 0 ? target.width() : 1);
  const float sy = 2.0f / static_cast<float>(target.height() > 0 ? target.height() : 1);
  std::vector<Vec3> positions;
  positions.reserve(triangles.size());
  for (const Vec2& p : triangles)
    positions.push_back({p.x * sx - 1.0f, 1.0f - p.y * sy, 0.0f});
  const std::vector<Vec4> colors(triangles.size(), color);
  DrawMesh mesh;
  mesh.positions = positions;
  mesh.colors = colors;
  DrawOptions options;
  options.depth_test = DepthTest::always;
  options.depth_write = false;
  options.shading = Shading::flat;
  options.isa = isa;
  return draw(target, mesh, options);
}

}  // namespace edgewise
