// draw()'s vertex stage, triangle-parallel (docs/DESIGN.md, "The vertex stage"). Two passes:
// - every mesh vertex, a batch at a time, through ScreenMapping: screen vertex i is mesh vertex
//   i, so no vertex is looked up or remapped, and each vertex's class is kept as a code;
// - every triangle in the mesh's order, a block of one triangle per lane at a time: when the
//   codes of a block's corners say that all its triangles are inside every clipping plane (the
//   common case), its indices are stored as they are; otherwise its triangles are taken one by
//   one, in order, by the shared scalar add_triangle(), which clips where it must.
// The results equal the reference's (kernels/reference/vertex_stage_reference.cpp) bit for bit.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>

#include <xsimd/xsimd.hpp>

#include "../src/vertex_stage.hpp"
#include "screen_mapping-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// Every mesh vertex into `out` (sized by start_screen_mesh()) and its code into codes.
template <class Arch>
void map_vertices(const detail::VertexStageCall& call, detail::ScreenMesh& out,
                  std::int32_t* codes) {
  const ScreenMapping<Arch> mapping(call.transform, call.viewport, call.planes);
  constexpr std::size_t kLanes = ScreenMapping<Arch>::kLanes;
  const std::size_t count = call.mesh.positions.size();
  const Vec3* in = call.mesh.positions.data();
  // The arrays' addresses as locals: stores through them could otherwise change `out`.
  Vec2* const positions = out.positions.data();
  float* const depth = out.depth.data();
  float* const clip_w = out.clip_w.data();
  std::size_t i = 0;
  for (; i + kLanes <= count; i += kLanes)
    mapping.map(in + i, positions + i, depth + i, clip_w + i, codes + i);
  if (i == count) return;
  // The last few vertices through the same code, from and to buffers of a whole batch.
  const std::size_t rest = count - i;
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

// Triangles [first, first + lanes) of an unindexed mesh, stored whole when every corner is
// inside; false (nothing done) otherwise. Their corners are the 3 lanes vertices from 3 first.
template <class Arch>
[[gnu::always_inline]] inline bool pass_unindexed_block(const std::int32_t* codes,
                                                        std::size_t first,
                                                        detail::ScreenMesh& out) {
  using Ints = xsimd::batch<std::int32_t, Arch>;
  constexpr std::size_t kLanes = Ints::size;
  const std::int32_t* corners = codes + 3 * first;
  const Ints any = Ints::load_unaligned(corners) | Ints::load_unaligned(corners + kLanes) |
                   Ints::load_unaligned(corners + 2 * kLanes);
  if (xsimd::any(any != Ints(0))) return false;
  static constexpr std::int32_t kLaneIndex[8] = {0, 1, 2, 3, 4, 5, 6, 7};
  static_assert(kLanes <= 8);
  const Ints index = Ints::load_unaligned(kLaneIndex) + Ints(static_cast<std::int32_t>(3 * first));
  auto* at = reinterpret_cast<std::int32_t*>(out.indices.extend(3 * kLanes));
  index.store_unaligned(at);
  (index + Ints(static_cast<std::int32_t>(kLanes))).store_unaligned(at + kLanes);
  (index + Ints(static_cast<std::int32_t>(2 * kLanes))).store_unaligned(at + 2 * kLanes);
  return true;
}

// The same for an indexed mesh: its 3 lanes indices from 3 first are stored as they are when all
// of them are in range and every corner is inside.
template <class Arch>
[[gnu::always_inline]] inline bool pass_indexed_block(const detail::VertexStageCall& call,
                                                      const std::int32_t* codes, std::size_t first,
                                                      detail::ScreenMesh& out) {
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
  if (xsimd::any(any != Ints(0))) return false;
  auto* at = reinterpret_cast<std::int32_t*>(out.indices.extend(3 * kLanes));
  a.store_unaligned(at);
  b.store_unaligned(at + kLanes);
  c.store_unaligned(at + 2 * kLanes);
  return true;
}

// Every triangle, in the mesh's order, into out.indices (and through clipping).
template <class Arch>
void assemble_triangles(const detail::VertexStageCall& call, const std::int32_t* codes,
                        detail::ScreenMesh& out, DrawReport& report) {
  constexpr std::size_t kLanes = xsimd::batch<std::int32_t, Arch>::size;
  std::size_t t = 0;
  const auto blocks = [&](auto pass_block) {
    for (; t + kLanes <= call.triangles; t += kLanes) {
      if (pass_block(t)) continue;
      for (std::size_t k = t; k < t + kLanes; ++k)
        add_triangle_by_codes(call, codes, k, out, report);
    }
  };
  if (call.mesh.indices.empty()) {
    blocks([&](std::size_t first) { return pass_unindexed_block<Arch>(codes, first, out); });
  } else {
    blocks([&](std::size_t first) { return pass_indexed_block<Arch>(call, codes, first, out); });
  }
  for (; t < call.triangles; ++t)
    add_triangle_by_codes(call, codes, t, out, report);
}

template <class Arch>
void map_mesh_to_screen(const detail::VertexStageCall& call, detail::ScreenMesh& out,
                        DrawReport& report) {
  detail::start_screen_mesh(call, out);
  detail::GrowableArray<std::int32_t> codes(call.mesh.positions.size());
  map_vertices<Arch>(call, out, codes.data());
  assemble_triangles<Arch>(call, codes.data(), out, report);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
