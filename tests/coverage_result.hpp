// Running rasterize() into plain vectors, and comparing two runs tile by tile. A mismatch is
// described so it can be replayed: the call's target, scissor and cull mode, the triangle's
// coordinates to full float precision (%.9g and hexfloat), and the first differing tile and pixel.
#pragma once

#include <gtest/gtest.h>

#include <compare>
#include <cstdint>
#include <ostream>
#include <span>
#include <string>
#include <vector>

#include "edgewise/coverage.hpp"

namespace edgewise {
// Readable statuses in GoogleTest's messages.
inline void PrintTo(TriangleStatus status, std::ostream* out) {
  *out << describe(status);
}
}  // namespace edgewise

namespace edgewise::test {

struct Pixel {
  std::int32_t x, y;
  friend bool operator==(const Pixel&, const Pixel&) = default;
  // Row by row, as an image is read.
  friend std::strong_ordering operator<=>(const Pixel& a, const Pixel& b) {
    if (a.y != b.y) return a.y <=> b.y;
    return a.x <=> b.x;
  }
};

// The inputs of one rasterize() call.
struct RasterCall {
  std::span<const Vec2> vertices;
  std::span<const std::uint32_t> indices;  // empty: triangle t is vertices 3t .. 3t+2
  RasterTarget target;
  CullMode cull = CullMode::none;
  int samples = 1;  // RasterOptions::samples

  std::size_t triangle_count() const {
    return (indices.empty() ? vertices.size() : indices.size()) / 3;
  }
};

// Everything one rasterize() call produced.
struct RasterRun {
  RasterReport report;
  std::vector<TileCoverage> tiles;
  std::vector<TriangleStatus> statuses;
};

RasterRun run_raster(Isa isa, const RasterCall& call);

// Covered pixels, sorted; a pixel covered by several triangles appears once per triangle.
std::vector<Pixel> covered_pixels(const RasterRun& run);
std::vector<Pixel> covered_pixels(const RasterRun& run, std::uint32_t triangle);

// "x y" pairs of a pixel list, for failure messages.
std::string format_pixels(std::span<const Pixel> pixels);
// "%.9g (%a)": the exact float, readable and copyable.
std::string format_float(float v);
std::string describe_triangle(const RasterCall& call, std::size_t triangle);
std::string describe_call(const RasterCall& call);

// Tiles are in triangle order, row by row within a triangle; no mask is 0; no bit lies outside
// the target and scissor; the report's counts agree with the statuses.
::testing::AssertionResult well_formed(const RasterCall& call, const RasterRun& run);

// Bit-exact equality of tiles, statuses and report counts (not the ISA that ran), with the
// first difference described.
::testing::AssertionResult same_coverage(const RasterCall& call, const RasterRun& expected,
                                         const RasterRun& actual);

// Runs `isa`, checks the run is well formed and equals the reference's, and returns it.
RasterRun run_checked(Isa isa, const RasterCall& call);

// run_checked() on unindexed triangles.
RasterRun draw(Isa isa, std::span<const Vec2> vertices, const RasterTarget& target,
               CullMode cull = CullMode::none);

// The triangle's six vertex orders: three rotations of each winding.
std::vector<std::vector<Vec2>> vertex_orders(const Vec2& a, const Vec2& b, const Vec2& c);

}  // namespace edgewise::test
