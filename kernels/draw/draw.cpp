// draw(): its arguments checked and its ISA chosen, then its two stages (draw_stages.hpp): the
// vertex stage (vertex_stage.cpp) and the chosen ISA's shading kernel, on the calling thread or
// in bins on several (binned_draw.cpp).
#include <cmath>
#include <optional>
#include <stdexcept>
#include <string>

#include "binned_draw.hpp"
#include "draw_stages.hpp"
#include "../core/framebuffer_access.hpp"
#include "shading/shade_batch.hpp"
#include "shading/shading_budget.hpp"
#include "../texture/texture_description.hpp"

namespace edgewise {
namespace detail {
namespace {

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
  if (options.error_budget && !(*options.error_budget >= 0.0f)) {
    throw std::invalid_argument("draw: the error budget must be a number >= 0");
  }
  // Checked whatever the shading, as the budget is: a value out of its domain is a mistake
  // that would otherwise show only as black or unlit pixels once the shading changes.
  if (!(options.ambient >= 0.0f && options.ambient <= 1.0f)) {
    throw std::invalid_argument("draw: the ambient term must be a number in [0, 1], not " +
                                std::to_string(options.ambient));
  }
  const Vec3& light = options.light_direction;
  if (!std::isfinite(light.x) || !std::isfinite(light.y) || !std::isfinite(light.z)) {
    throw std::invalid_argument("draw: the light direction must be finite");
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

DrawCall prepare_draw(const Framebuffer& target, const DrawMesh& mesh, const DrawOptions& options) {
  validate(mesh, options);
  DrawCall call;
  call.report.isa = resolve_isa(options.isa);
  call.kernels = &kernel_table(call.report.isa);
  call.clip = detail::checked_clip_rect(
      RasterTarget{target.width(), target.height(), options.scissor}, "draw");
  call.workers = resolve_workers(options.threads, options.executor, "draw");
  call.samples = target.samples();
  call.view = {target.width(), target.height()};
  const std::size_t corners = mesh.indices.empty() ? mesh.positions.size() : mesh.indices.size();
  call.report.triangles = corners / 3;
  return call;
}

ShadeBatch make_shade_batch(Framebuffer& target, const ScreenMesh& screen,
                            const DrawOptions& options, const PixelRect& clip,
                            const TextureDescription* texture) {
  ShadeBatch batch{{screen.positions.data(), screen.positions.size(), screen.indices.data(),
                    screen.indices.size() / 3, clip, options.cull, nullptr,
                    FramebufferAccess::sample_pattern(target)},
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
                   FramebufferAccess::color(target),
                   FramebufferAccess::depth(target),
                   target.tiles_x(),
                   FramebufferAccess::tile_max_depth(target),
                   options.hierarchical_depth};
  if (options.texture) {
    batch.uvs = screen.uvs.data();
    batch.texture = options.texture->texture;
    batch.texture_description = texture;
    batch.sampler = options.texture->sampler;
    batch.sampler.precision = effective_precision(*options.texture->texture, batch.sampler);
    batch.derivatives = options.texture->derivatives;
  }
  // Multisampled pixels are shaded at centres that may lie outside the triangle, where the
  // budget's bounds do not hold: drawn exactly.
  if (batch.sample_count() == 1 && options.interpolation == InterpolationMethod::plane_equations)
    batch.budget_codes = budget_codes(options.error_budget);
  return batch;
}

void shade_screen_mesh(DrawCall& call, Framebuffer& target, const ScreenMesh& screen,
                       const DrawOptions& options) {
  if (screen.indices.empty()) return;
  // The texture flattened for the kernels once per draw.
  std::optional<FlatTexture> flat_texture;
  if (options.texture) flat_texture.emplace(*options.texture->texture);
  const TextureDescription* texture = flat_texture ? &flat_texture->description() : nullptr;
  if (call.binned()) {
    shade_in_bins(call, target, screen, options, texture);
    return;
  }
  ShadeBatch batch = make_shade_batch(target, screen, options, call.clip, texture);
  if (call.plane_store != nullptr) {
    batch.plane_tiles =
        call.plane_store->view(call.plane_store->reserve(batch.coverage.triangle_count));
  }
  RasterReport raster;
  ShadeCounts counts;
  call.kernels->shade(batch, raster, counts);
  add_shading_counts(call.report, raster, counts);
}

void add_shading_counts(DrawReport& report, const RasterReport& raster, const ShadeCounts& counts) {
  report.rasterized += raster.drawn;
  report.culled += raster.culled;
  report.errors += raster.errors;
  report.fragments = counts.fragments;
  report.fragments_passed = counts.passed;
  report.statistics.tiles_skipped = counts.tiles_skipped;
  report.statistics.fragments_constant = counts.constant;
  report.statistics.fragments_one_texel = counts.one_texel;
}

}  // namespace detail

namespace detail {

DrawReport run_draw(DrawCall call, Framebuffer& target, const DrawMesh& mesh,
                    const DrawOptions& options) {
  if (!call.has_work()) return call.report;
  if (call.binned()) {
    call.workers.call_up();
    if (mesh.indices.empty()) {
      draw_in_ranges(call, target, mesh, options);
    } else {
      draw_indexed_in_ranges(call, target, mesh, options);
    }
    return call.report;
  }
  const ScreenMesh screen = map_to_screen(call, mesh, options);
  shade_screen_mesh(call, target, screen, options);
  return call.report;
}

}  // namespace detail

DrawReport draw(Framebuffer& target, const DrawMesh& mesh, const DrawOptions& options) {
  return detail::run_draw(detail::prepare_draw(target, mesh, options), target, mesh, options);
}

}  // namespace edgewise
