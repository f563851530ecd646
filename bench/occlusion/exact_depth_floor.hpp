// The least work exact depth can cost on the fill-rate triangles (fillrate_triangles.hpp): draw()'s
// snapping, fill rule and depth formula (depth_plane.hpp) with depth test less, every covered
// pixel's depth computed and tested, and nothing else: no planes, no binning, no report, no
// clipping, no checks of the input (which the protocol's triangles, wholly on screen, do not
// need). Set-up runs eight triangles at a time in AVX2 lanes (snapping, winding, boxes and edge
// steps in int32, the depth slopes in double as the library's set-up computes them), then each
// row of a triangle's box takes eight pixels at a time: three int32 edge values, the depth formula
// in float, the test, a blend and a store. Written only for AVX2, the ISA of the occluder target
// it bounds (docs/design/occlusion.md, "What exact depth costs").
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "../benchmarks.hpp"
#include "fillrate_triangles.hpp"

namespace edgewise::bench {

// A row-major depth buffer of kWidth x kHeight, each row padded by a batch of pixels (a box's last
// batch of a row may reach past the view's last column).
struct FloorDepth {
  static constexpr std::size_t kStride = kWidth + 8;
  std::vector<float> depth = std::vector<float>(kStride * kHeight, 1.0f);
  std::uint64_t passed = 0;  // samples that passed the depth test
  float at(int x, int y) const { return depth[static_cast<std::size_t>(y) * kStride + x]; }
};

// The triangles drawn into `out`, whose depths the caller has set (to 1 for a cleared view).
// Built for x86-64 only (EDGEWISE_BENCH_FLOOR), and run only where AVX2 is supported.
void draw_exact_depth_floor(const FillrateTriangles& triangles, FloorDepth& out);

}  // namespace edgewise::bench
