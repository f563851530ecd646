// Public raster entry points: argument checks, then the chosen ISA's kernels; count_coverage()
// in screen bins on several threads when asked (docs/design/threads.md).
#include "edgewise/coverage.hpp"
#include "edgewise/pixel_area.hpp"

#include <algorithm>
#include <cstdint>
#include <stdexcept>
#include <string>
#include <string_view>
#include <vector>

#include "../core/kernel_table.hpp"
#include "../core/parallel.hpp"
#include "triangle_binning.hpp"

namespace edgewise {
namespace {

// `caller`: the entry point, which each message names first.
detail::TriangleBatch make_batch(std::span<const Vec2> vertices,
                                 std::span<const std::uint32_t> indices, const RasterTarget& target,
                                 const RasterOptions& options, std::string_view caller) {
  const std::string who = std::string(caller) + ": ";
  const std::size_t corners = indices.empty() ? vertices.size() : indices.size();
  if (corners % 3 != 0) {
    throw std::invalid_argument(who + (indices.empty() ? "vertex" : "index") + " count " +
                                std::to_string(corners) + " is not a multiple of 3");
  }
  const std::size_t triangles = corners / 3;
  if (!options.statuses.empty() && options.statuses.size() != triangles) {
    throw std::invalid_argument(who + "statuses has " + std::to_string(options.statuses.size()) +
                                " entries for " + std::to_string(triangles) + " triangles");
  }
  if (static_cast<int>(options.cull) > static_cast<int>(CullMode::counter_clockwise)) {
    throw std::invalid_argument(who + "cull mode " +
                                std::to_string(static_cast<int>(options.cull)) +
                                " is none of CullMode's values");
  }
  if (!is_standard_sample_count(options.samples)) {
    throw std::invalid_argument(who + std::to_string(options.samples) +
                                " samples per pixel has no standard pattern (1, 2, 4, 8 or 16)");
  }
  const std::span<const SampleOffset> pattern = standard_sample_pattern(options.samples);
  return {vertices.data(),
          vertices.size(),
          indices.empty() ? nullptr : indices.data(),
          triangles,
          detail::checked_clip_rect(target, caller),
          options.cull,
          options.statuses.empty() ? nullptr : options.statuses.data(),
          options.samples > 1 ? pattern : std::span<const SampleOffset>{}};
}

const detail::KernelTable& chosen_kernels(const RasterOptions& options) {
  return detail::kernel_table(resolve_isa(options.isa));
}

// count_coverage() in bins: ranges of triangles binned at once (statuses and counts decided
// there, once per triangle), then each bin counted by one task, its ranges' lists in order.
// Pixels are counted per tile and every tile lies in one bin, so the sum is the one-thread sum.
CoverageCount count_in_bins(const detail::TriangleBatch& batch, const detail::KernelTable& kernels,
                            const detail::Workers& workers) {
  const detail::BinGrid grid(batch.clip, workers.threads);
  const std::size_t ranges = detail::binning_ranges(batch.triangle_count, workers.threads);
  detail::BinLists lists(ranges, grid.count());
  std::vector<RasterReport> range_reports(ranges);
  workers.run(ranges, [&](std::size_t range) {
    detail::bin_triangles(batch, range * batch.triangle_count / ranges,
                          (range + 1) * batch.triangle_count / ranges, grid,
                          lists.start_range(range), range_reports[range]);
  });
  std::vector<std::uint64_t> bin_pixels(grid.count());
  workers.run(grid.count(), [&](std::size_t bin) {
    detail::TriangleBatch part = batch;
    part.clip = grid.rect(bin);
    part.statuses = nullptr;
    RasterReport ignored;  // the binning counted the triangles
    for (std::size_t range = 0; range < ranges; ++range) {
      const detail::CornerList& list = lists.list(range, bin);
      if (list.empty()) continue;
      part.indices = list.data();
      part.triangle_count = list.triangles();
      kernels.count_coverage(part, ignored, bin_pixels[bin]);
    }
  });
  CoverageCount count;
  count.report.isa = kernels.isa;
  for (const RasterReport& range : range_reports)
    detail::add_range_report(count.report, range);
  for (std::uint64_t pixels : bin_pixels)
    count.pixels += pixels;
  return count;
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
  return detail::checked_clip_rect(target, "clip_rect");
}

PixelRect detail::checked_clip_rect(const RasterTarget& target, std::string_view caller) {
  if (target.width < 0 || target.width > kMaxTargetSize || target.height < 0 ||
      target.height > kMaxTargetSize) {
    throw std::invalid_argument(std::string(caller) + ": target " + std::to_string(target.width) +
                                "x" + std::to_string(target.height) + " is outside 0.." +
                                std::to_string(kMaxTargetSize) + " pixels per side");
  }
  PixelRect clip{0, 0, target.width, target.height};
  if (target.scissor) {
    const PixelRect& s = *target.scissor;
    if (s.x0 > s.x1 || s.y0 > s.y1) {
      throw std::invalid_argument(std::string(caller) +
                                  ": the scissor is inverted (x0 > x1 or y0 > y1)");
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
  const detail::TriangleBatch batch = make_batch(vertices, indices, target, options, "rasterize");
  const detail::KernelTable& kernels = chosen_kernels(options);
  RasterReport report;
  report.isa = kernels.isa;
  kernels.rasterize(batch, sink, report);
  return report;
}

RasterReport rasterize_areas(std::span<const Vec2> vertices, std::span<const std::uint32_t> indices,
                             const RasterTarget& target, const RasterOptions& options,
                             AreaSink& sink) {
  RasterOptions centres = options;
  centres.samples = 1;  // areas have no samples
  const detail::TriangleBatch batch =
      make_batch(vertices, indices, target, centres, "rasterize_areas");
  const detail::KernelTable& kernels = chosen_kernels(options);
  RasterReport report;
  report.isa = kernels.isa;
  kernels.rasterize_areas(batch, sink, report);
  return report;
}

CoverageCount count_coverage(std::span<const Vec2> vertices, std::span<const std::uint32_t> indices,
                             const RasterTarget& target, const RasterOptions& options) {
  const detail::TriangleBatch batch =
      make_batch(vertices, indices, target, options, "count_coverage");
  const detail::KernelTable& kernels = chosen_kernels(options);
  const detail::Workers workers =
      detail::resolve_workers(options.threads, options.executor, "count_coverage");
  // Bin lists hold 32-bit corner indices.
  if (workers.threads > 1 && detail::BinGrid(batch.clip, workers.threads).count() > 1 &&
      vertices.size() <= UINT32_MAX && 3 * batch.triangle_count <= UINT32_MAX) {
    workers.call_up();
    return count_in_bins(batch, kernels, workers);
  }
  CoverageCount count;
  count.report.isa = kernels.isa;
  kernels.count_coverage(batch, count.report, count.pixels);
  return count;
}

}  // namespace edgewise
