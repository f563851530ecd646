// The drawing kernels (draw.hpp's draw()): the vertex transform, the vertex stage and the
// shading of screen-space triangles, compiled once per ISA.
#include "../src/isa_build.hpp"

#include "../generic/shade-inl.hpp"
#include "../generic/triangle_batch-inl.hpp"
#include "../generic/vertex_stage-inl.hpp"
#include "../generic/vertex_transform-inl.hpp"
#include "../src/isa_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {
namespace {

template <InterpolationMethod Method>
void shade_with(const detail::ShadeBatch& batch, RasterReport& report,
                detail::ShadeCounts& counts) {
  if (batch.coverage.samples.size() > 1) {
    MultisampleShadingVisitor<Arch, Method> visitor(batch);
    run_batch(batch.coverage, visitor, report);
    visitor.add_counts(counts);
    return;
  }
  ShadingVisitor<Arch, Method> visitor(batch);
  run_batch(batch.coverage, visitor, report);
  visitor.add_counts(counts);
}

}  // namespace

void shade(const detail::ShadeBatch& batch, RasterReport& report, detail::ShadeCounts& counts) {
  switch (batch.method) {
    case InterpolationMethod::nearest_vertex:
      return shade_with<InterpolationMethod::nearest_vertex>(batch, report, counts);
    case InterpolationMethod::inverse_distance:
      return shade_with<InterpolationMethod::inverse_distance>(batch, report, counts);
    case InterpolationMethod::subtriangle_areas:
      return shade_with<InterpolationMethod::subtriangle_areas>(batch, report, counts);
    case InterpolationMethod::edge_functions:
      return shade_with<InterpolationMethod::edge_functions>(batch, report, counts);
    case InterpolationMethod::scanline:
      return shade_with<InterpolationMethod::scanline>(batch, report, counts);
    case InterpolationMethod::plane_equations:
      return shade_with<InterpolationMethod::plane_equations>(batch, report, counts);
  }
}

void transform_vertices(const Mat4& m, const Vec3* in, std::size_t count, Vec4* out) {
  transform_vertex_array<Arch>(m, in, count, out);
}

void map_to_screen(const detail::VertexStageCall& call, detail::ScreenMesh& out,
                   DrawReport& report) {
  map_mesh_to_screen<Arch>(call, out, report);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
