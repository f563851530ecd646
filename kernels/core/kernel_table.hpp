// The per-ISA kernel table behind the public entry points: one table per compiled ISA, the
// scalar reference included, each holding every kernel. A table is defined in its ISA's own
// objects (kernel_table_kernels.cpp, once per ISA; reference_kernel_table.cpp).
#pragma once

#include <cstddef>
#include <cstdint>
#include <span>
#include <type_traits>

#include "edgewise/camera.hpp"
#include "edgewise/coverage.hpp"
#include "edgewise/occlusion.hpp"
#include "edgewise/pixel_area.hpp"
#include "../coverage/bin_grid.hpp"
#include "isa_list.hpp"
#include "../antialiasing/resolve_call.hpp"
#include "../texture/sample_kernels.hpp"
#include "../coverage/triangle_batch.hpp"
#include "../occlusion/occlusion_call.hpp"

namespace edgewise {
struct DrawReport;
struct GuardBandPlanes;
}  // namespace edgewise

namespace edgewise::detail {

struct BoxSamples;
struct PlaneTiles;
struct ShadeBatch;
struct ShadeCounts;
struct VertexStageCall;
struct ScreenMesh;

// Every kernel, once: its name and its function type, in the table's order. The table's members,
// each ISA's declarations (isa_kernels.hpp) and its table (kernel_table_kernels.cpp) are made from
// this list, and so are the reference's (reference_kernels.hpp, reference_kernel_table.cpp);
// designated initializers make the compiler check every table against the members.
#define EDGEWISE_FOR_EACH_KERNEL(X)                                                                \
  /* Coverage (coverage.hpp): tiles to a sink, or covered pixels counted. */                       \
  X(rasterize, void(const detail::TriangleBatch& batch, CoverageSink& sink, RasterReport& report)) \
  X(count_coverage,                                                                                \
    void(const detail::TriangleBatch& batch, RasterReport& report, std::uint64_t& pixels))         \
  /* Drawing (draw.hpp): the vertex transform, out[i] = transform(m, in[i]) (camera.hpp) bit for   \
     bit. */                                                                                       \
  X(transform_vertices, void(const Mat4& m, const Vec3* in, std::size_t count, Vec4* out))         \
  /* The vertex stage (vertex_stage.hpp), in two passes that ranges may run apart. Vertices        \
     [first, last) transformed, classified against the clipping planes (a code each, which only    \
     this table's assemble_triangles reads), mapped to the screen and snapped into `out` (sized    \
     by start_screen_mesh()); then triangles [first, last), every vertex's code known, passed on,  \
     clipped or counted out, in the mesh's order, appended to `out`. */                            \
  X(map_vertices, void(const detail::VertexStageCall& call, std::size_t first, std::size_t last,   \
                       detail::ScreenMesh& out, std::int32_t* codes))                              \
  X(assemble_triangles,                                                                            \
    void(const detail::VertexStageCall& call, const std::int32_t* codes, std::size_t first,        \
         std::size_t last, detail::ScreenMesh& out, DrawReport& report))                           \
  /* Drops from `indices` (three per triangle into `vertices`) the triangles set-up would cull     \
     (zero area after snapping, or facing away under `cull`) and those it would draw with no       \
     sample of `window` in their box; the rest keep their order. A triangle with a bad index or a  \
     vertex outside the guard band stays, for set-up to report. With a grid in `output`, also      \
     each kept triangle's bin (BinOutput). */                                                      \
  X(drop_culled_triangles,                                                                         \
    detail::DroppedTriangles(const Vec2* vertices, std::size_t vertex_count,                       \
                             std::uint32_t* indices, std::size_t triangles, CullMode cull,         \
                             const detail::SampleWindow& window, const detail::BinOutput& output)) \
  /* The screen-space triangles shaded into the framebuffer. */                                    \
  X(shade,                                                                                         \
    void(const detail::ShadeBatch& batch, RasterReport& report, detail::ShadeCounts& counts))      \
  /* Resolving (resolve.hpp): the box filter at factor 1, output rows [8 first, 8 last); tent and  \
     Mitchell, output rows [first, last). */                                                       \
  X(resolve_box, void(const detail::ResolveCall& call, std::int32_t first_tile_row,                \
                      std::int32_t last_tile_row))                                                 \
  X(resolve_taps,                                                                                  \
    void(const detail::ResolveCall& call, std::int32_t first_row, std::int32_t last_row))          \
  /* Sampling (sample.hpp): queries and results as records, or as one array per field. */          \
  X(sample, std::remove_pointer_t<detail::SampleKernel>)                                           \
  X(sample_fields, std::remove_pointer_t<detail::SampleFieldsKernel>)                              \
  /* Exact-area coverage (pixel_area.hpp): each triangle's pixel areas to a sink. */               \
  X(rasterize_areas,                                                                               \
    void(const detail::TriangleBatch& batch, AreaSink& sink, RasterReport& report))                \
  /* Occlusion (occlusion.hpp): rectangles to the ranges of samples (or blocks of `reduction`      \
     samples) they hold, as rect_samples() and sample_blocks() make them, returning `count`, or    \
     the index of the first rectangle rect_samples() rejects; rectangles of samples against the    \
     depths, and each tile's largest depth for tiles [first, last). */                             \
  X(rect_sample_ranges,                                                                            \
    std::size_t(const OcclusionRect* rects, std::size_t count, std::int32_t width,                 \
                std::int32_t height, std::int32_t reduction, detail::SampleRect* out))             \
  /* Boxes to the samples their faces may cover under `to_clip`, as box_samples() finds them,      \
     returning `count`, or the index of the first box box_samples() rejects. */                    \
  X(box_sample_ranges,                                                                             \
    std::size_t(const OcclusionBox* boxes, std::size_t count, const Mat4& to_clip,                 \
                const Viewport& viewport, const GuardBandPlanes& planes, detail::BoxSamples* out)) \
  X(test_sample_rects, void(const detail::OcclusionDepth& depth, const detail::SampleRect* rects,  \
                            std::size_t count, Visibility* out))                                   \
  X(occlusion_tile_maxima,                                                                         \
    void(const float* tiles, std::size_t first, std::size_t last, float* out))                     \
  /* Depth kept as planes (plane_tiles.hpp): the values of tiles [first, last) whose planes the    \
     depth tiles do not hold yet, written there. */                                                \
  X(resolve_plane_tiles, void(const detail::PlaneTiles& planes, float* depth_tiles,                \
                              std::int32_t tiles_x, std::size_t first, std::size_t last))

struct KernelTable {
  Isa isa;  // the ISA the table's objects were compiled for
#define EDGEWISE_KERNEL_MEMBER(name, type) std::add_pointer_t<type> name;
  EDGEWISE_FOR_EACH_KERNEL(EDGEWISE_KERNEL_MEMBER)
#undef EDGEWISE_KERNEL_MEMBER
};

// The table of a compiled ISA (isa_supported() is the caller's to check).
const KernelTable& kernel_table(Isa isa);

}  // namespace edgewise::detail

// Each ISA's table, defined in that ISA's namespace.
namespace edgewise::isa_reference {
const detail::KernelTable& kernel_table();
}
#define EDGEWISE_DECLARE_KERNEL_TABLE(name, arch, cpu_check) \
  namespace edgewise::isa_##name {                           \
    const detail::KernelTable& kernel_table();               \
  }
EDGEWISE_FOR_EACH_SIMD_ISA(EDGEWISE_DECLARE_KERNEL_TABLE)
#undef EDGEWISE_DECLARE_KERNEL_TABLE
