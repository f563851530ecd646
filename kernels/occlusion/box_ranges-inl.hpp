// Boxes to the samples their faces may cover (box_samples(), query_bounds.cpp), a batch of boxes
// at a time, one per lane. The corners go through the vertex stage's own mapping
// (screen_mapping-inl.hpp: the transform, the clip class, the screen position and the snapping,
// each bit for bit the scalar function box_samples() calls). The rest repeats box_samples() in
// lanes, operation for operation: the corners' bounds in float (std::min and std::max as
// selects, so that even the sign of a zero is the same), the faces' steepest slopes in double
// (differences of floats, exact; one rounding per product, quotient and difference, as there,
// never fused: the kernels are built with -ffp-contract=off). Only the last step, the sample
// ranges and the depth bound from those, runs per box, through bounded_box_samples() itself. So
// every box gets box_samples()'s answer field for field (box_ranges_test.cpp checks it on every
// ISA); the slopes were a box's largest cost.
#pragma once

#include <algorithm>
#include <cstddef>
#include <cstdint>
#include <limits>

#include <xsimd/xsimd.hpp>

#include "query_bounds.hpp"
#include "../draw/vertex_stage/screen_mapping-inl.hpp"
#include "../simd/interleave-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

namespace box_ranges_detail {

// std::min(a, b) and std::max(a, b) lane by lane: b only where the comparison holds.
template <class B>
[[gnu::always_inline]] inline B smaller(B a, B b) {
  return xsimd::select(b < a, b, a);
}
template <class B>
[[gnu::always_inline]] inline B larger(B a, B b) {
  return xsimd::select(a < b, b, a);
}

// The largest |dz/dx| and |dz/dy| over kFaceTriangles, for the boxes whose corners' snapped
// positions and depths are x[k], y[k], z[k] (as doubles, one box per lane): steepest_slopes().
template <class Arch>
[[gnu::always_inline]] inline void steepest_slopes(const xsimd::batch<double, Arch> (&x)[8],
                                                   const xsimd::batch<double, Arch> (&y)[8],
                                                   const xsimd::batch<double, Arch> (&z)[8],
                                                   xsimd::batch<double, Arch>& sx,
                                                   xsimd::batch<double, Arch>& sy) {
  using Doubles = xsimd::batch<double, Arch>;
  sx = Doubles(0.0);
  sy = Doubles(0.0);
  for (const detail::FaceTriangle& t : detail::kFaceTriangles) {
    const Doubles x1 = x[t.b] - x[t.a], y1 = y[t.b] - y[t.a];
    const Doubles x2 = x[t.c] - x[t.a], y2 = y[t.c] - y[t.a];
    const Doubles z1 = z[t.b] - z[t.a], z2 = z[t.c] - z[t.a];
    const Doubles area = x1 * y2 - y1 * x2;
    const auto covers = area != Doubles(0.0);  // a zero area covers nothing
    const Doubles inverse = Doubles(1.0) / xsimd::abs(area);
    const Doubles slope_x = xsimd::abs(z1 * y2 - z2 * y1) * inverse;
    const Doubles slope_y = xsimd::abs(z2 * x1 - z1 * x2) * inverse;
    sx = xsimd::select(covers && sx < slope_x, slope_x, sx);
    sy = xsimd::select(covers && sy < slope_y, slope_y, sy);
  }
}

}  // namespace box_ranges_detail

// box_samples() of boxes[0 .. count) into out[0 .. count), returning count, or the index of the
// first box it would reject (valid_box() false), the boxes before it done.
template <class Arch>
std::size_t box_ranges(const OcclusionBox* boxes, std::size_t count, const Mat4& to_clip,
                       const Viewport& viewport, const GuardBandPlanes& planes,
                       detail::BoxSamples* out) {
  using namespace box_ranges_detail;
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  using Doubles = xsimd::batch<double, Arch>;
  constexpr std::size_t kLanes = Floats::size;
  constexpr std::size_t kDoubleLanes = Doubles::size;
  static_assert(sizeof(OcclusionBox) == 6 * sizeof(float));
  const ScreenMapping<Arch> mapping(to_clip, viewport, planes);
  constexpr float kInfinity = std::numeric_limits<float>::infinity();
  for (std::size_t first = 0; first < count; first += kLanes) {
    std::size_t lanes = std::min(kLanes, count - first);
    // The boxes before a bad one are answered, then the bad one named.
    bool rejected = false;
    for (std::size_t l = 0; l < lanes; ++l) {
      if (!detail::valid_box(boxes[first + l])) {
        lanes = l;
        rejected = true;
        break;
      }
    }
    if (lanes == 0) return first;
    // A part batch: its missing lanes repeat its first box, their answers dropped.
    alignas(64) OcclusionBox batch[kLanes];
    for (std::size_t l = 0; l < kLanes; ++l)
      batch[l] = boxes[first + (l < lanes ? l : 0)];
    Floats fields[6];  // min.x, min.y, min.z, max.x, max.y, max.z
    load_records6<Arch>(&batch[0].min.x, fields);

    Ints all_codes(~0), any_code(0);
    Floats min_x(kInfinity), max_x(-kInfinity), min_y(kInfinity), max_y(-kInfinity);
    Floats min_z(kInfinity);
    alignas(64) float corner_x[8][kLanes], corner_y[8][kLanes], corner_z[8][kLanes];
    for (int k = 0; k < 8; ++k) {
      const Floats corner[3] = {(k & 1) ? fields[3] : fields[0], (k & 2) ? fields[4] : fields[1],
                                (k & 4) ? fields[5] : fields[2]};
      const auto mapped = mapping.map_lanes(corner);
      all_codes = all_codes & mapped.code;
      any_code = any_code | mapped.code;
      min_x = smaller(min_x, mapped.x);
      max_x = larger(max_x, mapped.x);
      min_y = smaller(min_y, mapped.y);
      max_y = larger(max_y, mapped.y);
      min_z = smaller(min_z, mapped.depth);
      mapped.x.store_aligned(corner_x[k]);
      mapped.y.store_aligned(corner_y[k]);
      mapped.depth.store_aligned(corner_z[k]);
    }
    // Outside: every corner beyond one frustum plane (an unchecked corner has no frustum bit).
    // Bounded: every corner inside the clipping planes (code 0).
    alignas(64) std::int32_t outside[kLanes], inside[kLanes];
    xsimd::select((all_codes & Ints(kFrustumBits)) != Ints(0), Ints(1), Ints(0))
        .store_aligned(outside);
    xsimd::select(any_code == Ints(0), Ints(1), Ints(0)).store_aligned(inside);
    alignas(64) float extent[5][kLanes];
    min_x.store_aligned(extent[0]);
    max_x.store_aligned(extent[1]);
    min_y.store_aligned(extent[2]);
    max_y.store_aligned(extent[3]);
    min_z.store_aligned(extent[4]);

    alignas(64) double slope_x[kLanes], slope_y[kLanes];
    for (std::size_t h = 0; h < kLanes; h += kDoubleLanes) {
      Doubles x[8], y[8], z[8];
      for (int k = 0; k < 8; ++k) {
        alignas(64) double wide[3][kDoubleLanes];
        for (std::size_t l = 0; l < kDoubleLanes; ++l) {
          wide[0][l] = corner_x[k][h + l];
          wide[1][l] = corner_y[k][h + l];
          wide[2][l] = corner_z[k][h + l];
        }
        x[k] = Doubles::load_aligned(wide[0]);
        y[k] = Doubles::load_aligned(wide[1]);
        z[k] = Doubles::load_aligned(wide[2]);
      }
      Doubles sx, sy;
      steepest_slopes<Arch>(x, y, z, sx, sy);
      sx.store_aligned(slope_x + h);
      sy.store_aligned(slope_y + h);
    }

    for (std::size_t l = 0; l < lanes; ++l) {
      detail::BoxSamples& answer = out[first + l];
      if (outside[l] != 0) {
        answer = {detail::BoxReach::outside, {}};
      } else if (inside[l] == 0) {
        answer = {detail::BoxReach::unbounded, {}};
      } else {
        answer = detail::bounded_box_samples({extent[0][l], extent[1][l], extent[2][l],
                                              extent[3][l], extent[4][l], slope_x[l], slope_y[l]},
                                             viewport);
      }
    }
    if (rejected) return first + lanes;
  }
  return count;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
