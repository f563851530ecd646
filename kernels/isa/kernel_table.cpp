// The ISA's kernel table: every kernel of its objects (isa_kernels.hpp), compiled once per ISA.
#include "../src/isa_build.hpp"

#include "../src/isa_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

const detail::KernelTable& kernel_table() {
  // Designated: the compiler checks each kernel against its member's name, type and order.
  static constexpr detail::KernelTable table{.isa = EDGEWISE_ISA_ENUM,
                                             .rasterize = &rasterize,
                                             .count_coverage = &count_coverage,
                                             .transform_vertices = &transform_vertices,
                                             .map_vertices = &map_vertices,
                                             .assemble_triangles = &assemble_triangles,
                                             .drop_culled_triangles = &drop_culled_triangles,
                                             .shade = &shade,
                                             .resolve_box = &resolve_box,
                                             .resolve_taps = &resolve_taps,
                                             .sample = &sample,
                                             .sample_fields = &sample_fields,
                                             .rasterize_areas = &rasterize_areas};
  return table;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
