#include <gtest/gtest.h>

#include "edgewise/interpolation.hpp"

namespace edgewise {
namespace {

TEST(InterpolationNames, RoundTripAndRejectUnknown) {
  for (InterpolationMethod method : kInterpolationMethods) {
    EXPECT_EQ(parse_interpolation_method(interpolation_method_name(method)), method);
  }
  for (Perspective perspective : {Perspective::correct, Perspective::affine}) {
    EXPECT_EQ(parse_perspective(perspective_name(perspective)), perspective);
  }
  EXPECT_EQ(parse_interpolation_method("plane"), std::nullopt);
  EXPECT_EQ(parse_interpolation_method(""), std::nullopt);
  EXPECT_EQ(parse_perspective("perspective"), std::nullopt);
  static_assert(parse_interpolation_method("scanline") == InterpolationMethod::scanline);
}

}  // namespace
}  // namespace edgewise
