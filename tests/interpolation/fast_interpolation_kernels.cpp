// Every interpolator instantiated for one ISA and exposed as a FastInterpolation table; compiled
// once per ISA (edgewise_add_isa_objects), in namespaces of its own (isa_test_<isa>), apart from
// the library's copies of the same inline code.
#define EDGEWISE_ISA_NAMESPACE EDGEWISE_CONCAT(isa_test_, EDGEWISE_BUILD_ISA)
#include "core/isa_build.hpp"

#include "fast_interpolation.hpp"
#include "interpolation/interpolation-inl.hpp"
#include "simd/lane_arch-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {
namespace {

using Arch = RowArch<EDGEWISE_ARCH>;

template <InterpolationMethod Method>
WeightRow<Arch> screen_row_of(const ScreenTriangle& triangle, double origin_x, double origin_y,
                              std::int32_t column, std::int32_t row) {
  return ScreenInterpolator<Arch, Method>(triangle, origin_x, origin_y).row(column, row);
}

WeightRow<Arch> screen_row_for(InterpolationMethod method, const ScreenTriangle& triangle,
                               double origin_x, double origin_y, std::int32_t column,
                               std::int32_t row) {
  switch (method) {
    case InterpolationMethod::nearest_vertex:
      return screen_row_of<InterpolationMethod::nearest_vertex>(triangle, origin_x, origin_y,
                                                                column, row);
    case InterpolationMethod::inverse_distance:
      return screen_row_of<InterpolationMethod::inverse_distance>(triangle, origin_x, origin_y,
                                                                  column, row);
    case InterpolationMethod::subtriangle_areas:
      return screen_row_of<InterpolationMethod::subtriangle_areas>(triangle, origin_x, origin_y,
                                                                   column, row);
    case InterpolationMethod::edge_functions:
      return screen_row_of<InterpolationMethod::edge_functions>(triangle, origin_x, origin_y,
                                                                column, row);
    case InterpolationMethod::scanline:
      return screen_row_of<InterpolationMethod::scanline>(triangle, origin_x, origin_y, column,
                                                          row);
    case InterpolationMethod::plane_equations:
      return screen_row_of<InterpolationMethod::plane_equations>(triangle, origin_x, origin_y,
                                                                 column, row);
  }
  return interpolation_detail::centroid_row<Arch>();
}

void store(const WeightRow<Arch>& row, float* weights) {
  constexpr std::size_t kLanes = xsimd::batch<float, Arch>::size;
  for (int i = 0; i < 3; ++i)
    row.b[i].store_unaligned(weights + i * kLanes);
}

void screen_row(InterpolationMethod method, const ScreenTriangle& triangle, double origin_x,
                double origin_y, std::int32_t column, std::int32_t row, float* weights) {
  store(screen_row_for(method, triangle, origin_x, origin_y, column, row), weights);
}

void perspective_row(InterpolationMethod method, const ScreenTriangle& triangle, double origin_x,
                     double origin_y, std::int32_t column, std::int32_t row, float* weights) {
  const PerspectiveDivide<Arch> divide(triangle);
  store(divide.apply(screen_row_for(method, triangle, origin_x, origin_y, column, row)), weights);
}

}  // namespace

const test::FastInterpolation& fast_interpolation() {
  static const test::FastInterpolation table{EDGEWISE_ISA_ENUM, xsimd::batch<float, Arch>::size,
                                             &screen_row, &perspective_row};
  return table;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
