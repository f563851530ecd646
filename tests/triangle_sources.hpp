// Random triangle generators for the differential tests and the fuzz corpus: each aims at a
// different way a fast path could part from the reference.
#pragma once

#include <span>
#include <string_view>

#include "edgewise/coverage.hpp"
#include "random.hpp"

namespace edgewise::test {

struct TriangleSource {
  std::string_view name;
  // Triangles are drawn into this target; batches may add a scissor.
  RasterTarget target;
  // Share of the per-ISA triangle budget. The reference's cost grows with the clipped bounding
  // box, so sources of large triangles get small targets or scissor windows and smaller shares.
  double share;
  // Each batch gets a scissor window of at most this many pixels per side, at a random place
  // (0: a random scissor, often none, sometimes empty or partly outside the target).
  std::int32_t window;
  // Writes one triangle; `aim` is the batch's clip rectangle (target and scissor).
  void (*make)(Random& random, const PixelRect& aim, Vec2 (&triangle)[3]);
};

// uniform, tiny, huge, slivers, near_axis, ties, guard_band; shares add up to 1.
std::span<const TriangleSource> triangle_sources();

}  // namespace edgewise::test
