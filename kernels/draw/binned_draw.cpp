// draw() on several threads: sort-middle binning (docs/design/threads.md). Ranges of
// triangles are binned at once, each into lists of its own; then each bin is shaded by one task
// that walks the ranges' lists in range order, which is submission order, through the same
// kernel as a one-thread call, with the bin as the clip rectangle. Every tile lies in one bin,
// so each tile (colour, depth and depth bound) sees the same triangles in the same order as with
// one thread: the framebuffer and every count are the same bit for bit.
#include <algorithm>
#include <cstdint>
#include <optional>
#include <span>
#include <vector>

#include "binned_draw.hpp"
#include "../core/framebuffer_access.hpp"
#include "shading_plan.hpp"
#include "../texture/texture_description.hpp"
#include "../coverage/triangle_binning.hpp"
#include "vertex_stage/vertex_stage.hpp"

namespace edgewise::detail {

// Multisampled targets are drawn in bins on one thread too: a bin's samples stay in cache (see
// BinGrid), where drawing each triangle straight into a target of several times the single-sample
// size misses the cache at every tile (docs/design/anti-aliasing.md).
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
  report.rasterized += raster.triangles - raster.culled - raster.errors;
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

// The vertex stage's counts of each range (clipping, outside, culled, errors) into `report`.
void add_vertex_counts(DrawReport& report, std::span<const DrawReport> ranges) {
  for (const DrawReport& part : ranges) {
    report.clipped += part.clipped;
    report.clip_triangles += part.clip_triangles;
    report.outside += part.outside;
    report.culled += part.culled;
    report.errors += part.errors;
    report.rasterized += part.rasterized;
  }
}

// The `triangles` triangles of `indices` (three each) into the vertices of screen mesh `screen`
// (first_vertex_index 0), as the binning and the coverage kernels take them.
TriangleBatch screen_triangles(const Framebuffer& target, const ScreenMesh& screen,
                               const std::uint32_t* indices, std::size_t triangles,
                               const PixelRect& clip, CullMode cull) {
  return {screen.positions.data(),
          screen.positions.size(),
          indices,
          triangles,
          clip,
          cull,
          nullptr,
          FramebufferAccess::sample_pattern(target)};
}

// The corner indices of lists refs[first, end), one after the other, in `joined`.
void join_lists(std::span<const ListRef> refs, std::size_t first, std::size_t end,
                GrowableArray<std::uint32_t>& joined) {
  joined.truncate(0);
  for (std::size_t r = first; r < end; ++r) {
    const CornerList& list = *refs[r].list;
    std::copy_n(list.data(), 3 * list.triangles(), joined.extend(3 * list.triangles()));
  }
}

// Shades every bin (or its sub-bins, plan_shading()), one task each: its lists in submission
// order, each through the kernel with the task's rectangle as its clip rectangle and the screen
// mesh of the list's range (range_batches[r]). When every range's triangles index one screen
// mesh, a task joins its lists and makes one kernel call: a call per list would set up each
// list's last few triangles in a group of their own (lanes left empty) and pay the call's own
// set-up once per range.
void shade_bins(DrawCall& call, const BinGrid& grid, const BinLists& lists,
                std::span<const ShadeBatch> range_batches) {
  const bool one_screen =
      std::all_of(range_batches.begin(), range_batches.end(), [&](const ShadeBatch& batch) {
        return batch.coverage.vertices == range_batches[0].coverage.vertices;
      });
  ShadePlan plan;
  plan_shading(plan, call, grid, lists, range_batches);
  // Occluders' planes: room for every list's triangles, each task's from its own first plane.
  std::vector<std::uint32_t> first_plane(plan.tasks.size());
  if (call.plane_store != nullptr) {
    std::size_t planes = 0;
    for (std::size_t index = 0; index < plan.tasks.size(); ++index) {
      first_plane[index] = static_cast<std::uint32_t>(planes);
      const ShadeTask& task = plan.dealt(index);
      for (std::size_t r = task.first; r < task.end; ++r)
        planes += plan.refs[r].list->triangles();
    }
    const std::uint32_t first = call.plane_store->reserve(planes);
    for (std::uint32_t& task_first : first_plane)
      task_first += first;
  }
  std::vector<BinCounts> task_counts(plan.tasks.size());
  call.workers.run(plan.tasks.size(), [&](std::size_t index) {
    const ShadeTask& task = plan.dealt(index);
    ShadeCounts& counts = task_counts[index].shading;
    RasterReport& triangles = task_counts[index].triangles;
    std::uint32_t next_plane = first_plane[index];
    const auto with_planes = [&](ShadeBatch& batch) {
      if (call.plane_store == nullptr) return;
      batch.plane_tiles = call.plane_store->view(next_plane);
      next_plane += static_cast<std::uint32_t>(batch.coverage.triangle_count);
    };
    if (one_screen && task.end - task.first > 1) {
      thread_local GrowableArray<std::uint32_t> joined;  // kept: no allocation once warm
      join_lists(plan.refs, task.first, task.end, joined);
      ShadeBatch batch = range_batches[0];
      batch.coverage.clip = task.rect;
      batch.coverage.indices = joined.data();
      batch.coverage.triangle_count = joined.size() / 3;
      with_planes(batch);
      call.kernels->shade(batch, triangles, counts);
      return;
    }
    for (std::size_t r = task.first; r < task.end; ++r) {
      const CornerList& list = *plan.refs[r].list;
      ShadeBatch batch = range_batches[plan.refs[r].range];
      batch.coverage.clip = task.rect;
      batch.coverage.indices = list.data();
      batch.coverage.triangle_count = list.triangles();
      with_planes(batch);
      call.kernels->shade(batch, triangles, counts);
    }
    if (task.first == task.end) {
      // A one-thread call hands these tiles to the kernel too: the reference rebuilds the depth
      // bounds of its whole clip rectangle after drawing.
      ShadeBatch batch = range_batches[0];
      batch.coverage.clip = task.rect;
      batch.coverage.triangle_count = 0;
      with_planes(batch);
      call.kernels->shade(batch, triangles, counts);
    }
  });
  DrawReport& report = call.report;
  for (const BinCounts& counts : task_counts) {
    report.culled += counts.triangles.culled;
    report.errors += counts.triangles.errors;
    report.rasterized -= counts.triangles.culled + counts.triangles.errors;
    report.fragments += counts.shading.fragments;
    report.fragments_passed += counts.shading.passed;
    report.statistics.tiles_skipped += counts.shading.tiles_skipped;
    report.statistics.fragments_constant += counts.shading.constant;
    report.statistics.fragments_one_texel += counts.shading.one_texel;
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
                         (range + 1) * triangles / ranges, grid, lists.start_range(range),
                         range_reports[range]);
    lists.count_range(range);
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
    GrowableArray<std::uint32_t> bins;
    screen = map_to_screen(part, triangle_range(mesh, options, first, last), options, &grid, &bins);
    vertex_reports[range] = part.report;
    const TriangleBatch batch = screen_triangles(
        target, screen, screen.indices.data(), screen.indices.size() / 3, call.clip, options.cull);
    bin_screen_triangles(batch, 0, batch.triangle_count, grid, bins.data(),
                         lists.start_range(range), range_reports[range]);
    lists.count_range(range);
  });
  DrawReport& report = call.report;
  add_vertex_counts(report, vertex_reports);
  // As the direct path: no kernel call without screen triangles.
  if (count_screen_triangles(report, range_reports) == 0) return;
  // The texture flattened for the kernels once per draw.
  std::optional<FlatTexture> flat;
  if (options.texture) flat.emplace(*options.texture->texture);
  const TextureDescription* texture = flat ? &flat->description() : nullptr;
  std::vector<ShadeBatch> range_batches;
  range_batches.reserve(ranges);
  for (const ScreenMesh& screen : screens)
    range_batches.push_back(make_shade_batch(target, screen, options, call.clip, texture));
  shade_bins(call, grid, lists, range_batches);
}

namespace {

// The screen mesh `screen` of `vertices` mesh vertices, followed by the vertices that each
// range's clipping made (parts[r], first_vertex_index `vertices`), in range order, as one screen
// mesh: copied in ranges on the call's threads, vertex ranges and parts at once. Each part's
// indices of its own vertices are renumbered to where they now are; `first` (one per part) is
// where each part's vertices begin.
ScreenMesh join_clipped_vertices(const DrawCall& call, const VertexStageCall& stage,
                                 const ScreenMesh& screen, std::span<ScreenMesh> parts,
                                 std::span<const std::size_t> first, std::size_t total,
                                 std::size_t vertex_ranges) {
  const std::size_t vertices = stage.mesh.positions.size();
  ScreenMesh joined;
  Vec2* positions = joined.positions.extend(total);
  float* depth = joined.depth.extend(total);
  float* clip_w = joined.clip_w.extend(total);
  Vec4* colors = joined.colors.own(total);
  Vec3* normals = stage.diffuse ? joined.normals.own(total) : nullptr;
  Vec2* uvs = stage.textured ? joined.uvs.own(total) : nullptr;
  // Values [from, from + count) of `values` to `to` + `at`.
  const auto copy = [](const auto* values, std::size_t from, std::size_t count, auto* to,
                       std::size_t at) { std::copy_n(values + from, count, to + at); };
  const auto copy_vertices = [&](const ScreenMesh& source, std::size_t from, std::size_t count,
                                 std::size_t at) {
    copy(source.positions.data(), from, count, positions, at);
    copy(source.depth.data(), from, count, depth, at);
    copy(source.clip_w.data(), from, count, clip_w, at);
    copy(source.colors.data(), from, count, colors, at);
    if (normals != nullptr) copy(source.normals.data(), from, count, normals, at);
    if (uvs != nullptr) copy(source.uvs.data(), from, count, uvs, at);
  };
  call.workers.run(vertex_ranges + parts.size(), [&](std::size_t task) {
    if (task < vertex_ranges) {
      const std::size_t begin = task * vertices / vertex_ranges;
      const std::size_t end = (task + 1) * vertices / vertex_ranges;
      copy_vertices(screen, begin, end - begin, begin);
      return;
    }
    const std::size_t range = task - vertex_ranges;
    ScreenMesh& part = parts[range];
    copy_vertices(part, 0, part.positions.size(), first[range]);
    const auto shift = static_cast<std::uint32_t>(first[range] - vertices);
    std::uint32_t* index = part.indices.data();
    for (std::size_t i = 0; i < part.indices.size(); ++i)
      index[i] += index[i] >= vertices ? shift : 0;
  });
  return joined;
}

}  // namespace

void draw_indexed_in_ranges(DrawCall& call, Framebuffer& target, const DrawMesh& mesh,
                            const DrawOptions& options) {
  const std::size_t vertices = mesh.positions.size();
  const std::size_t triangles = call.report.triangles;
  const std::size_t threads = call.workers.threads;
  const VertexStageCall stage = vertex_stage_call(call.view, mesh, options, triangles);

  // The mesh's vertices, a range per task (ranges of the binning's length), into one screen
  // mesh, each with its code.
  ScreenMesh screen;
  start_screen_mesh(stage, screen);
  GrowableArray<std::int32_t> codes(vertices);
  const std::size_t vertex_ranges = binning_ranges(vertices, threads);
  call.workers.run(vertex_ranges, [&](std::size_t range) {
    map_vertex_range(*call.kernels, stage, range * vertices / vertex_ranges,
                     (range + 1) * vertices / vertex_ranges, screen, codes.data());
  });

  // Then the triangles, a range per task, each range's indices (and the vertices its clipping
  // makes) in a screen mesh of its own; binned at once, unless it made vertices.
  const BinGrid grid(call.clip, threads, call.samples);
  const std::size_t ranges = binning_ranges(triangles, threads);
  BinLists lists(ranges, grid.count());
  std::vector<ScreenMesh> parts(ranges);
  std::vector<DrawReport> vertex_reports(ranges);
  std::vector<RasterReport> range_reports(ranges);
  const auto bin_part = [&](const ScreenMesh& all, std::size_t range) {
    ScreenMesh& part = parts[range];
    GrowableArray<std::uint32_t> bins(part.indices.size() / 3);
    drop_culled_triangles(*call.kernels, all, part, options.cull,
                          sample_window(call.clip, call.samples), vertex_reports[range],
                          {&grid, bins.data()});
    const TriangleBatch batch = screen_triangles(target, all, part.indices.data(),
                                                 part.indices.size() / 3, call.clip, options.cull);
    bin_screen_triangles(batch, 0, batch.triangle_count, grid, bins.data(),
                         lists.start_range(range), range_reports[range]);
    lists.count_range(range);
  };
  call.workers.run(ranges, [&](std::size_t range) {
    const std::size_t first = range * triangles / ranges, last = (range + 1) * triangles / ranges;
    ScreenMesh& part = parts[range];
    part.first_vertex_index = vertices;
    part.indices.reserve(3 * (last - first));
    call.kernels->assemble_triangles(stage, codes.data(), first, last, part, vertex_reports[range]);
    if (part.positions.empty()) bin_part(screen, range);
  });

  // The vertices that clipping made follow the mesh's, range after range, as with one thread;
  // the ranges that made some are binned once they are in place.
  std::vector<std::size_t> first_clipped(ranges);
  std::size_t total = vertices;
  for (std::size_t range = 0; range < ranges; ++range) {
    first_clipped[range] = total;
    total += parts[range].positions.size();
  }
  if (total != vertices) {
    screen = join_clipped_vertices(call, stage, screen, parts, first_clipped, total, vertex_ranges);
    call.workers.run(ranges, [&](std::size_t range) {
      if (!parts[range].positions.empty()) bin_part(screen, range);
    });
  }

  DrawReport& report = call.report;
  add_vertex_counts(report, vertex_reports);
  if (count_screen_triangles(report, range_reports) == 0) return;
  std::optional<FlatTexture> flat;
  if (options.texture) flat.emplace(*options.texture->texture);
  const ShadeBatch whole =
      make_shade_batch(target, screen, options, call.clip, flat ? &flat->description() : nullptr);
  // Every range's triangles index the one screen mesh.
  shade_bins(call, grid, lists, std::vector<ShadeBatch>(ranges, whole));
}

}  // namespace edgewise::detail
