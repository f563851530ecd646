// The per-ISA kernel table behind the public entry points.
#pragma once

#include <cstddef>
#include <cstdint>

#include "edgewise/camera.hpp"
#include "edgewise/raster.hpp"

namespace edgewise::detail {

// A validated call: the target is already reduced to one clip rectangle.
struct TriangleBatch {
  const Vec2* vertices;
  std::size_t vertex_count;
  const std::uint32_t* indices;  // null: triangle t is vertices 3t .. 3t+2
  std::size_t triangle_count;
  PixelRect clip;
  CullMode cull;
  TriangleStatus* statuses;  // null or triangle_count entries
};

struct ShadeBatch;
struct ShadeCounts;

struct KernelTable {
  Isa isa;
  void (*rasterize)(const TriangleBatch& batch, CoverageSink& sink, RasterReport& report);
  void (*count_coverage)(const TriangleBatch& batch, RasterReport& report, std::uint64_t& pixels);
  void (*shade)(const ShadeBatch& batch, RasterReport& report, ShadeCounts& counts);
  // out[i] = transform(m, in[i]) (camera.hpp), bit for bit.
  void (*transform_vertices)(const Mat4& m, const Vec3* in, std::size_t count, Vec4* out);
};

const KernelTable& kernel_table(Isa isa);

// Counts a triangle that was not drawn into the report: errors (remembering the first one) or
// culled. Shared by every ISA and the reference, so their reports agree by construction.
inline void count_not_drawn(RasterReport& report, std::size_t triangle, TriangleStatus status) {
  if (is_error(status)) {
    if (report.errors++ == 0) {
      report.first_error_triangle = triangle;
      report.first_error = status;
    }
  } else {
    ++report.culled;
  }
}

}  // namespace edgewise::detail

// One table per compiled ISA, each defined in its own translation unit.
namespace edgewise::isa_reference {
const detail::KernelTable& kernel_table();
}
namespace edgewise::isa_sse2 {
const detail::KernelTable& kernel_table();
}
namespace edgewise::isa_sse4_1 {
const detail::KernelTable& kernel_table();
}
namespace edgewise::isa_avx2 {
const detail::KernelTable& kernel_table();
}
namespace edgewise::isa_neon {
const detail::KernelTable& kernel_table();
}
