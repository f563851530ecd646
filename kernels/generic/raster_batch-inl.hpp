// Batch entry points for one ISA: fetch, set up and walk every triangle, delivering tiles to
// an inlined visitor. Defines kernel_table() for the including ISA.
#pragma once

#include <bit>
#include <cstddef>
#include <cstdint>

#include "../src/kernel_table.hpp"
#include "tile_walk-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

using Arch = EDGEWISE_ARCH;

// Runs setup and the walk for every triangle of the batch, keeping the report.
template <class Visitor>
void run_batch(const detail::TriangleBatch& batch, Visitor& visitor, RasterReport& report) {
  report.triangles += batch.triangle_count;
  for (std::size_t t = 0; t < batch.triangle_count; ++t) {
    std::uint32_t i0 = static_cast<std::uint32_t>(3 * t), i1 = i0 + 1, i2 = i0 + 2;
    if (batch.indices != nullptr) {
      i0 = batch.indices[3 * t];
      i1 = batch.indices[3 * t + 1];
      i2 = batch.indices[3 * t + 2];
    }
    TriangleStatus status = TriangleStatus::error_bad_index;
    TriangleSetup setup;
    bool empty = true;
    if (i0 < batch.vertex_count && i1 < batch.vertex_count && i2 < batch.vertex_count) {
      status = setup_triangle(batch.vertices[i0], batch.vertices[i1], batch.vertices[i2],
                              batch.clip, batch.cull, setup, empty);
    }
    if (batch.statuses != nullptr) batch.statuses[t] = status;
    if (status == TriangleStatus::drawn) {
      ++report.drawn;
      if (!empty) {
        visitor.triangle = static_cast<std::uint32_t>(t);
        const PixelRect& box = setup.box;
        if (setup.narrow && box.x1 - box.x0 <= kTileSize && box.y1 - box.y0 <= kTileSize) {
          walk_block<Arch>(setup, visitor);
        } else if (setup.narrow) {
          walk_tiles<Arch, std::int32_t>(setup, visitor);
        } else {
          walk_tiles<Arch, std::int64_t>(setup, visitor);
        }
      }
    } else if (is_error(status)) {
      if (report.errors++ == 0) {
        report.first_error_triangle = t;
        report.first_error = status;
      }
    } else {
      ++report.culled;
    }
  }
}

struct CountingVisitor {
  std::uint32_t triangle = 0;
  std::uint64_t pixels = 0;
  void tile(std::uint32_t, std::uint32_t, std::uint64_t mask) {
    pixels += static_cast<std::uint64_t>(std::popcount(mask));
  }
  void full_tiles(std::uint32_t begin, std::uint32_t end, std::uint32_t, std::uint64_t mask) {
    pixels += static_cast<std::uint64_t>(std::popcount(mask)) * (end - begin);
  }
};

// Buffers tiles and hands them to the sink in batches.
class BufferingVisitor {
 public:
  explicit BufferingVisitor(CoverageSink& sink) : sink_(sink) {}
  std::uint32_t triangle = 0;
  void tile(std::uint32_t tile_x, std::uint32_t tile_y, std::uint64_t mask) {
    buffer_[count_++] = {triangle, static_cast<std::uint16_t>(tile_x),
                         static_cast<std::uint16_t>(tile_y), mask};
    if (count_ == kCapacity) flush();
  }
  void full_tiles(std::uint32_t begin, std::uint32_t end, std::uint32_t tile_y,
                  std::uint64_t mask) {
    for (std::uint32_t tile_x = begin; tile_x < end; ++tile_x)
      tile(tile_x, tile_y, mask);
  }
  void flush() {
    if (count_ != 0) sink_.consume({buffer_, count_});
    count_ = 0;
  }

 private:
  static constexpr std::size_t kCapacity = 256;
  CoverageSink& sink_;
  std::size_t count_ = 0;
  TileCoverage buffer_[kCapacity];
};

void rasterize(const detail::TriangleBatch& batch, CoverageSink& sink, RasterReport& report) {
  BufferingVisitor visitor(sink);
  run_batch(batch, visitor, report);
  visitor.flush();
}

void count_coverage(const detail::TriangleBatch& batch, RasterReport& report,
                    std::uint64_t& pixels) {
  CountingVisitor visitor;
  run_batch(batch, visitor, report);
  pixels += visitor.pixels;
}

const detail::KernelTable& kernel_table() {
  static const detail::KernelTable table{EDGEWISE_ISA_ENUM, &rasterize, &count_coverage};
  return table;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
