// draw(): the vertex stage (transform, clipping, screen mapping, snapping) and the dispatch of
// the screen-space triangles to the chosen ISA's shading kernel.
#include "edgewise/render.hpp"

#include <chrono>
#include <cmath>
#include <stdexcept>
#include <string>
#include <vector>

#include "edgewise/clip.hpp"
#include "framebuffer_access.hpp"
#include "kernel_table.hpp"
#include "shade_batch.hpp"
#include "texture_description.hpp"

namespace edgewise {
namespace {

// Screen-space vertices and triangles, as the shading kernels take them.
struct ScreenMesh {
  std::vector<Vec2> positions;  // snapped to 1/256 px
  std::vector<float> depth;
  std::vector<float> clip_w;
  std::vector<Vec4> colors;
  std::vector<Vec3> normals;
  std::vector<Vec2> uvs;  // textured draws only
  std::vector<std::uint32_t> indices;
};

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
              const detail::KernelTable& kernels)
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

void validate(const DrawMesh& mesh, const DrawOptions& options) {
  const std::size_t n = mesh.positions.size();
  if (!mesh.colors.empty() && mesh.colors.size() != n) {
    throw std::invalid_argument("draw: " + std::to_string(mesh.colors.size()) + " colours for " +
                                std::to_string(n) + " positions");
  }
  if (!mesh.normals.empty() && mesh.normals.size() != n) {
    throw std::invalid_argument("draw: " + std::to_string(mesh.normals.size()) + " normals for " +
                                std::to_string(n) + " positions");
  }
  if (options.shading == Shading::diffuse && mesh.normals.empty()) {
    throw std::invalid_argument("draw: diffuse shading needs normals");
  }
  if (options.texture) {
    if (options.texture->texture == nullptr) {
      throw std::invalid_argument("draw: the texture option holds no texture");
    }
    if (mesh.uvs.size() != n) {
      throw std::invalid_argument("draw: " + std::to_string(mesh.uvs.size()) + " uvs for " +
                                  std::to_string(n) + " positions (a texture needs one each)");
    }
    detail::validate_sampler(*options.texture->texture, options.texture->sampler, "draw");
  }
  const std::size_t corners = mesh.indices.empty() ? n : mesh.indices.size();
  if (corners % 3 != 0) {
    throw std::invalid_argument("draw: " + std::to_string(corners) +
                                " corners is not a multiple of 3");
  }
  if (n > UINT32_MAX / 2) throw std::invalid_argument("draw: too many vertices");
}

Vec3 unit(const Vec3& v) {
  const double length = std::sqrt(static_cast<double>(v.x) * v.x + static_cast<double>(v.y) * v.y +
                                  static_cast<double>(v.z) * v.z);
  if (!(length > 0.0) || !std::isfinite(length)) return {0.0f, 0.0f, 0.0f};  // no direct light
  return {static_cast<float>(v.x / length), static_cast<float>(v.y / length),
          static_cast<float>(v.z / length)};
}

}  // namespace

DrawReport draw(Framebuffer& target, const DrawMesh& mesh, const DrawOptions& options) {
  using Clock = std::chrono::steady_clock;
  validate(mesh, options);
  const Isa isa = resolve_isa(options.isa);
  const PixelRect clip = clip_rect(RasterTarget{target.width(), target.height(), options.scissor});
  DrawReport report;
  report.isa = isa;
  const std::size_t corners = mesh.indices.empty() ? mesh.positions.size() : mesh.indices.size();
  report.triangles = corners / 3;
  if (clip.empty() || report.triangles == 0) return report;

  const auto start = Clock::now();
  ScreenMesh screen;
  screen.positions.reserve(mesh.positions.size());
  screen.depth.reserve(mesh.positions.size());
  screen.clip_w.reserve(mesh.positions.size());
  screen.colors.reserve(mesh.positions.size());
  if (options.shading == Shading::diffuse) screen.normals.reserve(mesh.positions.size());
  if (options.texture) screen.uvs.reserve(mesh.positions.size());
  screen.indices.reserve(3 * report.triangles);
  const detail::KernelTable& kernels = detail::kernel_table(isa);
  VertexStage stage(mesh, options, Viewport{target.width(), target.height()}, kernels);
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
  const auto mapped = Clock::now();

  // The texture flattened for the kernels once per draw.
  std::optional<detail::FlatTexture> flat_texture;
  if (options.texture) flat_texture.emplace(*options.texture->texture);
  detail::ShadeBatch batch{{screen.positions.data(), screen.positions.size(), screen.indices.data(),
                            screen.indices.size() / 3, clip, options.cull, nullptr},
                           screen.depth.data(),
                           screen.clip_w.data(),
                           screen.colors.data(),
                           options.shading == Shading::diffuse ? screen.normals.data() : nullptr,
                           options.shading,
                           options.interpolation,
                           options.perspective,
                           options.depth_test,
                           options.depth_write,
                           unit(options.light_direction),
                           options.ambient,
                           detail::FramebufferAccess::color(target),
                           detail::FramebufferAccess::depth(target),
                           target.tiles_x(),
                           detail::FramebufferAccess::tile_max_depth(target),
                           options.hierarchical_depth};
  if (options.texture) {
    batch.uvs = screen.uvs.data();
    batch.texture = options.texture->texture;
    batch.texture_description = flat_texture ? &flat_texture->description() : nullptr;
    batch.sampler = options.texture->sampler;
    batch.derivatives = options.texture->derivatives;
  }
  RasterReport raster;
  detail::ShadeCounts counts;
  if (!screen.indices.empty()) kernels.shade(batch, raster, counts);
  report.rasterized = raster.triangles;
  report.culled += raster.culled;
  report.errors += raster.errors;
  report.fragments = counts.fragments;
  report.fragments_passed = counts.passed;
  report.tiles_skipped = counts.tiles_skipped;
  report.vertex_seconds = std::chrono::duration<double>(mapped - start).count();
  report.raster_seconds = std::chrono::duration<double>(Clock::now() - mapped).count();
  return report;
}

std::string_view depth_test_name(DepthTest test) {
  switch (test) {
    case DepthTest::less:
      return "less";
    case DepthTest::less_equal:
      return "less_equal";
    case DepthTest::greater:
      return "greater";
    case DepthTest::always:
      return "always";
    case DepthTest::never:
      return "never";
  }
  return "unknown";
}

std::optional<DepthTest> parse_depth_test(std::string_view name) {
  for (DepthTest test : {DepthTest::less, DepthTest::less_equal, DepthTest::greater,
                         DepthTest::always, DepthTest::never}) {
    if (depth_test_name(test) == name) return test;
  }
  return std::nullopt;
}

std::string_view shading_name(Shading shading) {
  switch (shading) {
    case Shading::flat:
      return "flat";
    case Shading::gouraud:
      return "gouraud";
    case Shading::diffuse:
      return "diffuse";
  }
  return "unknown";
}

std::optional<Shading> parse_shading(std::string_view name) {
  for (Shading shading : {Shading::flat, Shading::gouraud, Shading::diffuse}) {
    if (shading_name(shading) == name) return shading;
  }
  return std::nullopt;
}

std::string_view texture_derivatives_name(TextureDerivatives derivatives) {
  switch (derivatives) {
    case TextureDerivatives::quad:
      return "quad";
    case TextureDerivatives::analytic:
      return "analytic";
  }
  return "unknown";
}

std::optional<TextureDerivatives> parse_texture_derivatives(std::string_view name) {
  for (TextureDerivatives d : {TextureDerivatives::quad, TextureDerivatives::analytic}) {
    if (texture_derivatives_name(d) == name) return d;
  }
  return std::nullopt;
}

}  // namespace edgewise
