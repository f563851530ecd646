// The coverage kernels (coverage.hpp's rasterize() and count_coverage()), compiled once per ISA.
#include "../core/isa_build.hpp"

#include <bit>
#include <cstddef>
#include <cstdint>
#include <span>

#include "triangle_batch-inl.hpp"
#include "../core/isa_kernels.hpp"

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

}  // namespace

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
