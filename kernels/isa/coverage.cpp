// The coverage kernels (coverage.hpp's rasterize() and count_coverage()), compiled once per ISA.
#include "../src/isa_build.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <cmath>
#include <span>
#include <vector>

#include "../generic/pixel_area-inl.hpp"
#include "../generic/triangle_batch-inl.hpp"
#include "../src/isa_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {
namespace {

struct CountingVisitor {
  static constexpr bool kTakesEmptyMasks = true;  // an empty mask counts no pixel
  std::uint64_t pixels = 0;
  void begin_triangle(std::uint32_t) {}
  void tile(std::uint32_t, std::uint32_t, std::uint64_t mask) {
    pixels += static_cast<std::uint64_t>(std::popcount(mask));
  }
  void full_tiles(std::uint32_t begin, std::uint32_t end, std::uint32_t, std::uint64_t mask) {
    pixels += static_cast<std::uint64_t>(std::popcount(mask)) * (end - begin);
  }
  void add_pixels(std::uint64_t count) { pixels += count; }  // the span walk's count
};

// Counts the covered samples of every sample of the pattern.
struct MultisampleCountingVisitor {
  static constexpr bool kMultisample = true;
  std::uint64_t samples = 0;
  void begin_triangle(std::uint32_t) {}
  void multisample_tile(std::uint32_t, std::uint32_t, std::span<const std::uint64_t> masks) {
    for (std::uint64_t mask : masks)
      samples += static_cast<std::uint64_t>(std::popcount(mask));
  }
};

// Buffers tiles and hands them to the sink in batches.
class BufferingVisitor {
 public:
  explicit BufferingVisitor(CoverageSink& sink) : sink_(sink) {}
  std::uint32_t triangle = 0;
  void begin_triangle(std::uint32_t t) { triangle = t; }
  void tile(std::uint32_t tile_x, std::uint32_t tile_y, std::uint64_t mask,
            std::uint8_t sample = 0) {
    buffer_[count_++] = {triangle, static_cast<std::uint16_t>(tile_x),
                         static_cast<std::uint16_t>(tile_y), mask, sample};
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

// BufferingVisitor for every sample of the pattern: a tile's samples in pattern order.
struct MultisampleBufferingVisitor : BufferingVisitor {
  static constexpr bool kMultisample = true;
  using BufferingVisitor::BufferingVisitor;
  void multisample_tile(std::uint32_t tile_x, std::uint32_t tile_y,
                        std::span<const std::uint64_t> masks) {
    for (std::size_t k = 0; k < masks.size(); ++k) {
      if (masks[k] != 0) tile(tile_x, tile_y, masks[k], static_cast<std::uint8_t>(k));
    }
  }
};

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

void rasterize(const detail::TriangleBatch& batch, CoverageSink& sink, RasterReport& report) {
  if (batch.samples.size() > 1) {
    MultisampleBufferingVisitor visitor(sink);
    run_batch(batch, visitor, report);
    visitor.flush();
    return;
  }
  BufferingVisitor visitor(sink);
  run_batch(batch, visitor, report);
  visitor.flush();
}

void count_coverage(const detail::TriangleBatch& batch, RasterReport& report,
                    std::uint64_t& pixels) {
  if (batch.samples.size() > 1) {
    MultisampleCountingVisitor visitor;
    run_batch(batch, visitor, report);
    pixels += visitor.samples;
    return;
  }
  CountingVisitor visitor;
  run_batch(batch, visitor, report);
  pixels += visitor.pixels;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
