// Public raster entry points: argument checks, then the chosen ISA's kernels.
#include "edgewise/coverage.hpp"

#include <algorithm>
#include <stdexcept>
#include <string>

#include "kernel_table.hpp"

namespace edgewise {
namespace {

detail::TriangleBatch make_batch(std::span<const Vec2> vertices,
                                 std::span<const std::uint32_t> indices, const RasterTarget& target,
                                 const RasterOptions& options) {
  const std::size_t corners = indices.empty() ? vertices.size() : indices.size();
  if (corners % 3 != 0) {
    throw std::invalid_argument(std::string(indices.empty() ? "vertex" : "index") + " count " +
                                std::to_string(corners) + " is not a multiple of 3");
  }
  const std::size_t triangles = corners / 3;
  if (!options.statuses.empty() && options.statuses.size() != triangles) {
    throw std::invalid_argument("statuses has " + std::to_string(options.statuses.size()) +
                                " entries for " + std::to_string(triangles) + " triangles");
  }
  if (static_cast<int>(options.cull) > static_cast<int>(CullMode::counter_clockwise)) {
    throw std::invalid_argument("unknown cull mode");
  }
  return {vertices.data(),
          vertices.size(),
          indices.empty() ? nullptr : indices.data(),
          triangles,
          clip_rect(target),
          options.cull,
          options.statuses.empty() ? nullptr : options.statuses.data()};
}

const detail::KernelTable& chosen_kernels(const RasterOptions& options) {
  return detail::kernel_table(resolve_isa(options.isa));
}

}  // namespace

std::string_view describe(TriangleStatus status) {
  switch (status) {
    case TriangleStatus::drawn:
      return "drawn";
    case TriangleStatus::culled_zero_area:
      return "culled: zero area after snapping to 1/256 pixel";
    case TriangleStatus::culled_winding:
      return "culled: winding removed by the cull mode";
    case TriangleStatus::error_non_finite:
      return "error: a vertex coordinate is NaN or infinite";
    case TriangleStatus::error_outside_guard_band:
      return "error: a vertex lies outside the guard band [-32768, 32768) pixels";
    case TriangleStatus::error_bad_index:
      return "error: an index is past the end of the vertex array";
  }
  return "unknown status";
}

PixelRect clip_rect(const RasterTarget& target) {
  if (target.width < 0 || target.width > kMaxTargetSize || target.height < 0 ||
      target.height > kMaxTargetSize) {
    throw std::invalid_argument("target " + std::to_string(target.width) + "x" +
                                std::to_string(target.height) + " is outside 0.." +
                                std::to_string(kMaxTargetSize) + " pixels per side");
  }
  PixelRect clip{0, 0, target.width, target.height};
  if (target.scissor) {
    const PixelRect& s = *target.scissor;
    if (s.x0 > s.x1 || s.y0 > s.y1) {
      throw std::invalid_argument("scissor is inverted (x0 > x1 or y0 > y1)");
    }
    clip.x0 = std::max(clip.x0, s.x0);
    clip.y0 = std::max(clip.y0, s.y0);
    clip.x1 = std::min(clip.x1, s.x1);
    clip.y1 = std::min(clip.y1, s.y1);
    if (clip.empty()) clip = {0, 0, 0, 0};
  }
  return clip;
}

RasterReport rasterize(std::span<const Vec2> vertices, std::span<const std::uint32_t> indices,
                       const RasterTarget& target, const RasterOptions& options,
                       CoverageSink& sink) {
  const detail::TriangleBatch batch = make_batch(vertices, indices, target, options);
  const detail::KernelTable& kernels = chosen_kernels(options);
  RasterReport report;
  report.isa = kernels.isa;
  kernels.rasterize(batch, sink, report);
  return report;
}

CoverageCount count_coverage(std::span<const Vec2> vertices, std::span<const std::uint32_t> indices,
                             const RasterTarget& target, const RasterOptions& options) {
  const detail::TriangleBatch batch = make_batch(vertices, indices, target, options);
  const detail::KernelTable& kernels = chosen_kernels(options);
  CoverageCount count;
  count.report.isa = kernels.isa;
  kernels.count_coverage(batch, count.report, count.pixels);
  return count;
}

}  // namespace edgewise
