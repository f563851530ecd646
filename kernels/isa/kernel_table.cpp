// The ISA's kernel table: every kernel of its objects (isa_kernels.hpp), compiled once per ISA.
#include "../src/isa_build.hpp"

#include "../src/isa_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

const detail::KernelTable& kernel_table() {
  static constexpr detail::KernelTable table{
      EDGEWISE_ISA_ENUM,      &rasterize,    &count_coverage,
      &transform_vertices,    &map_vertices, &assemble_triangles,
      &drop_culled_triangles, &shade,        &resolve_box,
      &resolve_taps,          &sample,       &sample_fields,
      &rasterize_areas};
  return table;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
