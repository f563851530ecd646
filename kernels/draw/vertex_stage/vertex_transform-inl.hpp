// Object space to clip space for a whole vertex array, a batch of vertices at a time. Every
// lane computes ((m0 x + m1 y) + m2 z) + m3 per row, the operations and order of transform()
// (camera.cpp) without fused multiply-adds, so the results equal it bit for bit on every ISA
// and in the reference: clipping, snapping and depth then see the same numbers everywhere.
#pragma once

#include <cstddef>

#include <xsimd/xsimd.hpp>

#include "edgewise/camera.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
void transform_vertex_array(const Mat4& m, const Vec3* in, std::size_t count, Vec4* out) {
  using Floats = xsimd::batch<float, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  std::size_t first = 0;
  for (; first + kLanes <= count; first += kLanes) {
    // Array of structures to one batch per coordinate.
    alignas(64) float x[kLanes], y[kLanes], z[kLanes];
    for (std::size_t i = 0; i < kLanes; ++i) {
      x[i] = in[first + i].x;
      y[i] = in[first + i].y;
      z[i] = in[first + i].z;
    }
    const Floats px = Floats::load_aligned(x), py = Floats::load_aligned(y);
    const Floats pz = Floats::load_aligned(z);
    alignas(64) float row[4][kLanes];
    for (int r = 0; r < 4; ++r) {
      const Floats value =
          ((Floats(m.m[r][0]) * px + Floats(m.m[r][1]) * py) + Floats(m.m[r][2]) * pz) +
          Floats(m.m[r][3]);
      value.store_aligned(row[r]);
    }
    for (std::size_t i = 0; i < kLanes; ++i)
      out[first + i] = {row[0][i], row[1][i], row[2][i], row[3][i]};
  }
  for (; first < count; ++first)  // the last few, one at a time, with the same operations
    out[first] = transform(m, in[first]);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
