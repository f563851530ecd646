// The screen interpolator of the method a draw call names, chosen at run time.
//
// Only the row evaluation differs between the interpolation methods (interpolation-inl.hpp);
// the depth test, the colour writes and the tile walks around it are the same. One shading
// visitor therefore serves every method, with one switch per row of lanes where the methods
// spend a dozen float operations or more each, instead of a copy of the visitor (and of every
// walk and depth-test variant inside it) per method: the drawing kernels compile in a third of
// the time. The plane-equation paths of shade_colour-inl.hpp, which interpolate colours by their
// own planes, do not call row() at all.
#pragma once

#include <cstdint>
#include <utility>
#include <variant>

#include "screen_triangle.hpp"
#include "interpolation-inl.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

template <class Arch>
class MethodInterpolator {
 public:
  // A value outside the enumeration (possible only by a cast) is taken as plane_equations.
  MethodInterpolator(InterpolationMethod method, const ScreenTriangle& t, double origin_x,
                     double origin_y)
      : interpolator_(make(method, t, origin_x, origin_y)) {}

  // A switch whose cases inline each method's row (std::visit calls them through a table).
  [[gnu::always_inline]] WeightRow<Arch> row(std::int32_t column, std::int32_t row) const {
    switch (interpolator_.index()) {
      case 0:
        return std::get_if<0>(&interpolator_)->row(column, row);
      case 1:
        return std::get_if<1>(&interpolator_)->row(column, row);
      case 2:
        return std::get_if<2>(&interpolator_)->row(column, row);
      case 3:
        return std::get_if<3>(&interpolator_)->row(column, row);
      case 4:
        return std::get_if<4>(&interpolator_)->row(column, row);
      default:
        return std::get_if<5>(&interpolator_)->row(column, row);
    }
  }

 private:
  using Any = std::variant<ScreenInterpolator<Arch, InterpolationMethod::nearest_vertex>,
                           ScreenInterpolator<Arch, InterpolationMethod::inverse_distance>,
                           ScreenInterpolator<Arch, InterpolationMethod::subtriangle_areas>,
                           ScreenInterpolator<Arch, InterpolationMethod::edge_functions>,
                           ScreenInterpolator<Arch, InterpolationMethod::scanline>,
                           ScreenInterpolator<Arch, InterpolationMethod::plane_equations>>;

  static Any make(InterpolationMethod method, const ScreenTriangle& t, double origin_x,
                  double origin_y) {
    switch (method) {
      case InterpolationMethod::nearest_vertex:
        return Any(std::in_place_index<0>, t, origin_x, origin_y);
      case InterpolationMethod::inverse_distance:
        return Any(std::in_place_index<1>, t, origin_x, origin_y);
      case InterpolationMethod::subtriangle_areas:
        return Any(std::in_place_index<2>, t, origin_x, origin_y);
      case InterpolationMethod::edge_functions:
        return Any(std::in_place_index<3>, t, origin_x, origin_y);
      case InterpolationMethod::scanline:
        return Any(std::in_place_index<4>, t, origin_x, origin_y);
      case InterpolationMethod::plane_equations:
        break;
    }
    return Any(std::in_place_index<5>, t, origin_x, origin_y);
  }

  Any interpolator_;
};

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
