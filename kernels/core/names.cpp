// name_of() and values_of<>() of every enum of the public API (names.hpp).
#include <span>
#include <string_view>

#include "edgewise/edgewise.hpp"

namespace edgewise {

std::string_view name_of(CullMode value) {
  switch (value) {
    case CullMode::none:
      return "none";
    case CullMode::clockwise:
      return "clockwise";
    case CullMode::counter_clockwise:
      return "counter_clockwise";
  }
  return "unknown";
}

template <>
std::span<const CullMode> values_of<CullMode>() {
  static constexpr CullMode kValues[] = {CullMode::none, CullMode::clockwise,
                                         CullMode::counter_clockwise};
  return kValues;
}

std::string_view name_of(TriangleStatus value) {
  switch (value) {
    case TriangleStatus::drawn:
      return "drawn";
    case TriangleStatus::culled_zero_area:
      return "culled_zero_area";
    case TriangleStatus::culled_winding:
      return "culled_winding";
    case TriangleStatus::error_non_finite:
      return "error_non_finite";
    case TriangleStatus::error_outside_guard_band:
      return "error_outside_guard_band";
    case TriangleStatus::error_bad_index:
      return "error_bad_index";
  }
  return "unknown";
}

template <>
std::span<const TriangleStatus> values_of<TriangleStatus>() {
  static constexpr TriangleStatus kValues[] = {TriangleStatus::drawn,
                                               TriangleStatus::culled_zero_area,
                                               TriangleStatus::culled_winding,
                                               TriangleStatus::error_non_finite,
                                               TriangleStatus::error_outside_guard_band,
                                               TriangleStatus::error_bad_index};
  return kValues;
}

std::string_view name_of(InterpolationMethod value) {
  switch (value) {
    case InterpolationMethod::nearest_vertex:
      return "nearest_vertex";
    case InterpolationMethod::inverse_distance:
      return "inverse_distance";
    case InterpolationMethod::subtriangle_areas:
      return "subtriangle_areas";
    case InterpolationMethod::edge_functions:
      return "edge_functions";
    case InterpolationMethod::scanline:
      return "scanline";
    case InterpolationMethod::plane_equations:
      return "plane_equations";
  }
  return "unknown";
}

template <>
std::span<const InterpolationMethod> values_of<InterpolationMethod>() {
  static constexpr InterpolationMethod kValues[] = {
      InterpolationMethod::nearest_vertex,    InterpolationMethod::inverse_distance,
      InterpolationMethod::subtriangle_areas, InterpolationMethod::edge_functions,
      InterpolationMethod::scanline,          InterpolationMethod::plane_equations};
  return kValues;
}

std::string_view name_of(LineCap value) {
  switch (value) {
    case LineCap::butt:
      return "butt";
    case LineCap::round:
      return "round";
    case LineCap::square:
      return "square";
  }
  return "unknown";
}

template <>
std::span<const LineCap> values_of<LineCap>() {
  static constexpr LineCap kValues[] = {LineCap::butt, LineCap::round, LineCap::square};
  return kValues;
}

std::string_view name_of(LineJoin value) {
  switch (value) {
    case LineJoin::miter:
      return "miter";
    case LineJoin::round:
      return "round";
    case LineJoin::bevel:
      return "bevel";
  }
  return "unknown";
}

template <>
std::span<const LineJoin> values_of<LineJoin>() {
  static constexpr LineJoin kValues[] = {LineJoin::miter, LineJoin::round, LineJoin::bevel};
  return kValues;
}

std::string_view name_of(ResolveFilter value) {
  switch (value) {
    case ResolveFilter::box:
      return "box";
    case ResolveFilter::tent:
      return "tent";
    case ResolveFilter::mitchell:
      return "mitchell";
  }
  return "unknown";
}

template <>
std::span<const ResolveFilter> values_of<ResolveFilter>() {
  static constexpr ResolveFilter kValues[] = {ResolveFilter::box, ResolveFilter::tent,
                                              ResolveFilter::mitchell};
  return kValues;
}

std::string_view name_of(Perspective value) {
  switch (value) {
    case Perspective::correct:
      return "correct";
    case Perspective::affine:
      return "affine";
  }
  return "unknown";
}

template <>
std::span<const Perspective> values_of<Perspective>() {
  static constexpr Perspective kValues[] = {Perspective::correct, Perspective::affine};
  return kValues;
}

std::string_view name_of(DepthTest value) {
  switch (value) {
    case DepthTest::less:
      return "less";
    case DepthTest::less_equal:
      return "less_equal";
    case DepthTest::greater:
      return "greater";
    case DepthTest::always:
      return "always";
    case DepthTest::never:
      return "never";
  }
  return "unknown";
}

template <>
std::span<const DepthTest> values_of<DepthTest>() {
  static constexpr DepthTest kValues[] = {DepthTest::less, DepthTest::less_equal,
                                          DepthTest::greater, DepthTest::always, DepthTest::never};
  return kValues;
}

std::string_view name_of(Shading value) {
  switch (value) {
    case Shading::flat:
      return "flat";
    case Shading::gouraud:
      return "gouraud";
    case Shading::diffuse:
      return "diffuse";
  }
  return "unknown";
}

template <>
std::span<const Shading> values_of<Shading>() {
  static constexpr Shading kValues[] = {Shading::flat, Shading::gouraud, Shading::diffuse};
  return kValues;
}

std::string_view name_of(TextureDerivatives value) {
  switch (value) {
    case TextureDerivatives::quad:
      return "quad";
    case TextureDerivatives::analytic:
      return "analytic";
  }
  return "unknown";
}

template <>
std::span<const TextureDerivatives> values_of<TextureDerivatives>() {
  static constexpr TextureDerivatives kValues[] = {TextureDerivatives::quad,
                                                   TextureDerivatives::analytic};
  return kValues;
}

std::string_view name_of(TextureFilter value) {
  switch (value) {
    case TextureFilter::nearest:
      return "nearest";
    case TextureFilter::bilinear:
      return "bilinear";
    case TextureFilter::bicubic_catmull_rom:
      return "bicubic_catmull_rom";
    case TextureFilter::bicubic_bspline:
      return "bicubic_bspline";
    case TextureFilter::mip_nearest:
      return "mip_nearest";
    case TextureFilter::trilinear:
      return "trilinear";
    case TextureFilter::supersample:
      return "supersample";
    case TextureFilter::ripmap:
      return "ripmap";
    case TextureFilter::summed_area:
      return "summed_area";
    case TextureFilter::anisotropic:
      return "anisotropic";
    case TextureFilter::ewa:
      return "ewa";
  }
  return "unknown";
}

template <>
std::span<const TextureFilter> values_of<TextureFilter>() {
  static constexpr TextureFilter kValues[] = {TextureFilter::nearest,
                                              TextureFilter::bilinear,
                                              TextureFilter::bicubic_catmull_rom,
                                              TextureFilter::bicubic_bspline,
                                              TextureFilter::mip_nearest,
                                              TextureFilter::trilinear,
                                              TextureFilter::supersample,
                                              TextureFilter::ripmap,
                                              TextureFilter::summed_area,
                                              TextureFilter::anisotropic,
                                              TextureFilter::ewa};
  return kValues;
}

std::string_view name_of(WrapMode value) {
  switch (value) {
    case WrapMode::repeat:
      return "repeat";
    case WrapMode::clamp_to_edge:
      return "clamp";
    case WrapMode::mirror:
      return "mirror";
  }
  return "unknown";
}

template <>
std::span<const WrapMode> values_of<WrapMode>() {
  static constexpr WrapMode kValues[] = {WrapMode::repeat, WrapMode::clamp_to_edge,
                                         WrapMode::mirror};
  return kValues;
}

std::string_view name_of(LodFormula value) {
  switch (value) {
    case LodFormula::exact:
      return "exact";
    case LodFormula::max_axis:
      return "max_axis";
  }
  return "unknown";
}

template <>
std::span<const LodFormula> values_of<LodFormula>() {
  static constexpr LodFormula kValues[] = {LodFormula::exact, LodFormula::max_axis};
  return kValues;
}

std::string_view name_of(FilterPrecision value) {
  switch (value) {
    case FilterPrecision::automatic:
      return "automatic";
    case FilterPrecision::float32:
      return "float32";
    case FilterPrecision::fixed16:
      return "fixed16";
  }
  return "unknown";
}

template <>
std::span<const FilterPrecision> values_of<FilterPrecision>() {
  static constexpr FilterPrecision kValues[] = {FilterPrecision::automatic,
                                                FilterPrecision::float32, FilterPrecision::fixed16};
  return kValues;
}

std::string_view name_of(TexelFormat value) {
  switch (value) {
    case TexelFormat::rgba8:
      return "rgba8";
    case TexelFormat::rgba32f:
      return "rgba32f";
  }
  return "unknown";
}

template <>
std::span<const TexelFormat> values_of<TexelFormat>() {
  static constexpr TexelFormat kValues[] = {TexelFormat::rgba8, TexelFormat::rgba32f};
  return kValues;
}

std::string_view name_of(ColorEncoding value) {
  switch (value) {
    case ColorEncoding::linear:
      return "linear";
    case ColorEncoding::srgb:
      return "srgb";
  }
  return "unknown";
}

template <>
std::span<const ColorEncoding> values_of<ColorEncoding>() {
  static constexpr ColorEncoding kValues[] = {ColorEncoding::linear, ColorEncoding::srgb};
  return kValues;
}

std::string_view name_of(PyramidFilter value) {
  switch (value) {
    case PyramidFilter::box:
      return "box";
    case PyramidFilter::lanczos3:
      return "lanczos3";
  }
  return "unknown";
}

template <>
std::span<const PyramidFilter> values_of<PyramidFilter>() {
  static constexpr PyramidFilter kValues[] = {PyramidFilter::box, PyramidFilter::lanczos3};
  return kValues;
}

}  // namespace edgewise
