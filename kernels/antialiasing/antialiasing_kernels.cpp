// The anti-aliasing kernels, compiled once per ISA: exact pixel areas (pixel_area.hpp's
// rasterize_areas()) and the resolve filters (resolve.hpp's resolve()).
#include "../core/isa_build.hpp"

#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "pixel_area-inl.hpp"
#include "resolve_box-inl.hpp"
#include "resolve_taps-inl.hpp"
#include "../core/isa_kernels.hpp"
#include "../coverage/triangle_batch-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {
namespace {

// The areas of each triangle's pixels (pixel_area-inl.hpp), buffered for the sink.
class AreaVisitor {
 public:
  static constexpr bool kWalksItself = true;
  AreaVisitor(const detail::TriangleBatch& batch, AreaSink& sink) : batch_(batch), sink_(sink) {}
  void begin_triangle(std::uint32_t t) { triangle_ = t; }
  void walk(const TriangleSetup& setup) {
    AreaTriangle tri;
    for (int i = 0; i < 3; ++i) {
      const std::size_t corner = batch_.indices != nullptr
                                     ? batch_.indices[3 * std::size_t{triangle_} + i]
                                     : 3 * std::size_t{triangle_} + i;
      // Snapped as setup_triangles() snaps (the set-up accepted these coordinates).
      tri.x[i] = static_cast<std::int64_t>(
          std::nearbyint(static_cast<double>(batch_.vertices[corner].x) * 256.0));
      tri.y[i] = static_cast<std::int64_t>(
          std::nearbyint(static_cast<double>(batch_.vertices[corner].y) * 256.0));
    }
    const std::int64_t twice_area = (tri.x[1] - tri.x[0]) * (tri.y[2] - tri.y[0]) -
                                    (tri.y[1] - tri.y[0]) * (tri.x[2] - tri.x[0]);
    tri.orientation = twice_area > 0 ? -1.0 : 1.0;
    walk_areas<Arch>(tri, setup.box, *this, triangle_, [this](const AreaTile& tile) {
      // A tile made in place stays there; the others move down over the empty ones (or in
      // from a row too wide for the buffer).
      if (&tile != buffer_ + count_) buffer_[count_] = tile;
      if (++count_ == kCapacity) flush();
    });
  }
  // Room for a tile row (walk_areas): the buffer's free end, after a flush if it is short; a
  // row wider than the buffer is made apart and copied in as its tiles are emitted. In place,
  // the count can reach kCapacity only at the row's last slot, so no flush comes mid-row.
  AreaTile* row(std::int32_t columns) {
    const auto wanted = static_cast<std::size_t>(columns);
    if (wanted > kCapacity) {
      wide_row_.resize(wanted);
      return wide_row_.data();
    }
    if (count_ + wanted > kCapacity) flush();
    return buffer_ + count_;
  }
  void flush() {
    if (count_ != 0) sink_.consume({buffer_, count_});
    count_ = 0;
  }

 private:
  static constexpr std::size_t kCapacity = 32;
  const detail::TriangleBatch& batch_;
  AreaSink& sink_;
  std::uint32_t triangle_ = 0;
  std::vector<AreaTile> wide_row_;
  std::size_t count_ = 0;
  AreaTile buffer_[kCapacity];
};

}  // namespace

void rasterize_areas(const detail::TriangleBatch& batch, AreaSink& sink, RasterReport& report) {
  AreaVisitor visitor(batch, sink);
  run_batch(batch, visitor, report);
  visitor.flush();
}

void resolve_box(const detail::ResolveCall& call, std::int32_t first_tile_row,
                 std::int32_t last_tile_row) {
  resolve_box_tiles<RowArch<EDGEWISE_ARCH>>(call, first_tile_row, last_tile_row);
}

void resolve_taps(const detail::ResolveCall& call, std::int32_t first_row, std::int32_t last_row) {
  resolve_taps_rows<RowArch<EDGEWISE_ARCH>>(call, first_row, last_row);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
