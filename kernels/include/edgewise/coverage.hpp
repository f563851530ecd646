// Coverage rasterization: triangles in, 8x8 tile coverage masks out.
//
// Conventions (see docs/DESIGN.md): pixel (i, j) is sampled at (i + 0.5, j + 0.5); vertices are
// snapped to 1/256 px with ties to even; the top-left fill rule decides samples on edges; a tile
// mask has bit (y * 8 + x) for pixel (tile_x * 8 + x, tile_y * 8 + y).
//
// Thread safety: rasterize() and count_coverage() keep no state between calls and may run on
// many threads at once, each with its own sink and statuses. rasterize() always runs on the
// calling thread alone, whatever RasterOptions::threads says, so that its sink sees tiles in the
// order stated below, on that thread, before the function returns. count_coverage() uses
// RasterOptions::threads (threads.hpp): its counts and statuses are the same for every count.
#pragma once

#include <cstddef>
#include <cstdint>
#include <optional>
#include <span>
#include <string_view>

#include "edgewise/isa.hpp"
#include "edgewise/multisample.hpp"
#include "edgewise/threads.hpp"
#include "edgewise/vector.hpp"
#include "edgewise/names.hpp"

namespace edgewise {

inline constexpr int kTileSize = 8;
inline constexpr int kSubpixelBits = 8;
// Snapped vertices must lie in [-kGuardBand, kGuardBand) pixels on each axis.
inline constexpr int kGuardBand = 32768;
// Targets are at most this many pixels wide and high (every pixel lies inside the guard band).
inline constexpr int kMaxTargetSize = kGuardBand;

// Half-open pixel rectangle [x0, x1) x [y0, y1).
struct PixelRect {
  std::int32_t x0, y0, x1, y1;
  bool empty() const { return x0 >= x1 || y0 >= y1; }
};

struct RasterTarget {
  std::int32_t width = 0, height = 0;  // 0 .. kMaxTargetSize
  std::optional<PixelRect> scissor;    // intersected with the target
};

// Winding as seen on screen (y down). Clockwise means a positive (x1-x0)(y2-y0)-(y1-y0)(x2-x0).
enum class CullMode : std::uint8_t { none, clockwise, counter_clockwise };

enum class TriangleStatus : std::uint8_t {
  drawn,             // rasterized (it may still cover no sample)
  culled_zero_area,  // zero area after snapping
  culled_winding,    // removed by the cull mode
  error_non_finite,  // a NaN or infinite coordinate
  error_outside_guard_band,
  error_bad_index,  // an index past the end of the vertex array
};
std::string_view describe(TriangleStatus status);
inline bool is_error(TriangleStatus s) {
  return s >= TriangleStatus::error_non_finite;
}

struct RasterOptions {
  CullMode cull = CullMode::none;
  std::optional<Isa> isa;  // default: active_isa()
  // Optional: one status per triangle is written here (size must equal the triangle count).
  std::span<TriangleStatus> statuses;
  // count_coverage() only (rasterize() ignores them): 0 takes default_thread_count(), 1 counts
  // on the calling thread alone; the executor runs the tasks (empty: oneTBB's; threads.hpp).
  std::size_t threads = 0;
  TaskExecutor executor;
  // Samples per pixel: 1 samples each pixel's centre; 2, 4, 8 or 16 the standard pattern
  // (multisample.hpp), each sample decided as exactly as a centre. With more than one,
  // rasterize() delivers a TileCoverage per tile and sample and count_coverage() counts
  // covered samples. Any other count throws std::invalid_argument.
  int samples = 1;
};

struct RasterReport {
  std::uint64_t triangles = 0;
  std::uint64_t drawn = 0;
  std::uint64_t culled = 0;  // zero area or winding
  std::uint64_t errors = 0;
  std::optional<std::uint64_t> first_error_triangle;
  TriangleStatus first_error = TriangleStatus::drawn;
  Isa isa = Isa::reference;  // the ISA that ran
};

struct TileCoverage {
  std::uint32_t triangle;  // index of the triangle in the call
  std::uint16_t tile_x, tile_y;
  std::uint64_t mask;       // never 0
  std::uint8_t sample = 0;  // the sample the mask is for (RasterOptions::samples > 1)
};

// Receives tile coverage in triangle order; within a triangle, tiles come row by row
// (tile_y ascending, then tile_x ascending), and a tile's samples in pattern order. Batches are
// at most a few hundred tiles.
class CoverageSink {
 public:
  virtual ~CoverageSink() = default;
  virtual void consume(std::span<const TileCoverage> tiles) = 0;
};

// Triangles are indices[3t .. 3t+2] into `vertices`, or, with an empty `indices`, vertices
// 3t .. 3t+2. Throws std::invalid_argument for a bad target, scissor, index count or options;
// a bad triangle gets an error status and is not drawn.
RasterReport rasterize(std::span<const Vec2> vertices, std::span<const std::uint32_t> indices,
                       const RasterTarget& target, const RasterOptions& options,
                       CoverageSink& sink);

struct CoverageCount {
  RasterReport report;
  std::uint64_t pixels =
      0;  // covered samples (pixel centres, or every sample), summed over triangles
};
// Coverage only: the number of covered pixels, without delivering masks.
CoverageCount count_coverage(std::span<const Vec2> vertices, std::span<const std::uint32_t> indices,
                             const RasterTarget& target, const RasterOptions& options);

// The target (and scissor) as the rectangle that rasterization is clipped to.
// Throws std::invalid_argument for sizes outside 0 .. kMaxTargetSize or an inverted scissor.
PixelRect clip_rect(const RasterTarget& target);

// Names of the values (names.hpp).
std::string_view name_of(CullMode value);
template <>
std::span<const CullMode> values_of<CullMode>();
std::string_view name_of(TriangleStatus value);
template <>
std::span<const TriangleStatus> values_of<TriangleStatus>();

}  // namespace edgewise
