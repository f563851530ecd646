// The vertex stage of draw() in plain scalar code: the reference's kernel-table entry and the
// oracle of every ISA's kernel (kernels/generic/vertex_stage-inl.hpp).
#pragma once

#include "../src/vertex_stage.hpp"

namespace edgewise::reference {

// Each vertex through transform(), classify_clip_vertex(), to_screen() and snap(), one at a time;
// each triangle's class read from its vertices' classes, then added by the shared add_triangle().
void map_to_screen(const detail::VertexStageCall& call, detail::ScreenMesh& out,
                   DrawReport& report);

}  // namespace edgewise::reference
