// draw() on several threads: sort-middle binning (docs/DESIGN.md, "Threads"). Ranges of
// triangles are binned at once, each into lists of its own; then each bin is shaded by one task
// that walks the ranges' lists in range order, which is submission order, through the same
// kernel as a one-thread call, with the bin as the clip rectangle. Every tile lies in one bin,
// so each tile (colour, depth and depth bound) sees the same triangles in the same order as with
// one thread: the framebuffer and every count are the same bit for bit.
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "binned_draw.hpp"
#include "framebuffer_access.hpp"
#include "texture_description.hpp"
#include "triangle_binning.hpp"

namespace edgewise::detail {

// Multisampled targets are drawn in bins on one thread too: a bin's samples stay in cache (see
// BinGrid), where drawing each triangle straight into a target of several times the single-sample
// size misses the cache at every tile (docs/DESIGN.md, "Anti-aliasing").
bool DrawCall::binned() const {
  return (workers.threads > 1 || samples > 1) &&
         BinGrid(clip, workers.threads, samples).count() > 1;
}

namespace {

// Triangles [first, last) of a mesh without indices: its own mesh, as the vertex stage takes it.
DrawMesh triangle_range(const DrawMesh& mesh, const DrawOptions& options, std::size_t first,
                        std::size_t last) {
  const std::size_t begin = 3 * first, count = 3 * (last - first);
  DrawMesh part;
  part.positions = mesh.positions.subspan(begin, count);
  if (!mesh.colors.empty()) part.colors = mesh.colors.subspan(begin, count);
  if (!mesh.normals.empty()) part.normals = mesh.normals.subspan(begin, count);
  if (options.texture) part.uvs = mesh.uvs.subspan(begin, count);
  return part;
}

// The binning's counts of the screen triangles into the report; returns how many there are.
// Every screen triangle not culled or an error in the binning counts as rasterized until
// shade_bins() moves those the bins' kernel calls cull or reject (each only ever in one bin).
std::uint64_t count_screen_triangles(DrawReport& report, std::span<const RasterReport> ranges) {
  RasterReport raster;
  for (const RasterReport& range : ranges)
    add_range_report(raster, range);
  report.rasterized = raster.triangles - raster.culled - raster.errors;
  report.culled += raster.culled;
  report.errors += raster.errors;
  return raster.triangles;
}

// What one bin's kernel calls counted. Of the triangle counts, only the culled triangles and
// errors are new: those of the triangles bin_screen_triangles() left to the bins, one bin each.
struct BinCounts {
  ShadeCounts shading;
  RasterReport triangles;
};

// Shades every bin, one task each: the lists of every range in range order, each through the
// kernel with the bin as its clip rectangle, with range r's screen mesh (range_batches[r]).
void shade_bins(DrawCall& call, const BinGrid& grid, const BinLists& lists,
                std::span<const ShadeBatch> range_batches) {
  std::vector<BinCounts> bin_counts(grid.count());
  call.workers.run(grid.count(), [&](std::size_t bin) {
    ShadeCounts& counts = bin_counts[bin].shading;
    RasterReport& triangles = bin_counts[bin].triangles;
    const PixelRect rect = grid.rect(bin);
    bool shaded = false;
    for (std::size_t range = 0; range < range_batches.size(); ++range) {
      const CornerList& list = lists.list(range, bin);
      if (list.empty()) continue;
      ShadeBatch batch = range_batches[range];
      batch.coverage.clip = rect;
      batch.coverage.indices = list.data();
      batch.coverage.triangle_count = list.triangles();
      call.kernels->shade(batch, triangles, counts);
      shaded = true;
    }
    if (!shaded) {
      // A one-thread call hands these tiles to the kernel too: the reference rebuilds the depth
      // bounds of its whole clip rectangle after drawing.
      ShadeBatch batch = range_batches[0];
      batch.coverage.clip = rect;
      batch.coverage.triangle_count = 0;
      call.kernels->shade(batch, triangles, counts);
    }
  });
  DrawReport& report = call.report;
  for (const BinCounts& counts : bin_counts) {
    report.culled += counts.triangles.culled;
    report.errors += counts.triangles.errors;
    report.rasterized -= counts.triangles.culled + counts.triangles.errors;
    report.fragments += counts.shading.fragments;
    report.fragments_passed += counts.shading.passed;
    report.tiles_skipped += counts.shading.tiles_skipped;
    report.fragments_constant += counts.shading.constant;
    report.fragments_one_texel += counts.shading.one_texel;
  }
}

}  // namespace

void shade_in_bins(DrawCall& call, Framebuffer& target, const ScreenMesh& screen,
                   const DrawOptions& options, const TextureDescription* texture) {
  const BinGrid grid(call.clip, call.workers.threads, call.samples);
  const std::size_t triangles = screen.indices.size() / 3;
  const std::size_t ranges = binning_ranges(triangles, call.workers.threads);
  BinLists lists(ranges, grid.count());
  const ShadeBatch whole = make_shade_batch(target, screen, options, call.clip, texture);
  std::vector<RasterReport> range_reports(ranges);
  call.workers.run(ranges, [&](std::size_t range) {
    bin_screen_triangles(whole.coverage, range * triangles / ranges,
                         (range + 1) * triangles / ranges, grid, lists.range_lists(range),
                         range_reports[range]);
  });
  count_screen_triangles(call.report, range_reports);
  const std::vector<ShadeBatch> range_batches(ranges, whole);
  shade_bins(call, grid, lists, range_batches);
}

void draw_in_ranges(DrawCall& call, Framebuffer& target, const DrawMesh& mesh,
                    const DrawOptions& options) {
  const BinGrid grid(call.clip, call.workers.threads, call.samples);
  const std::size_t triangles = call.report.triangles;
  const std::size_t ranges = binning_ranges(triangles, call.workers.threads);
  BinLists lists(ranges, grid.count());
  std::vector<ScreenMesh> screens(ranges);
  std::vector<DrawReport> vertex_reports(ranges);
  std::vector<RasterReport> range_reports(ranges);
  call.workers.run(ranges, [&](std::size_t range) {
    const std::size_t first = range * triangles / ranges, last = (range + 1) * triangles / ranges;
    DrawCall part = call;
    part.report = DrawReport{};
    part.report.triangles = last - first;
    ScreenMesh& screen = screens[range];
    screen = map_to_screen(part, target, triangle_range(mesh, options, first, last), options);
    vertex_reports[range] = part.report;
    const TriangleBatch batch{screen.positions.data(),
                              screen.positions.size(),
                              screen.indices.data(),
                              screen.indices.size() / 3,
                              call.clip,
                              options.cull,
                              nullptr,
                              FramebufferAccess::sample_pattern(target)};
    bin_screen_triangles(batch, 0, batch.triangle_count, grid, lists.range_lists(range),
                         range_reports[range]);
  });
  DrawReport& report = call.report;
  for (const DrawReport& part : vertex_reports) {
    report.clipped += part.clipped;
    report.clip_triangles += part.clip_triangles;
    report.outside += part.outside;
    report.culled += part.culled;
    report.errors += part.errors;
  }
  // As the direct path: no kernel call without screen triangles.
  if (count_screen_triangles(report, range_reports) == 0) return;
  std::optional<FlatTexture> flat_texture;
  if (options.texture) flat_texture.emplace(*options.texture->texture);
  const TextureDescription* texture = flat_texture ? &flat_texture->description() : nullptr;
  std::vector<ShadeBatch> range_batches;
  range_batches.reserve(ranges);
  for (const ScreenMesh& screen : screens)
    range_batches.push_back(make_shade_batch(target, screen, options, call.clip, texture));
  shade_bins(call, grid, lists, range_batches);
}

}  // namespace edgewise::detail
