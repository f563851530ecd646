// draw()'s vertex stage: the call handed to its ISA's kernel (kernel_table.hpp, map_to_screen),
// and the parts every kernel shares (vertex_stage.hpp).
#include "vertex_stage.hpp"

#include <algorithm>
#include <cmath>
#include <cstdint>
#include <span>

#include "../draw_stages.hpp"

namespace edgewise::detail {
namespace {

template <class T>
T blend(const T& a, const T& b, const T& c, float b0, float b1, float b2);
template <>
Vec2 blend(const Vec2& a, const Vec2& b, const Vec2& c, float b0, float b1, float b2) {
  return {b0 * a.x + b1 * b.x + b2 * c.x, b0 * a.y + b1 * b.y + b2 * c.y};
}
template <>
Vec4 blend(const Vec4& a, const Vec4& b, const Vec4& c, float b0, float b1, float b2) {
  return {b0 * a.x + b1 * b.x + b2 * c.x, b0 * a.y + b1 * b.y + b2 * c.y,
          b0 * a.z + b1 * b.z + b2 * c.z, b0 * a.w + b1 * b.w + b2 * c.w};
}
template <>
Vec3 blend(const Vec3& a, const Vec3& b, const Vec3& c, float b0, float b1, float b2) {
  return {b0 * a.x + b1 * b.x + b2 * c.x, b0 * a.y + b1 * b.y + b2 * c.y,
          b0 * a.z + b1 * b.z + b2 * c.z};
}

template <class T>
T blend(std::span<const T> values, const std::uint32_t (&corner)[3], const ClipVertex& v) {
  return blend(values[corner[0]], values[corner[1]], values[corner[2]], v.b0, v.b1, v.b2);
}

constexpr Vec4 kOpaqueWhite{1.0f, 1.0f, 1.0f, 1.0f};

// Appends a vertex made by clipping triangle `corner`, its attributes blended from the corners'
// (the mesh's own vertices).
void append_clipped(const VertexStageCall& call, const ClipVertex& v,
                    const std::uint32_t (&corner)[3], ScreenMesh& out) {
  const ScreenVertex s = to_screen(v.position, call.viewport);
  out.positions.push_back({snap(s.x), snap(s.y)});
  out.depth.push_back(s.z);
  out.clip_w.push_back(v.position.w);
  // A mesh without colours is opaque white, blended like any other colour.
  out.colors.push_back(call.mesh.colors.empty()
                           ? blend(kOpaqueWhite, kOpaqueWhite, kOpaqueWhite, v.b0, v.b1, v.b2)
                           : blend(call.mesh.colors, corner, v));
  if (call.diffuse) out.normals.push_back(blend(call.mesh.normals, corner, v));
  if (call.textured) out.uvs.push_back(blend(call.mesh.uvs, corner, v));
}

void push_triangle(ScreenMesh& out, std::uint32_t a, std::uint32_t b, std::uint32_t c) {
  std::uint32_t* at = out.indices.extend(3);
  at[0] = a;
  at[1] = b;
  at[2] = c;
}

void clip(const VertexStageCall& call, const std::uint32_t (&corner)[3], ScreenMesh& out,
          DrawReport& report) {
  // The corners in clip space again: transform() is every kernel's transform, bit for bit.
  Vec4 p[3];
  for (int i = 0; i < 3; ++i)
    p[i] = transform(call.transform, call.mesh.positions[corner[i]]);
  const ClippedPolygon polygon = clip_triangle(p[0], p[1], p[2], call.planes);
  switch (polygon.status) {
    case ClipStatus::inside:
      push_triangle(out, corner[0], corner[1], corner[2]);
      return;
    case ClipStatus::clipped: {
      ++report.clipped;
      const auto first = static_cast<std::uint32_t>(out.first_vertex_index + out.positions.size());
      for (int k = 0; k < polygon.count; ++k)
        append_clipped(call, polygon.vertices[k], corner, out);
      for (int k = 0; k < polygon.triangle_count(); ++k)
        push_triangle(out, first, first + k + 1, first + k + 2);
      report.clip_triangles += static_cast<std::uint64_t>(polygon.triangle_count());
      return;
    }
    case ClipStatus::outside:
      ++report.outside;
      return;
    case ClipStatus::culled_degenerate:
      ++report.culled;
      return;
    case ClipStatus::error_non_finite:
    case ClipStatus::error_out_of_range:
      ++report.errors;
      return;
  }
}

}  // namespace

// Adding and subtracting 1.5 * 2^52 rounds a double below 2^51 in magnitude to an integer in the
// current (nearest-even) mode without a library call; larger values, infinities and NaN pass
// through unchanged or stay non-finite, and the rasterizer reports them. Scaling by 256 and
// dividing by it are exact, so values from 2^43 on come back unchanged.
float snap(float v) {
  constexpr double kRound = 0x1.8p52;
  const double scaled = static_cast<double>(v) * 256.0;
  const double rounded = std::fabs(scaled) < 0x1p51 ? (scaled + kRound) - kRound : scaled;
  return static_cast<float>(rounded / 256.0);
}

VertexStageCall vertex_stage_call(const Viewport& view, const DrawMesh& mesh,
                                  const DrawOptions& options, std::size_t triangles) {
  return {mesh,
          options.transform,
          view,
          guard_band_planes(view),
          options.shading == Shading::diffuse,
          options.texture.has_value(),
          triangles};
}

void start_screen_mesh(const VertexStageCall& call, ScreenMesh& out) {
  const std::size_t n = call.mesh.positions.size();
  out.positions.extend(n);
  out.depth.extend(n);
  out.clip_w.extend(n);
  if (call.mesh.colors.empty()) {
    out.colors.own(n);
  } else {
    out.colors.borrow(call.mesh.colors);
  }
  if (call.diffuse) out.normals.borrow(call.mesh.normals);
  if (call.textured) out.uvs.borrow(call.mesh.uvs);
}

void map_vertex_range(const KernelTable& kernels, const VertexStageCall& call, std::size_t first,
                      std::size_t last, ScreenMesh& out, std::int32_t* codes) {
  kernels.map_vertices(call, first, last, out, codes);
  if (call.mesh.colors.empty())
    std::fill(out.colors.owned_data() + first, out.colors.owned_data() + last, kOpaqueWhite);
}

void run_vertex_stage(const KernelTable& kernels, const VertexStageCall& call, ScreenMesh& out,
                      DrawReport& report) {
  const std::size_t n = call.mesh.positions.size();
  start_screen_mesh(call, out);
  GrowableArray<std::int32_t> codes(n);
  map_vertex_range(kernels, call, 0, n, out, codes.data());
  out.indices.reserve(3 * call.triangles);
  kernels.assemble_triangles(call, codes.data(), 0, call.triangles, out, report);
}

void add_triangle(const VertexStageCall& call, const std::uint32_t (&corner)[3],
                  TriangleClass triangle_class, ScreenMesh& out, DrawReport& report) {
  switch (triangle_class) {
    case TriangleClass::inside:
      push_triangle(out, corner[0], corner[1], corner[2]);
      return;
    case TriangleClass::outside:
      ++report.outside;
      return;
    case TriangleClass::undecided:
      clip(call, corner, out, report);
      return;
    case TriangleClass::bad_index:
      ++report.errors;
      return;
  }
}

void drop_culled_triangles(const KernelTable& kernels, const ScreenMesh& positions,
                           ScreenMesh& screen, CullMode cull, const SampleWindow& window,
                           DrawReport& report, const BinOutput& output) {
  const DroppedTriangles dropped = kernels.drop_culled_triangles(
      positions.positions.data(), positions.positions.size(), screen.indices.data(),
      screen.indices.size() / 3, cull, window, output);
  screen.indices.truncate(3 * dropped.kept);
  report.culled += dropped.culled;
  report.rasterized += dropped.unseen;
}

SampleWindow sample_window(const PixelRect& clip, int samples) {
  return {clip, samples > 1 ? 128 : 0};
}

ScreenMesh map_to_screen(DrawCall& call, const DrawMesh& mesh, const DrawOptions& options,
                         const BinGrid* grid, GrowableArray<std::uint32_t>* bins) {
  ScreenMesh screen;
  run_vertex_stage(*call.kernels,
                   vertex_stage_call(call.view, mesh, options, call.report.triangles), screen,
                   call.report);
  BinOutput output;
  if (grid != nullptr) output = {grid, bins->extend(screen.indices.size() / 3)};
  drop_culled_triangles(*call.kernels, screen, screen, options.cull,
                        sample_window(call.clip, call.samples), call.report, output);
  return screen;
}

}  // namespace edgewise::detail
