// Occlusion culling: occluders drawn into a depth buffer, then objects tested against it, so that
// a renderer draws only what can be seen (docs/design/occlusion.md).
//
// An OcclusionBuffer holds one depth per pixel of a view: z/w in Direct3D's clip space
// (camera.hpp), cleared to 1, the far plane. draw_occluders() draws meshes into it through
// draw()'s pipeline (the same snapping, fill rule, clipping, culling, depth formula and threads),
// depth test less with writes: the depth it holds is, bit for bit, what draw() of the same meshes
// leaves in a Framebuffer. A query then asks, for each object, whether any sample it covers would
// pass the depth test less against those depths:
// - test_triangles(): the object's own triangles, exactly as draw() would test them;
// - test_rects(): screen rectangles, each with the nearest depth of what it bounds;
// - test_boxes(): boxes in object space, under a transform to clip space (perspective or
//   orthographic).
// Each answer is visible, occluded, or outside (no sample of the view to cover). Rectangles and
// boxes stand for the objects inside them, so their answers are conservative: occluded only when
// no sample of any object inside them can pass.
//
// Thread safety: test_rects() and test_boxes() may run on many threads at once, and each call
// may itself run on several (their OcclusionOptions overloads); draw_occluders(),
// test_triangles() and clear() need the buffer to themselves.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "edgewise/camera.hpp"
#include "edgewise/coverage.hpp"
#include "edgewise/draw.hpp"
#include "edgewise/framebuffer.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/names.hpp"
#include "edgewise/threads.hpp"
#include "edgewise/vector.hpp"

namespace edgewise {

namespace detail {
struct DrawCall;
struct ReducedDepth;
struct SampleRect;
struct DepthPlane;
struct PlaneTile;
struct PlaneSlots;
struct BlockLayer;
}  // namespace detail

enum class Visibility : std::uint8_t {
  visible,   // some sample may pass the depth test
  occluded,  // no sample can pass
  outside,   // no sample of the view is covered
};

// How the blocks of a reduced buffer (OcclusionBuffer's `reduction` 2 or 4) take the depth of
// triangles that cover them only in part.
enum class PartialCoverage : std::uint8_t {
  ignored,  // not at all: a block takes only triangles that cover it whole (4 bytes per block)
  merged,   // merged in a layer per block, to the largest of their depths once together they
            // cover it: culls more, but costs per block along every triangle's edges and 12
            // bytes per block (docs/design/occlusion.md, "Reduced resolution")
};

// Triangles for the buffer: occluders, or an object to test. Spans are read during the call.
struct OcclusionMesh {
  std::span<const Vec3> positions;
  std::span<const std::uint32_t> indices;  // three per triangle; empty: vertices 3t .. 3t + 2
};

struct OcclusionOptions {
  Mat4 transform = identity();     // object space to clip space
  CullMode cull = CullMode::none;  // winding on screen (y down), as coverage.hpp defines it
  std::optional<Isa> isa;          // default: active_isa()
  std::size_t threads = 0;         // as DrawOptions::threads
  TaskExecutor executor;           // as DrawOptions::executor
};

// What an object covers on screen: at most the samples whose centres (i + 0.5, j + 0.5) lie in
// the closed rectangle [x0, x1] x [y0, y1] (pixels, y down), none of them at a depth below
// `depth` (z/w as draw() computes it per sample). Coordinates may be infinite.
struct OcclusionRect {
  float x0 = 0.0f, y0 = 0.0f, x1 = 0.0f, y1 = 0.0f;
  float depth = 0.0f;
};

// The box [min, max] of object space (min <= max on each axis, finite).
struct OcclusionBox {
  Vec3 min, max;
};

class OcclusionBuffer {
 public:
  // A view of width x height pixels, sides 1 .. kMaxTargetSize (coverage.hpp). With `reduction`
  // 2 or 4 the buffer keeps one depth per block of reduction x reduction pixels of the view, and
  // what it answers stays conservative: a block holds at least every depth that the
  // full-resolution buffer would hold at its pixels (docs/design/occlusion.md, "Reduced
  // resolution"). Occluders set a block where one triangle covers all its pixels, to the largest
  // depth it has there, and, with `partial` merged, where triangles cover it only together;
  // copy_depth() takes each block's largest depth; queries test the blocks that hold their
  // pixels. Throws std::invalid_argument for another size or reduction.
  OcclusionBuffer(std::int32_t width, std::int32_t height, std::int32_t reduction = 1,
                  PartialCoverage partial = PartialCoverage::ignored);
  OcclusionBuffer(const OcclusionBuffer&);
  OcclusionBuffer(OcclusionBuffer&&) noexcept;
  OcclusionBuffer& operator=(const OcclusionBuffer&);
  OcclusionBuffer& operator=(OcclusionBuffer&&) noexcept;
  ~OcclusionBuffer();

  // The view's size, in pixels.
  std::int32_t width() const { return width_; }
  std::int32_t height() const { return height_; }
  // Pixels of the view per depth on each axis: 1, 2 or 4.
  std::int32_t reduction() const { return reduction_; }
  PartialCoverage partial_coverage() const { return partial_; }
  // The depths kept per row and per column: the view's sides divided by the reduction, rounded
  // up (a last block may hold fewer of the view's pixels).
  std::int32_t depth_width() const { return depth_.width(); }
  std::int32_t depth_height() const { return depth_.height(); }

  // Every depth to 1: nothing is occluded.
  void clear();

  // The mesh drawn as occluders: depth test less with writes; the report's triangle and
  // fragment counts are draw()'s. Drawn front to back, occluders are fastest: tiles they cover
  // wholly in front are kept as their planes (docs/design/occlusion.md), 20 bytes per triangle
  // drawn, kept until clear() (between calls, up to 2^20 planes or four per tile). Throws as
  // draw() does for inconsistent spans or options.
  DrawReport draw_occluders(const OcclusionMesh& mesh, const OcclusionOptions& options);

  // The depth of a frame already drawn in place of the buffer's: occluders drawn as the first
  // objects of a frame, or by a depth pre-pass, serve as they are. Throws std::invalid_argument
  // when the frame's size is not the view's, or when it is multisampled (a query answers for
  // pixel centres, and an object may reach another sample of a pixel without its centre). A
  // reduced buffer keeps each block's largest depth.
  void copy_depth(const Framebuffer& frame, const OcclusionOptions& options = {});

  // Exact: visible when draw() of the mesh with depth test less would pass a sample, outside when
  // it would cover none, occluded otherwise. On a reduced buffer, visible when a sample that
  // draw() would cover has a depth below its block's (the samples tested one by one on the
  // calling thread: for objects of few triangles). The depths are left unchanged.
  Visibility test_triangles(const OcclusionMesh& mesh, const OcclusionOptions& options);

  // One answer per rectangle: outside when it holds no pixel centre of the view or its depth
  // lies beyond 1, occluded when its depth is at least every stored depth of the samples it
  // holds, else visible. Throws std::invalid_argument, naming the rectangle, for a NaN, an
  // inverted rectangle (x0 > x1 or y0 > y1) or out.size() != rects.size().
  void test_rects(std::span<const OcclusionRect> rects, std::span<Visibility> out,
                  std::optional<Isa> isa = std::nullopt) const;
  // The same on options.threads (options.isa's kernels, options.executor's threads; the rest of
  // the options unused): the answers are the same for every thread count, and a bad rectangle is
  // named as above, the first of the list.
  void test_rects(std::span<const OcclusionRect> rects, std::span<Visibility> out,
                  const OcclusionOptions& options) const;

  // One answer per box, under `transform` (object space to clip space): outside when all its
  // corners lie beyond one plane of the view volume; occluded when none of the samples its faces
  // would cover could pass, judged from their screen box and a lower bound on the depths the
  // depth formula gives them (docs/design/occlusion.md); visible otherwise, and visible for a
  // box with a corner in front of the near plane or outside the guard band (one that draw()
  // would clip), whose bounds cannot be found from its corners. Throws std::invalid_argument,
  // naming the box, for a non-finite or inverted box, or out.size() != boxes.size().
  void test_boxes(std::span<const OcclusionBox> boxes, const Mat4& transform,
                  std::span<Visibility> out, std::optional<Isa> isa = std::nullopt) const;
  // The same under options.transform, on options.threads (as test_rects() above).
  void test_boxes(std::span<const OcclusionBox> boxes, std::span<Visibility> out,
                  const OcclusionOptions& options) const;

  // The stored depth of pixel (x, y) (unchecked), or of block (x, y) of a reduced buffer, and
  // every depth row-major (depth_width() x depth_height(), as Framebuffer::read_depth()).
  float depth(std::int32_t x, std::int32_t y) const { return depth_.depth(x, y); }
  void read_depth(std::span<float> depth) const { depth_.read_depth(depth); }

 private:
  // Writes the values of tiles kept as planes into depth_ (with `resolve`), then rebuilds the
  // tile maxima.
  void refresh_depth(const OcclusionOptions& options, const char* caller, bool resolve);
  // Every tile's depth now in depth_ alone: drawn or copied there (the bounds then rebuilt from
  // the maxima), or, with `keep_bounds`, already resolved there.
  void forget_planes(bool keep_bounds);
  // prepare_draw() for the view (a reduced buffer's draws run in the view's samples).
  detail::DrawCall prepare_view_draw(const DrawMesh& mesh, const DrawOptions& options) const;
  // Occluders into a reduced buffer by the scalar reference.
  DrawReport draw_blocks_reference(const DrawMesh& mesh, const DrawOptions& options);
  detail::ReducedDepth reduced_depth();

  std::int32_t width_, height_, reduction_;
  PartialCoverage partial_;

  // The depth target; its colour is never read (the reference's draw() writes one colour).
  Framebuffer depth_;
  // The depth as the SIMD kernels draw occluders into it: each tile as planes or as depth_'s
  // values, and the planes the tiles name, the far plane first
  // (kernels/draw/shading/plane_tiles.hpp).
  std::vector<detail::PlaneTile> plane_tiles_;
  std::vector<detail::PlaneSlots> plane_slots_;
  std::vector<detail::DepthPlane> planes_;
  // Of a reduced buffer whose partial coverage is merged, per block: the samples that triangles
  // covering the block in part have covered, and a depth they lie at or below.
  std::vector<detail::BlockLayer> layers_;
  // The largest depth of each 8x8 tile, exact: rebuilt after every change of the depths.
  std::vector<float> tile_max_;
};

// Names of the values (names.hpp).
std::string_view name_of(Visibility value);
std::string_view name_of(PartialCoverage value);
template <>
std::span<const Visibility> values_of<Visibility>();
template <>
std::span<const PartialCoverage> values_of<PartialCoverage>();

}  // namespace edgewise
