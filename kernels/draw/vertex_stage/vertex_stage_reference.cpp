// The vertex stage of draw() in plain scalar code: the reference's kernels (kernel_table.hpp) and
// the oracle of every ISA's (vertex_stage-inl.hpp).
#include <cstddef>
#include <cstdint>

#include "../../core/reference_kernels.hpp"
#include "edgewise/camera.hpp"
#include "vertex_stage.hpp"

namespace edgewise::reference {
namespace {

// A vertex's ClipClass as a code: bit 0 checked, bit 1 inside, the frustum planes from bit 2.
std::int32_t code_of(const ClipClass& c) {
  return (c.checked ? 1 : 0) | (c.inside ? 2 : 0) |
         static_cast<std::int32_t>(c.outside_frustum) << 2;
}

ClipClass class_of(std::int32_t code) {
  return {static_cast<std::uint16_t>(code >> 2), (code & 2) != 0, (code & 1) != 0};
}

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

// Each vertex of [first, last) through transform(), classify_clip_vertex(), to_screen() and
// snap(), one at a time; its class kept as a code of the reference's own.
void map_vertices(const detail::VertexStageCall& call, std::size_t first, std::size_t last,
                  detail::ScreenMesh& out, std::int32_t* codes) {
  for (std::size_t i = first; i < last; ++i) {
    const Vec4 clip = transform(call.transform, call.mesh.positions[i]);
    codes[i] = code_of(classify_clip_vertex(clip, call.planes));
    const ScreenVertex s = to_screen(clip, call.viewport);
    out.positions[i] = {detail::snap(s.x), detail::snap(s.y)};
    out.depth[i] = s.z;
    out.clip_w[i] = clip.w;
  }
}

// Each triangle of [first, last): its class read from its vertices' classes, then added by the
// shared add_triangle().
void assemble_triangles(const detail::VertexStageCall& call, const std::int32_t* codes,
                        std::size_t first, std::size_t last, detail::ScreenMesh& out,
                        DrawReport& report) {
  const std::size_t vertex_count = call.mesh.positions.size();
  for (std::size_t t = first; t < last; ++t) {
    std::uint32_t corner[3];
    bool in_range = true;
    for (std::size_t i = 0; i < 3; ++i) {
      const std::size_t c = 3 * t + i;
      const std::size_t v = call.mesh.indices.empty() ? c : call.mesh.indices[c];
      in_range = in_range && v < vertex_count;
      corner[i] = static_cast<std::uint32_t>(v);
    }
    const detail::TriangleClass triangle =
        in_range ? triangle_class(class_of(codes[corner[0]]), class_of(codes[corner[1]]),
                                  class_of(codes[corner[2]]))
                 : detail::TriangleClass::bad_index;
    detail::add_triangle(call, corner, triangle, out, report);
  }
}

void transform_vertices(const Mat4& m, const Vec3* in, std::size_t count, Vec4* out) {
  for (std::size_t i = 0; i < count; ++i)
    out[i] = transform(m, in[i]);
}

}  // namespace edgewise::reference
