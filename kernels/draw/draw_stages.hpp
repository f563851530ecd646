// draw()'s stages, each a function of its own, for the project's tools and benchmarks that time
// them apart: draw() is exactly prepare_draw(), then (for a call with work) map_to_screen() and
// shade_screen_mesh(), or, for a binned() call, draw_in_ranges() or draw_indexed_in_ranges(),
// which run the vertex stage in ranges too (docs/design/threads.md).
#pragma once

#include "edgewise/draw.hpp"
#include "../core/kernel_table.hpp"
#include "../core/parallel.hpp"
#include "shading/plane_tiles.hpp"
#include "vertex_stage/screen_mesh.hpp"

namespace edgewise::detail {

// A checked call: its ISA's kernels, the clip rectangle, its threads, and the report so far.
struct DrawCall {
  const KernelTable* kernels = nullptr;
  PixelRect clip;
  // The view the vertex stage maps to, in whose samples clip and set-up work: the target's size,
  // or, for occluders drawn into a reduced buffer (PlaneStore::reduction), that many times it.
  Viewport view;
  DrawReport report;  // isa and triangles filled in
  Workers workers;
  int samples = 1;  // the target's samples per pixel
  // Occluders drawn into depth kept as planes (ShadeBatch::plane_tiles), or null.
  const PlaneStore* plane_store = nullptr;
  bool has_work() const { return !clip.empty() && report.triangles != 0; }
  // Whether the call draws in bins on several threads (else on the calling thread alone, as
  // one kernel call: the direct path, with no binning).
  bool binned() const;
};

// Checks the arguments (draw.hpp says what throws) and chooses the ISA.
DrawCall prepare_draw(const Framebuffer& target, const DrawMesh& mesh, const DrawOptions& options);

// The call's stages after prepare_draw(): draw() is run_draw(prepare_draw(...), ...).
DrawReport run_draw(DrawCall call, Framebuffer& target, const DrawMesh& mesh,
                    const DrawOptions& options);

// The vertex stage (vertex_stage.cpp, through the ISA's kernel): transform, clipping, screen
// mapping and snapping of every triangle, and the culling of those set-up would cull, counted
// into call.report. Given a grid, `bins` receives the bin of each screen triangle (BinOutput).
ScreenMesh map_to_screen(DrawCall& call, const DrawMesh& mesh, const DrawOptions& options,
                         const BinGrid* grid = nullptr,
                         GrowableArray<std::uint32_t>* bins = nullptr);

// The screen mesh through the ISA's shading kernel: setup, coverage, depth test and shading;
// in bins on the call's threads when it is binned().
void shade_screen_mesh(DrawCall& call, Framebuffer& target, const ScreenMesh& screen,
                       const DrawOptions& options);

// What one call of the shading kernel counted (its triangles' outcomes, the fragments and the
// shortcuts taken) put into `report`, whose counts so far are the vertex stage's.
void add_shading_counts(DrawReport& report, const RasterReport& raster, const ShadeCounts& counts);

// The vertex stage and shade_screen_mesh() of a binned() call whose mesh has no indices, with
// the vertex stage itself run on ranges of triangles at once: each range is mapped to a screen
// mesh of its own and binned by one task; then each bin is shaded by one task.
void draw_in_ranges(DrawCall& call, Framebuffer& target, const DrawMesh& mesh,
                    const DrawOptions& options);

// The same for a mesh with indices, whose triangles share vertices: its vertices are mapped in
// ranges into one screen mesh, then its triangles are assembled (clipped, counted) and binned in
// ranges, each range keeping the vertices its clipping makes, which then follow the mesh's in
// range order. Nothing on the calling thread grows with the mesh but the allocations.
void draw_indexed_in_ranges(DrawCall& call, Framebuffer& target, const DrawMesh& mesh,
                            const DrawOptions& options);

}  // namespace edgewise::detail
