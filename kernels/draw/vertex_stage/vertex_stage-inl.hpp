// draw()'s vertex stage, triangle-parallel (docs/design/vertex-stage.md, "The vertex stage"). Two
// passes, each over a range (so that ranges may run on several threads):
// - mesh vertices, a batch at a time, through ScreenMapping: screen vertex i is mesh vertex i,
//   so no vertex is looked up or remapped, and each vertex's class is kept as a code;
// - triangles in the mesh's order, a block of one triangle per lane at a time: when the codes of
//   a block's corners say that all its triangles are inside every clipping plane (the common
//   case), its indices are stored as they are (a run of such blocks at once); otherwise its
//   triangles are taken one by one, in order, by the shared scalar add_triangle(), which clips
//   where it must.
// The results equal the reference's (kernels/draw/vertex_stage/vertex_stage_reference.cpp) bit for
// bit.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "vertex_stage.hpp"
#include "screen_mapping-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// Mesh vertices [first, last) into `out` (sized by start_screen_mesh()) and their codes into
// codes.
template <class Arch>
void map_vertex_array(const detail::VertexStageCall& call, std::size_t first, std::size_t last,
                      detail::ScreenMesh& out, std::int32_t* codes) {
  const ScreenMapping<Arch> mapping(call.transform, call.viewport, call.planes);
  constexpr std::size_t kLanes = ScreenMapping<Arch>::kLanes;
  const Vec3* in = call.mesh.positions.data();
  // The arrays' addresses as locals: the compiler cannot tell that the batches stored through
  // them leave `out` unchanged, and would load them again for every batch.
  Vec2* const positions = out.positions.data();
  float* const depth = out.depth.data();
  float* const clip_w = out.clip_w.data();
  std::size_t i = first;
  for (; i + kLanes <= last; i += kLanes)
    mapping.map(in + i, positions + i, depth + i, clip_w + i, codes + i);
  if (i == last) return;
  // The last few vertices through the same code, from and to buffers of a whole batch.
  const std::size_t rest = last - i;
  Vec3 tail_in[kLanes] = {};
  Vec2 tail_positions[kLanes];
  float tail_depth[kLanes], tail_clip_w[kLanes];
  std::int32_t tail_codes[kLanes];
  std::copy_n(in + i, rest, tail_in);
  mapping.map(tail_in, tail_positions, tail_depth, tail_clip_w, tail_codes);
  std::copy_n(tail_positions, rest, positions + i);
  std::copy_n(tail_depth, rest, depth + i);
  std::copy_n(tail_clip_w, rest, clip_w + i);
  std::copy_n(tail_codes, rest, codes + i);
}

// Triangle t through add_triangle(), its class read from its corners' codes.
inline void add_triangle_by_codes(const detail::VertexStageCall& call, const std::int32_t* codes,
                                  std::size_t t, detail::ScreenMesh& out, DrawReport& report) {
  const std::size_t vertex_count = call.mesh.positions.size();
  const bool indexed = !call.mesh.indices.empty();
  std::uint32_t corner[3];
  bool in_range = true;
  for (std::size_t i = 0; i < 3; ++i) {
    const std::size_t c = 3 * t + i;
    const std::size_t v = indexed ? call.mesh.indices[c] : c;
    in_range = in_range && v < vertex_count;
    corner[i] = static_cast<std::uint32_t>(v);
  }
  detail::TriangleClass triangle = detail::TriangleClass::bad_index;
  if (in_range) {
    const std::int32_t a = codes[corner[0]], b = codes[corner[1]], c = codes[corner[2]];
    triangle = (a & b & c & kFrustumBits) != 0 ? detail::TriangleClass::outside
               : (a | b | c) == 0              ? detail::TriangleClass::inside
                                               : detail::TriangleClass::undecided;
  }
  detail::add_triangle(call, corner, triangle, out, report);
}

// Whether the block of triangles [first, first + lanes) of an unindexed mesh passes whole: its
// corners, the 3 lanes vertices from 3 first, all inside.
template <class Arch>
[[gnu::always_inline]] inline bool unindexed_block_passes(const std::int32_t* codes,
                                                          std::size_t first) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
  constexpr std::size_t kLanes = Ints::size;
  const std::int32_t* corners = codes + 3 * first;
  const Ints any = Ints::load_unaligned(corners) | Ints::load_unaligned(corners + kLanes) |
                   Ints::load_unaligned(corners + 2 * kLanes);
  return !xsimd::any(any != Ints(0));
}

// The same for an indexed mesh: its 3 lanes indices from 3 first all in range, and the corners
// they name all inside.
template <class Arch>
[[gnu::always_inline]] inline bool indexed_block_passes(const detail::VertexStageCall& call,
                                                        const std::int32_t* codes,
                                                        std::size_t first) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
  constexpr std::size_t kLanes = Ints::size;
  // Indices as int32: the vertex count is below 2^31 (draw() checks it), so an index is in range
  // exactly when it is, as a signed value, in [0, vertex count).
  const auto* indices = reinterpret_cast<const std::int32_t*>(call.mesh.indices.data() + 3 * first);
  const Ints a = Ints::load_unaligned(indices), b = Ints::load_unaligned(indices + kLanes),
             c = Ints::load_unaligned(indices + 2 * kLanes);
  const auto vertex_count = static_cast<std::int32_t>(call.mesh.positions.size());
  const Ints lowest = xsimd::min(xsimd::min(a, b), c), highest = xsimd::max(xsimd::max(a, b), c);
  if (xsimd::any((lowest < Ints(0)) | (highest >= Ints(vertex_count)))) return false;
  const Ints any = Ints::gather(codes, a) | Ints::gather(codes, b) | Ints::gather(codes, c);
  return !xsimd::any(any != Ints(0));
}

// The indices of triangles [first, end), which all pass as they are: for an unindexed mesh
// 3 first, 3 first + 1, ..., for an indexed one its own.
template <class Arch>
void store_passing_triangles(const detail::VertexStageCall& call, std::size_t first,
                             std::size_t end, detail::ScreenMesh& out) {
  std::uint32_t* at = out.indices.extend(3 * (end - first));
  if (!call.mesh.indices.empty()) {
    std::copy(call.mesh.indices.data() + 3 * first, call.mesh.indices.data() + 3 * end, at);
    return;
  }
  using Ints = xsimd::batch<std::int32_t, Arch>;
  constexpr std::size_t kLanes = Ints::size;
  static constexpr std::int32_t kLaneIndex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  static_assert(kLanes <= 8);
  Ints index = Ints::load_unaligned(kLaneIndex) + Ints(static_cast<std::int32_t>(3 * first));
  const Ints step(static_cast<std::int32_t>(kLanes));
  auto* corner = reinterpret_cast<std::int32_t*>(at);
  for (std::size_t k = 0; k < 3 * (end - first); k += 3 * kLanes) {  // a block at a time
    for (std::size_t batch = 0; batch < 3; ++batch, index += step)
      index.store_unaligned(corner + k + batch * kLanes);
  }
}

// Triangles [first, last), in the mesh's order, into out.indices (and through clipping). A run
// of blocks that pass whole is found first and stored at once.
template <class Arch>
void assemble_triangle_range(const detail::VertexStageCall& call, const std::int32_t* codes,
                             std::size_t first, std::size_t last, detail::ScreenMesh& out,
                             DrawReport& report) {
  constexpr std::size_t kLanes = xsimd::batch<std::int32_t, Arch>::size;
  const bool indexed = !call.mesh.indices.empty();
  const auto run_end = [&](std::size_t start, auto block_passes) {
    std::size_t end = start;
    while (end + kLanes <= last && block_passes(end))
      end += kLanes;
    return end;
  };
  std::size_t t = first;
  while (t + kLanes <= last) {
    const std::size_t end =
        indexed
            ? run_end(t, [&](std::size_t b) { return indexed_block_passes<Arch>(call, codes, b); })
            : run_end(t, [&](std::size_t b) { return unindexed_block_passes<Arch>(codes, b); });
    if (end != t) {
      store_passing_triangles<Arch>(call, t, end, out);
      t = end;
      continue;
    }
    for (const std::size_t block_end = t + kLanes; t < block_end; ++t)
      add_triangle_by_codes(call, codes, t, out, report);
  }
  for (; t < last; ++t)
    add_triangle_by_codes(call, codes, t, out, report);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
