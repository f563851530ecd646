// The vertex stage of draw() in plain scalar code: the reference's kernel-table entries and the
// oracle of every ISA's kernel (kernels/draw/vertex_stage/vertex_stage-inl.hpp).
#pragma once

#include <cstddef>
#include <cstdint>

#include "vertex_stage.hpp"

namespace edgewise::reference {

// Each vertex of [first, last) through transform(), classify_clip_vertex(), to_screen() and
// snap(), one at a time; its class kept as a code of the reference's own.
void map_vertices(const detail::VertexStageCall& call, std::size_t first, std::size_t last,
                  detail::ScreenMesh& out, std::int32_t* codes);

// Each triangle of [first, last): its class read from its vertices' classes, then added by the
// shared add_triangle().
void assemble_triangles(const detail::VertexStageCall& call, const std::int32_t* codes,
                        std::size_t first, std::size_t last, detail::ScreenMesh& out,
                        DrawReport& report);

}  // namespace edgewise::reference
