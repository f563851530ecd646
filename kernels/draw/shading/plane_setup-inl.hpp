// The planes of a group of triangles set up together, one triangle per double lane: the depth
// plane (kernels/draw/shading/depth_plane.hpp) and the colour planes of Gouraud shading by plane
// equations (shade_colour-inl.hpp). Every lane computes exactly the double operations of the scalar
// set-up, in the same order (kernels are compiled without FMA contraction), and rounds to float
// once, so the planes are bit for bit those of make_depth_plane() and of the scalar colour
// planes; only the work is shared.
#pragma once

#include <cstddef>
#include <cstdint>
#include <limits>

#include <xsimd/xsimd.hpp>

#include "../../interpolation/screen_triangle.hpp"
#include "../../coverage/triangle_setup-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// A plane f(px, py) = (at_vertex + dy * ((py + 0.5) - y0)) + dx * ((px + 0.5) - x0).
struct ColourPlane {
  float at_vertex, dx, dy;
};

// Colour planes per triangle: R, G, B and A scaled to 0 .. 255 and, for perspective-correct
// colour, the plane of 1 / w (each channel then a plane of value / w).
inline constexpr int kColourPlanes = 5;
// Diffuse shading adds the planes of the normal's three components (of n / w when perspective-
// correct), after the colour planes. They are never divided by the plane of 1 / w: the light
// depends on n / |n| only, and dividing every component by the same positive value leaves that
// unchanged. Each lane's normal planes are scaled by one factor that brings the largest vertex
// value to 1, for the same reason: float32 squared lengths then neither overflow nor underflow.
inline constexpr int kNormalPlanes = 3;
inline constexpr int kFirstNormalPlane = kColourPlanes;
inline constexpr int kShadingPlanes = kColourPlanes + kNormalPlanes;

// The inputs of a group, gathered per lane from the triangles' vertices in their original
// order (corner 0 is the planes' origin).
template <class Arch>
struct PlaneGroupInput {
  static constexpr std::size_t kLanes = kSetupLanes<Arch>;
  alignas(64) double x[3][kLanes], y[3][kLanes];  // snapped positions
  alignas(64) double z[3][kLanes];                // depth z / w
  alignas(64) double w[3][kLanes];                // clip-space w
  alignas(64) double colour[3][4][kLanes];        // RGBA
  alignas(64) double normal[3][3][kLanes];        // xyz, for diffuse shading
};

// What the group's set-up gives each lane.
template <class Arch>
struct PlaneGroup {
  static constexpr std::size_t kLanes = kSetupLanes<Arch>;
  float x0[kLanes], y0[kLanes];  // corner 0, the planes' origin
  float z0[kLanes], dzdx[kLanes], dzdy[kLanes];
  float max_depth[kLanes];   // the largest vertex depth
  bool perspective[kLanes];  // colour divides by the plane of 1 / w
  // The smallest vertex 1 / w, which the plane of 1 / w is kept from falling below before the
  // division (outside the triangle, where a multisampled pixel's centre may lie, it can), as
  // the reference's perspective-correct weights keep the interpolated 1 / w.
  float min_inverse_w[kLanes];
  ColourPlane colour[kShadingPlanes][kLanes];  // colour, then normal planes
};

// Each lane's depth plane from its first vertex and the slopes dx, dy, and its largest depth.
template <class Arch>
[[gnu::always_inline]] inline void store_depth_planes(const PlaneGroupInput<Arch>& in,
                                                      const double* dx, const double* dy,
                                                      PlaneGroup<Arch>& out) {
  for (std::size_t l = 0; l < kSetupLanes<Arch>; ++l) {
    // Positions and depths came from float: converting back is exact.
    const float z[3] = {static_cast<float>(in.z[0][l]), static_cast<float>(in.z[1][l]),
                        static_cast<float>(in.z[2][l])};
    out.x0[l] = static_cast<float>(in.x[0][l]);
    out.y0[l] = static_cast<float>(in.y[0][l]);
    out.z0[l] = z[0];
    out.dzdx[l] = static_cast<float>(dx[l]);
    out.dzdy[l] = static_cast<float>(dy[l]);
    const float larger = z[0] > z[1] ? z[0] : z[1];
    out.max_depth[l] = z[2] > larger ? z[2] : larger;
  }
}

// Sets up the lanes of `in`: depth slopes always, colour planes when `colour_planes` (all but
// the R, G, B, A and 1 / w planes themselves without `colour_values`: for lanes whose colour
// is used as it is), normal planes too when `normal_planes`. With `perspective_correct`, a lane's
// colour and normal are perspective-correct when its three w are usable (kMinClipW <= w <=
// kMaxClipW) and not all equal, as the scalar shading decides.
template <class Arch>
inline void set_up_plane_group(const PlaneGroupInput<Arch>& in, bool colour_planes,
                               bool normal_planes, bool perspective_correct, PlaneGroup<Arch>& out,
                               bool colour_values = true) {
  using D = xsimd::batch<double, Arch>;
  constexpr std::size_t kLanes = kSetupLanes<Arch>;
  const auto at = [](const double* lanes) { return D::load_aligned(lanes); };
  const D x1 = at(in.x[1]) - at(in.x[0]), y1 = at(in.y[1]) - at(in.y[0]);
  const D x2 = at(in.x[2]) - at(in.x[0]), y2 = at(in.y[2]) - at(in.y[0]);
  const D area = x1 * y2 - y1 * x2;
  const auto nonzero = area != D(0.0);
  // Zero-area lanes divide by zero; their slopes are replaced by 0, as the scalar set-up does.
  const auto slopes = [&](const D& f1, const D& f2, double(&dx)[kLanes], double(&dy)[kLanes]) {
    xsimd::select(nonzero, (f1 * y2 - f2 * y1) / area, D(0.0)).store_aligned(dx);
    xsimd::select(nonzero, (f2 * x1 - f1 * x2) / area, D(0.0)).store_aligned(dy);
  };
  alignas(64) double dx[kLanes], dy[kLanes];
  const D z0 = at(in.z[0]);
  slopes(at(in.z[1]) - z0, at(in.z[2]) - z0, dx, dy);
  store_depth_planes(in, dx, dy, out);
  if (!colour_planes) return;

  const D w[3] = {at(in.w[0]), at(in.w[1]), at(in.w[2])};
  auto usable = w[0] == w[0];
  for (const D& wi : w)
    usable = usable && wi >= D(kMinClipW) && wi <= D(kMaxClipW);
  const auto perspective = usable && !(w[0] == w[1] && w[1] == w[2]);
  const auto never = D(0.0) != D(0.0);
  const auto divides = perspective_correct ? perspective : never;
  D inverse_w[3];
  for (int i = 0; i < 3; ++i)
    inverse_w[i] = xsimd::select(divides, D(1.0) / w[i], D(1.0));
  alignas(64) double at_vertex[kLanes], divided[kLanes];
  xsimd::select(divides, D(1.0), D(0.0)).store_aligned(divided);
  for (int k = 0; k < kColourPlanes && colour_values; ++k) {
    D f[3];
    for (int i = 0; i < 3; ++i)
      f[i] = k < 4 ? D(255.0) * at(in.colour[i][k]) * inverse_w[i] : inverse_w[i];
    f[0].store_aligned(at_vertex);
    slopes(f[1] - f[0], f[2] - f[0], dx, dy);
    for (std::size_t l = 0; l < kLanes; ++l) {
      out.colour[k][l] = {static_cast<float>(at_vertex[l]), static_cast<float>(dx[l]),
                          static_cast<float>(dy[l])};
    }
  }
  alignas(64) double smallest[kLanes];
  xsimd::min(xsimd::min(inverse_w[0], inverse_w[1]), inverse_w[2]).store_aligned(smallest);
  for (std::size_t l = 0; l < kLanes; ++l) {
    out.perspective[l] = divided[l] != 0.0;
    out.min_inverse_w[l] = static_cast<float>(smallest[l]);
  }
  if (!normal_planes) return;

  D f[3][kNormalPlanes];
  D largest(0.0);
  for (int i = 0; i < 3; ++i) {
    for (int k = 0; k < kNormalPlanes; ++k) {
      f[i][k] = at(in.normal[i][k]) * inverse_w[i];
      largest = xsimd::max(largest, xsimd::abs(f[i][k]));
    }
  }
  // Zero, NaN or infinite normals keep their values (the light is then 0 or undefined either way).
  const auto scalable = largest > D(0.0) && largest < D(std::numeric_limits<double>::infinity());
  const D scale = xsimd::select(scalable, D(1.0) / largest, D(1.0));
  for (int k = 0; k < kNormalPlanes; ++k) {
    (f[0][k] * scale).store_aligned(at_vertex);
    slopes((f[1][k] - f[0][k]) * scale, (f[2][k] - f[0][k]) * scale, dx, dy);
    for (std::size_t l = 0; l < kLanes; ++l) {
      out.colour[kFirstNormalPlane + k][l] = {static_cast<float>(at_vertex[l]),
                                              static_cast<float>(dx[l]), static_cast<float>(dy[l])};
    }
  }
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
