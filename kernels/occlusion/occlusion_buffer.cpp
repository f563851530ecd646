// OcclusionBuffer (occlusion.hpp): occluders through draw()'s pipeline into depth kept as planes,
// and exact triangle queries through draw(); the rectangle and box queries are
// occlusion_queries.cpp's.
#include "edgewise/occlusion.hpp"

#include <algorithm>
#include <limits>
#include <stdexcept>
#include <string>
#include <vector>

#include "../core/framebuffer_access.hpp"
#include "../core/kernel_table.hpp"
#include "../core/parallel.hpp"
#include "../draw/draw_stages.hpp"
#include "../draw/shading/depth_plane.hpp"
#include "../draw/shading/plane_tiles.hpp"
#include "reduced_depth.hpp"

namespace edgewise {
namespace {

// draw() as the occlusion buffer uses it: depth test less, one colour (no colours given, so the
// kernels' uniform-colour path with no colour planes), which nothing reads.
DrawOptions occlusion_draw_options(const OcclusionOptions& options, bool depth_write) {
  DrawOptions draw_options;
  draw_options.transform = options.transform;
  draw_options.cull = options.cull;
  draw_options.depth_test = DepthTest::less;
  draw_options.depth_write = depth_write;
  draw_options.shading = Shading::gouraud;
  draw_options.isa = options.isa;
  draw_options.threads = options.threads;
  draw_options.executor = options.executor;
  return draw_options;
}

DrawMesh draw_mesh(const OcclusionMesh& mesh) {
  DrawMesh out;
  out.positions = mesh.positions;
  out.indices = mesh.indices;
  return out;
}

// Tiles per task when the maxima are rebuilt on several threads: large enough that a task's
// start costs little beside its 64 KiB of depths per 256 tiles.
constexpr std::size_t kTilesPerTask = 4096;

// Planes kept from call to call before they are forgotten (20 bytes each), unless the buffer has
// more than a quarter as many tiles.
constexpr std::size_t kKeptPlanes = std::size_t{1} << 20;

// The screen mesh's triangles in the call's view, for the scalar loops of reduced buffers.
detail::TriangleBatch view_triangles(const detail::DrawCall& call, const detail::ScreenMesh& screen,
                                     CullMode cull) {
  return {screen.positions.data(),
          screen.positions.size(),
          screen.indices.data(),
          screen.indices.size() / 3,
          call.clip,
          cull,
          nullptr};
}

std::int32_t checked_reduction(std::int32_t reduction) {
  if (reduction != 1 && reduction != 2 && reduction != 4) {
    throw std::invalid_argument("OcclusionBuffer: reduction " + std::to_string(reduction) +
                                " is not 1, 2 or 4");
  }
  return reduction;
}

// Pixels of the buffer's depth along a side of `view` pixels (0 for a side out of range, which
// the Framebuffer then rejects).
std::int32_t reduced_side(std::int32_t view, std::int32_t reduction) {
  return view < 1 || view > kMaxTargetSize ? view : (view + reduction - 1) / reduction;
}

}  // namespace

OcclusionBuffer::OcclusionBuffer(std::int32_t width, std::int32_t height, std::int32_t reduction,
                                 PartialCoverage partial)
    : width_(width),
      height_(height),
      reduction_(checked_reduction(reduction)),
      partial_(partial),
      depth_(reduced_side(width, reduction_), reduced_side(height, reduction_)) {
  if (width < 1 || height < 1) {
    throw std::invalid_argument("OcclusionBuffer: size " + std::to_string(width) + "x" +
                                std::to_string(height) + " has no pixel");
  }
  if (name_of(partial) == "unknown") {
    throw std::invalid_argument("OcclusionBuffer: partial coverage " +
                                std::to_string(static_cast<int>(partial)) + " is not a value");
  }
  const std::size_t tiles = static_cast<std::size_t>(depth_.tiles_x()) * depth_.tiles_y();
  tile_max_.assign(tiles + detail::kTileMaximaPadding, -std::numeric_limits<float>::infinity());
  plane_tiles_.resize(tiles);
  plane_slots_.resize(tiles);
  if (reduction_ > 1 && partial_ == PartialCoverage::merged) layers_.resize(tiles * 64);
  clear();
}

OcclusionBuffer::OcclusionBuffer(const OcclusionBuffer&) = default;
OcclusionBuffer::OcclusionBuffer(OcclusionBuffer&&) noexcept = default;
OcclusionBuffer& OcclusionBuffer::operator=(const OcclusionBuffer&) = default;
OcclusionBuffer& OcclusionBuffer::operator=(OcclusionBuffer&&) noexcept = default;
OcclusionBuffer::~OcclusionBuffer() = default;

void OcclusionBuffer::clear() {
  depth_.clear(Vec4{1.0f, 1.0f, 1.0f, 1.0f}, 1.0f);
  std::fill(plane_tiles_.begin(), plane_tiles_.end(), detail::far_plane_tile());
  planes_.assign(1, detail::kFarPlane);
  std::fill(layers_.begin(), layers_.end(), detail::BlockLayer{});
  std::fill(tile_max_.begin(), tile_max_.end() - detail::kTileMaximaPadding, 1.0f);
}

DrawReport OcclusionBuffer::draw_occluders(const OcclusionMesh& mesh,
                                           const OcclusionOptions& options) {
  const DrawMesh occluders = draw_mesh(mesh);
  const DrawOptions draw_options = occlusion_draw_options(options, true);
  if (reduction_ > 1 && resolve_isa(options.isa) == Isa::reference) {
    const DrawReport report = draw_blocks_reference(occluders, draw_options);
    refresh_depth(options, "draw_occluders", false);
    forget_planes(false);
    return report;
  }
  if (resolve_isa(options.isa) == Isa::reference) {
    // The reference has no planes: it draws into the values, which then hold every tile's depth.
    const DrawReport report = draw(depth_, occluders, draw_options);
    refresh_depth(options, "draw_occluders", false);
    forget_planes(false);
    return report;
  }
  // Planes are kept until clear(), a plane for each triangle a kernel call draws: past a bound,
  // the tiles (their values resolved after the last call) forget theirs.
  if (planes_.size() > std::max(kKeptPlanes, 4 * plane_tiles_.size())) forget_planes(true);
  const detail::PlaneStore store{plane_tiles_.data(), plane_slots_.data(), &planes_, reduction_,
                                 layers_.empty() ? nullptr : layers_.data()};
  detail::DrawCall call = prepare_view_draw(occluders, draw_options);
  call.plane_store = &store;
  const DrawReport report = detail::run_draw(call, depth_, occluders, draw_options);
  refresh_depth(options, "draw_occluders", true);
  return report;
}

detail::DrawCall OcclusionBuffer::prepare_view_draw(const DrawMesh& mesh,
                                                    const DrawOptions& options) const {
  detail::DrawCall call = detail::prepare_draw(depth_, mesh, options);
  if (reduction_ > 1) {
    // Drawn in the view, and walked in blocks of its samples (the buffer's pixels).
    call.view = {width_, height_};
    call.clip = PixelRect{0, 0, width_, height_};
  }
  return call;
}

DrawReport OcclusionBuffer::draw_blocks_reference(const DrawMesh& mesh,
                                                  const DrawOptions& options) {
  detail::DrawCall call = prepare_view_draw(mesh, options);
  if (!call.has_work()) return call.report;
  const detail::ScreenMesh screen = detail::map_to_screen(call, mesh, options);
  const detail::TriangleBatch batch = view_triangles(call, screen, options.cull);
  RasterReport raster;
  detail::ShadeCounts counts;
  detail::draw_block_occluders_reference(batch, screen.depth.data(), reduced_depth(), raster,
                                         counts);
  detail::add_shading_counts(call.report, raster, counts);
  return call.report;
}

detail::ReducedDepth OcclusionBuffer::reduced_depth() {
  return {detail::FramebufferAccess::depth(depth_), depth_.tiles_x(), reduction_,
          layers_.empty() ? nullptr : layers_.data()};
}

void OcclusionBuffer::copy_depth(const Framebuffer& frame, const OcclusionOptions& options) {
  if (frame.width() != width() || frame.height() != height()) {
    throw std::invalid_argument("copy_depth: a " + std::to_string(frame.width()) + "x" +
                                std::to_string(frame.height()) + " frame for a " +
                                std::to_string(width()) + "x" + std::to_string(height()) +
                                " occlusion buffer");
  }
  if (frame.samples() != 1) {
    throw std::invalid_argument("copy_depth: a frame of " + std::to_string(frame.samples()) +
                                " samples per pixel; queries answer for one sample per pixel");
  }
  if (reduction_ > 1) {
    detail::copy_block_maxima(frame, reduced_depth());
    std::fill(layers_.begin(), layers_.end(), detail::BlockLayer{});
  } else {
    // Same tiles, same layout.
    const std::size_t values = (tile_max_.size() - detail::kTileMaximaPadding) * 64;
    std::copy_n(frame.depth_tiles(), values, depth_.depth_tiles());
  }
  refresh_depth(options, "copy_depth", false);
  forget_planes(false);
}

Visibility OcclusionBuffer::test_triangles(const OcclusionMesh& mesh,
                                           const OcclusionOptions& options) {
  const DrawMesh object = draw_mesh(mesh);
  const DrawOptions draw_options = occlusion_draw_options(options, false);
  if (reduction_ > 1) {
    // The view's samples, each against its block: a few triangles, scalar.
    detail::DrawCall call = prepare_view_draw(object, draw_options);
    if (!call.has_work()) return Visibility::outside;
    const detail::ScreenMesh screen = detail::map_to_screen(call, object, draw_options);
    const detail::TriangleBatch batch = view_triangles(call, screen, draw_options.cull);
    RasterReport raster;
    detail::ShadeCounts counts;
    if (detail::some_sample_passes(batch, screen.depth.data(), reduced_depth(), raster, counts))
      return Visibility::visible;
    return counts.fragments == 0 ? Visibility::outside : Visibility::occluded;
  }
  const DrawReport report = draw(depth_, object, draw_options);
  if (report.fragments == 0) return Visibility::outside;
  return report.fragments_passed > 0 ? Visibility::visible : Visibility::occluded;
}

void OcclusionBuffer::refresh_depth(const OcclusionOptions& options, const char* caller,
                                    bool resolve) {
  const detail::KernelTable& kernels = detail::kernel_table(resolve_isa(options.isa));
  const detail::Workers workers =
      detail::resolve_workers(options.threads, options.executor, caller);
  // Written without invalidating the Framebuffer's own depth bounds: depth test less only ever
  // lowers values, so its bounds stay bounds.
  float* tiles = detail::FramebufferAccess::depth(depth_);
  const std::size_t count = plane_tiles_.size();
  const detail::PlaneTiles planes{plane_tiles_.data(), plane_slots_.data(), planes_.data(), 0};
  const auto refresh = [&](std::size_t first, std::size_t last) {
    if (resolve) kernels.resolve_plane_tiles(planes, tiles, depth_.tiles_x(), first, last);
    kernels.occlusion_tile_maxima(tiles, first, last, tile_max_.data());
  };
  const std::size_t tasks = std::min(workers.threads, (count + kTilesPerTask - 1) / kTilesPerTask);
  if (tasks <= 1) {
    refresh(0, count);
    return;
  }
  workers.run(tasks,
              [&](std::size_t task) { refresh(count * task / tasks, count * (task + 1) / tasks); });
}

void OcclusionBuffer::forget_planes(bool keep_bounds) {
  for (std::size_t t = 0; t < plane_tiles_.size(); ++t) {
    detail::PlaneTile& tile = plane_tiles_[t];
    tile.kind = detail::TileKind::values;
    tile.unresolved = false;
    if (!keep_bounds) {
      // No lower bound is known without reading the tile; the maximum is exact.
      tile.lowest = -std::numeric_limits<float>::infinity();
      tile.highest = tile_max_[t];
    }
  }
  planes_.assign(1, detail::kFarPlane);
}

std::string_view name_of(Visibility value) {
  switch (value) {
    case Visibility::visible:
      return "visible";
    case Visibility::occluded:
      return "occluded";
    case Visibility::outside:
      return "outside";
  }
  return "unknown";
}

std::string_view name_of(PartialCoverage value) {
  switch (value) {
    case PartialCoverage::ignored:
      return "ignored";
    case PartialCoverage::merged:
      return "merged";
  }
  return "unknown";
}

template <>
std::span<const PartialCoverage> values_of<PartialCoverage>() {
  static constexpr PartialCoverage kValues[] = {PartialCoverage::ignored, PartialCoverage::merged};
  return kValues;
}

template <>
std::span<const Visibility> values_of<Visibility>() {
  static constexpr Visibility kValues[] = {Visibility::visible, Visibility::occluded,
                                           Visibility::outside};
  return kValues;
}

}  // namespace edgewise
