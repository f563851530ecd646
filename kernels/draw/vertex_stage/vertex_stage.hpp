// draw()'s vertex stage, the parts every ISA and the reference share (docs/design/vertex-stage.md,
// "The vertex stage"): the call's inputs, the start of the screen mesh, the snapping of one
// coordinate, and the scalar handling of one triangle, clipping included. Each ISA maps the mesh's
// vertices its own way (kernels/draw/vertex_stage/vertex_stage-inl.hpp; the reference's plain loops
// in kernels/draw/vertex_stage/vertex_stage_reference.cpp) and hands here every triangle it does
// not pass through as it is.
#pragma once

#include <cstddef>
#include <cstdint>

#include "clip.hpp"
#include "edgewise/camera.hpp"
#include "edgewise/draw.hpp"
#include "../../core/kernel_table.hpp"
#include "screen_mesh.hpp"

namespace edgewise::detail {

// One draw() call's vertex stage: what map_to_screen() (draw_stages.hpp) gives the kernel.
struct VertexStageCall {
  DrawMesh mesh;
  Mat4 transform;
  Viewport viewport;
  GuardBandPlanes planes;  // guard_band_planes(viewport)
  bool diffuse;            // the screen mesh carries normals
  bool textured;           // the screen mesh carries texture coordinates
  std::size_t triangles;   // in the mesh
};

// Rounds a screen coordinate to the 1/256 px grid, ties to even, as the rasterizer does
// (docs/design/rasterization.md, "Coordinates and snapping"). Values beyond 2^43 in magnitude and
// non-finite ones pass through unchanged. Every vertex the shading kernels see has been snapped so.
float snap(float v);

// The vertex stage of a draw() call in `view` (DrawCall::view), with its guard band.
VertexStageCall vertex_stage_call(const Viewport& view, const DrawMesh& mesh,
                                  const DrawOptions& options, std::size_t triangles);

// Sizes `out` for the mesh's vertices (positions, depth, w and, for a mesh without colours, the
// colours, left for map_vertex_range() to write) and borrows the mesh's attributes.
void start_screen_mesh(const VertexStageCall& call, ScreenMesh& out);

// Vertices [first, last) through the kernels' map_vertices (kernel_table.hpp): mapped into
// `out` (sized by start_screen_mesh()) and their codes into codes[first, last); for a mesh
// without colours, their colour opaque white. Ranges of vertices may run at once.
void map_vertex_range(const KernelTable& kernels, const VertexStageCall& call, std::size_t first,
                      std::size_t last, ScreenMesh& out, std::int32_t* codes);

// The whole vertex stage on the calling thread: every vertex, then every triangle, into `out`
// (empty on entry), counted into `report`.
void run_vertex_stage(const KernelTable& kernels, const VertexStageCall& call, ScreenMesh& out,
                      DrawReport& report);

// The triangles of `screen` that set-up would cull (zero area, or facing away under `cull`),
// or draw with no sample of `window` in their box, dropped from its indices by the kernels'
// drop_culled_triangles: primitive assembly's culling, before binning and set-up. The culled
// are counted into report.culled, the others into report.rasterized (drawn, covering nothing).
// `positions` are those the indices name (a range's screen mesh may index the whole mesh's).
// With a grid in `output`, output.bins (room for every triangle of `screen`) receives the kept
// triangles' bins.
void drop_culled_triangles(const KernelTable& kernels, const ScreenMesh& positions,
                           ScreenMesh& screen, CullMode cull, const SampleWindow& window,
                           DrawReport& report, const BinOutput& output = {});

// The samples of a draw on `call`'s clip rectangle: up to half a pixel from the centre when
// multisampled (a pattern's samples lie inside their pixel).
SampleWindow sample_window(const PixelRect& clip, int samples);

// What the classes of a triangle's vertices (classify_clip_vertex()) say about it, before
// clip_triangle() is asked.
enum class TriangleClass : std::uint8_t {
  inside,     // every vertex inside every clipping plane: the triangle as it is
  outside,    // every vertex outside one plane of the view frustum
  undecided,  // clip_triangle() decides
  bad_index,  // a corner past the end of the vertex array: an error, nothing drawn
};

// Adds mesh triangle `corner` to the screen mesh, counting what happens to it in the report as
// draw() does: an inside one by its three vertices, an outside or bad one only counted, an
// undecided one through clip_triangle(), whose new vertices (attributes blended from the
// mesh's) are appended to `out`, numbered from out.first_vertex_index.
void add_triangle(const VertexStageCall& call, const std::uint32_t (&corner)[3],
                  TriangleClass triangle_class, ScreenMesh& out, DrawReport& report);

}  // namespace edgewise::detail
