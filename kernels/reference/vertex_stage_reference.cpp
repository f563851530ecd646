#include "vertex_stage_reference.hpp"

#include <cstddef>
#include <cstdint>
#include <vector>

namespace edgewise::reference {
namespace {

// What clip_triangle() would conclude from the vertices' classes alone (clip.hpp, ClipClass).
detail::TriangleClass triangle_class(const ClipClass& a, const ClipClass& b, const ClipClass& c) {
  if (a.checked && b.checked && c.checked) {
    if ((a.outside_frustum & b.outside_frustum & c.outside_frustum) != 0) {
      return detail::TriangleClass::outside;
    }
    if (a.inside && b.inside && c.inside) return detail::TriangleClass::inside;
  }
  return detail::TriangleClass::undecided;
}

}  // namespace

void map_to_screen(const detail::VertexStageCall& call, detail::ScreenMesh& out,
                   DrawReport& report) {
  detail::start_screen_mesh(call, out);
  const std::size_t vertex_count = call.mesh.positions.size();
  std::vector<ClipClass> classes(vertex_count);
  for (std::size_t i = 0; i < vertex_count; ++i) {
    const Vec4 clip = transform(call.transform, call.mesh.positions[i]);
    classes[i] = classify_clip_vertex(clip, call.planes);
    const ScreenVertex s = to_screen(clip, call.viewport);
    out.positions[i] = {detail::snap(s.x), detail::snap(s.y)};
    out.depth[i] = s.z;
    out.clip_w[i] = clip.w;
  }
  for (std::size_t t = 0; t < call.triangles; ++t) {
    std::uint32_t corner[3];
    bool in_range = true;
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t c = 3 * t + i;
      const std::size_t v = call.mesh.indices.empty() ? c : call.mesh.indices[c];
      in_range = in_range && v < vertex_count;
      corner[i] = static_cast<std::uint32_t>(v);
    }
    const detail::TriangleClass triangle =
        in_range ? triangle_class(classes[corner[0]], classes[corner[1]], classes[corner[2]])
                 : detail::TriangleClass::bad_index;
    detail::add_triangle(call, corner, triangle, out, report);
  }
}

}  // namespace edgewise::reference
