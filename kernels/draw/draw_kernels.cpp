// The drawing kernels (draw.hpp's draw()): the vertex transform, the vertex stage and the
// shading of screen-space triangles, compiled once per ISA.
#include "../core/isa_build.hpp"

#include "vertex_stage/culled_triangles-inl.hpp"
#include "shading/shade_multisample-inl.hpp"
#include "shading/shade_occluder-inl.hpp"
#include "../coverage/triangle_batch-inl.hpp"
#include "vertex_stage/vertex_stage-inl.hpp"
#include "vertex_stage/vertex_transform-inl.hpp"
#include "../core/isa_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// One visitor for every interpolation method (method_interpolator-inl.hpp).
void shade(const detail::ShadeBatch& batch, RasterReport& report, detail::ShadeCounts& counts) {
  if (batch.plane_tiles.tiles != nullptr) {
    OccluderVisitor<Arch> visitor(batch);
    run_batch(batch.coverage, visitor, report);
    visitor.add_counts(counts);
    return;
  }
  if (batch.coverage.samples.size() > 1) {
    MultisampleShadingVisitor<Arch> visitor(batch);
    run_batch(batch.coverage, visitor, report);
    visitor.add_counts(counts);
    return;
  }
  ShadingVisitor<Arch> visitor(batch);
  run_batch(batch.coverage, visitor, report);
  visitor.add_counts(counts);
}

detail::DroppedTriangles drop_culled_triangles(const Vec2* vertices, std::size_t vertex_count,
                                               std::uint32_t* indices, std::size_t triangles,
                                               CullMode cull, const detail::SampleWindow& window,
                                               const detail::BinOutput& output) {
  return drop_culled_triangle_list<Arch>(vertices, vertex_count, indices, triangles, cull, window,
                                         output);
}

void transform_vertices(const Mat4& m, const Vec3* in, std::size_t count, Vec4* out) {
  transform_vertex_array<Arch>(m, in, count, out);
}

void map_vertices(const detail::VertexStageCall& call, std::size_t first, std::size_t last,
                  detail::ScreenMesh& out, std::int32_t* codes) {
  map_vertex_array<Arch>(call, first, last, out, codes);
}

void assemble_triangles(const detail::VertexStageCall& call, const std::int32_t* codes,
                        std::size_t first, std::size_t last, detail::ScreenMesh& out,
                        DrawReport& report) {
  assemble_triangle_range<Arch>(call, codes, first, last, out, report);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
