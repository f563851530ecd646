// A cheap first look, per group of triangles in double lanes, at which untextured triangles an
// error budget cannot draw in one colour (kernels/draw/shading/shading_budget.hpp): those whose
// exact colours at the vertices, c_i times the light at n_i, already spread wider than one colour
// allows. shade_interval() bounds the colour over the whole closed triangle, the vertices
// included, so it refuses every triangle marked here; marking only where the computed spread
// exceeds the limit by 2^-20 (far more than the few double roundings of either computation)
// keeps the choices exactly the scalar reference's, which has no such first look.
#pragma once

#include <cstddef>

#include <xsimd/xsimd.hpp>

#include "plane_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
inline void mark_beyond_budget(const PlaneGroupInput<Arch>& in, bool diffuse, const Vec3& light,
                               float ambient, double width_limit,
                               bool (&beyond)[kSetupLanes<Arch>]) {
  using D = xsimd::batch<double, Arch>;
  constexpr std::size_t kLanes = kSetupLanes<Arch>;
  const auto at = [](const double* lanes) { return D::load_aligned(lanes); };
  const D a(static_cast<double>(ambient));
  D lit[3];
  for (int i = 0; i < 3; ++i) {
    lit[i] = D(1.0);
    if (!diffuse) continue;
    const D nx = at(in.normal[i][0]), ny = at(in.normal[i][1]), nz = at(in.normal[i][2]);
    const D length = xsimd::sqrt(nx * nx + ny * ny + nz * nz);
    const D facing = (nx * D(light.x) + ny * D(light.y) + nz * D(light.z)) / length;
    // A zero or non-finite normal gives NaN here: the lane is left unmarked.
    lit[i] = a + (D(1.0) - a) * xsimd::max(facing, D(0.0));
  }
  const D limit(width_limit + 0x1p-20);
  auto marked = D(0.0) != D(0.0);
  for (int k = 0; k < 4; ++k) {
    D low(0.0), high(0.0);
    for (int i = 0; i < 3; ++i) {
      const D c = at(in.colour[i][k]) * (k < 3 ? lit[i] : D(1.0));
      const D clamped = xsimd::min(xsimd::max(c, D(0.0)), D(1.0));
      low = i == 0 ? clamped : xsimd::min(low, clamped);
      high = i == 0 ? clamped : xsimd::max(high, clamped);
    }
    marked = marked || (high - low > limit);
  }
  alignas(64) double flags[kLanes];
  xsimd::select(marked, D(1.0), D(0.0)).store_aligned(flags);
  for (std::size_t l = 0; l < kLanes; ++l)
    beyond[l] = flags[l] != 0.0;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
