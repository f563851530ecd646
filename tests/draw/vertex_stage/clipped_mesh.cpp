#include "clipped_mesh.hpp"

namespace edgewise::test {

ClippedMesh clip_mesh(std::span<const Vec4> vertices, std::span<const std::uint32_t> indices,
                      const Viewport& viewport) {
  const GuardBandPlanes planes = guard_band_planes(viewport);
  ClippedMesh mesh;
  for (std::size_t t = 0; t + 2 < indices.size(); t += 3) {
    const ClippedPolygon polygon = clip_triangle(vertices[indices[t]], vertices[indices[t + 1]],
                                                 vertices[indices[t + 2]], planes);
    for (int k = 0; k < polygon.triangle_count(); ++k) {
      for (int corner : {0, k + 1, k + 2}) {
        const ScreenVertex v = to_screen(polygon.vertices[corner].position, viewport);
        mesh.screen.push_back(v);
        mesh.positions.push_back({v.x, v.y});
      }
      mesh.source.push_back(static_cast<std::uint32_t>(t / 3));
    }
    mesh.polygons.push_back(polygon);
  }
  return mesh;
}

}  // namespace edgewise::test
