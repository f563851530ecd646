// draw()'s stages, each a function of its own, for the project's tools and benchmarks that time
// them apart: draw() is exactly prepare_draw(), then (for a call with work) map_to_screen() and
// shade_screen_mesh().
#pragma once

#include "edgewise/draw.hpp"
#include "kernel_table.hpp"
#include "screen_mesh.hpp"

namespace edgewise::detail {

// A checked call: its ISA's kernels, the clip rectangle, and the report so far.
struct DrawCall {
  const KernelTable* kernels = nullptr;
  PixelRect clip;
  DrawReport report;  // isa and triangles filled in
  bool has_work() const { return !clip.empty() && report.triangles != 0; }
};

// Checks the arguments (draw.hpp says what throws) and chooses the ISA.
DrawCall prepare_draw(const Framebuffer& target, const DrawMesh& mesh, const DrawOptions& options);

// The vertex stage (vertex_stage.cpp, through the ISA's kernel): transform, clipping, screen
// mapping and snapping of every triangle, counted into call.report.
ScreenMesh map_to_screen(DrawCall& call, const Framebuffer& target, const DrawMesh& mesh,
                         const DrawOptions& options);

// The screen mesh through the ISA's shading kernel: setup, coverage, depth test and shading.
void shade_screen_mesh(DrawCall& call, Framebuffer& target, const ScreenMesh& screen,
                       const DrawOptions& options);

}  // namespace edgewise::detail
