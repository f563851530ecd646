// draw()'s vertex stage: vertices transformed by the ISA's kernel, triangles classified against
// the frustum and the guard band, clipped where they must be, mapped to the screen and snapped.
#include <cmath>
#include <cstdint>
#include <vector>

#include "draw_stages.hpp"
#include "clip.hpp"

namespace edgewise::detail {
namespace {

// Rounds to the 1/256 px grid, ties to even, as the rasterizer does: the attributes' setup then
// sees exactly the positions that coverage uses. Adding and subtracting 1.5 * 2^52 rounds a
// double below 2^51 in magnitude to an integer in the current (nearest-even) mode without a
// library call; larger values, infinities and NaN pass through unchanged or stay non-finite,
// and the rasterizer reports them.
float snap(float v) {
  constexpr double kRound = 0x1.8p52;
  const double scaled = static_cast<double>(v) * 256.0;
  const double rounded = std::fabs(scaled) < 0x1p51 ? (scaled + kRound) - kRound : scaled;
  return static_cast<float>(rounded / 256.0);
}

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

class VertexStage {
 public:
  VertexStage(const DrawMesh& mesh, const DrawOptions& options, const Viewport& viewport,
              const KernelTable& kernels)
      : mesh_(mesh),
        viewport_(viewport),
        planes_(guard_band_planes(viewport)),
        diffuse_(options.shading == Shading::diffuse),
        textured_(options.texture.has_value()) {
    clip_.resize(mesh.positions.size());
    kernels.transform_vertices(options.transform, mesh.positions.data(), mesh.positions.size(),
                               clip_.data());
    class_.reserve(mesh.positions.size());
    for (const Vec4& p : clip_)
      class_.push_back(classify_clip_vertex(p, planes_));
    screen_index_.assign(mesh.positions.size(), kUnmapped);
  }

  void add_triangle(const std::uint32_t corner[3], DrawReport& report, ScreenMesh& out) {
    // What clip_triangle() would conclude, decided from the vertices' classes where it can be.
    const ClipClass& a = class_[corner[0]];
    const ClipClass& b = class_[corner[1]];
    const ClipClass& c = class_[corner[2]];
    if (a.checked && b.checked && c.checked) {
      if ((a.outside_frustum & b.outside_frustum & c.outside_frustum) != 0) {
        ++report.outside;
        return;
      }
      if (a.inside && b.inside && c.inside) {
        for (int i = 0; i < 3; ++i)
          out.indices.push_back(mapped(corner[i], out));
        return;
      }
    }
    const ClippedPolygon polygon =
        clip_triangle(clip_[corner[0]], clip_[corner[1]], clip_[corner[2]], planes_);
    switch (polygon.status) {
      case ClipStatus::inside:
        for (int i = 0; i < 3; ++i)
          out.indices.push_back(mapped(corner[i], out));
        return;
      case ClipStatus::clipped: {
        ++report.clipped;
        const std::uint32_t first = static_cast<std::uint32_t>(out.positions.size());
        for (int k = 0; k < polygon.count; ++k)
          append(polygon.vertices[k], corner, out);
        for (int k = 0; k < polygon.triangle_count(); ++k) {
          out.indices.insert(out.indices.end(), {first, first + k + 1, first + k + 2});
        }
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

 private:
  static constexpr std::uint32_t kUnmapped = UINT32_MAX;

  // The screen vertex of an original vertex (mapped once, shared by its unclipped triangles).
  std::uint32_t mapped(std::uint32_t vertex, ScreenMesh& out) {
    if (screen_index_[vertex] == kUnmapped) {
      screen_index_[vertex] = static_cast<std::uint32_t>(out.positions.size());
      push(clip_[vertex], color(vertex), normal(vertex), uv(vertex), out);
    }
    return screen_index_[vertex];
  }

  void append(const ClipVertex& v, const std::uint32_t corner[3], ScreenMesh& out) {
    push(v.position, blend(color(corner[0]), color(corner[1]), color(corner[2]), v.b0, v.b1, v.b2),
         blend(normal(corner[0]), normal(corner[1]), normal(corner[2]), v.b0, v.b1, v.b2),
         blend(uv(corner[0]), uv(corner[1]), uv(corner[2]), v.b0, v.b1, v.b2), out);
  }

  void push(const Vec4& clip, const Vec4& color, const Vec3& normal, const Vec2& uv,
            ScreenMesh& out) const {
    const ScreenVertex s = to_screen(clip, viewport_);
    out.positions.push_back({snap(s.x), snap(s.y)});
    out.depth.push_back(s.z);
    out.clip_w.push_back(clip.w);
    out.colors.push_back(color);
    if (diffuse_) out.normals.push_back(normal);
    if (textured_) out.uvs.push_back(uv);
  }

  Vec4 color(std::uint32_t v) const {
    return mesh_.colors.empty() ? Vec4{1.0f, 1.0f, 1.0f, 1.0f} : mesh_.colors[v];
  }
  Vec3 normal(std::uint32_t v) const { return diffuse_ ? mesh_.normals[v] : Vec3{0, 0, 0}; }
  Vec2 uv(std::uint32_t v) const { return textured_ ? mesh_.uvs[v] : Vec2{0, 0}; }

  const DrawMesh& mesh_;
  Viewport viewport_;
  GuardBandPlanes planes_;
  bool diffuse_;
  bool textured_;
  std::vector<Vec4> clip_;
  std::vector<ClipClass> class_;  // classify_clip_vertex() per vertex
  std::vector<std::uint32_t> screen_index_;
};

}  // namespace

ScreenMesh map_to_screen(DrawCall& call, const Framebuffer& target, const DrawMesh& mesh,
                         const DrawOptions& options) {
  DrawReport& report = call.report;
  ScreenMesh screen;
  screen.positions.reserve(mesh.positions.size());
  screen.depth.reserve(mesh.positions.size());
  screen.clip_w.reserve(mesh.positions.size());
  screen.colors.reserve(mesh.positions.size());
  if (options.shading == Shading::diffuse) screen.normals.reserve(mesh.positions.size());
  if (options.texture) screen.uvs.reserve(mesh.positions.size());
  screen.indices.reserve(3 * report.triangles);
  VertexStage stage(mesh, options, Viewport{target.width(), target.height()}, *call.kernels);
  for (std::size_t t = 0; t < report.triangles; ++t) {
    std::uint32_t corner[3];
    bool in_range = true;
    for (int i = 0; i < 3; ++i) {
      const std::size_t c = 3 * t + static_cast<std::size_t>(i);
      const std::size_t v = mesh.indices.empty() ? c : mesh.indices[c];
      in_range = in_range && v < mesh.positions.size();
      corner[i] = static_cast<std::uint32_t>(v);
    }
    if (!in_range) {
      ++report.errors;
      continue;
    }
    stage.add_triangle(corner, report, screen);
  }
  return screen;
}

}  // namespace edgewise::detail
