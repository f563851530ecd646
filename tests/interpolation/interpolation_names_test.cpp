#include <gtest/gtest.h>

#include "edgewise/interpolation.hpp"

namespace edgewise {
namespace {

TEST(InterpolationNames, RoundTripAndRejectUnknown) {
  for (InterpolationMethod method : kInterpolationMethods) {
    EXPECT_EQ(parse_name<InterpolationMethod>(name_of(method)), method);
  }
  for (Perspective perspective : {Perspective::correct, Perspective::affine}) {
    EXPECT_EQ(parse_name<Perspective>(name_of(perspective)), perspective);
  }
  EXPECT_EQ(parse_name<InterpolationMethod>("plane"), std::nullopt);
  EXPECT_EQ(parse_name<InterpolationMethod>(""), std::nullopt);
  EXPECT_EQ(parse_name<Perspective>("perspective"), std::nullopt);
  EXPECT_EQ(parse_name<InterpolationMethod>("scanline"), InterpolationMethod::scanline);
}

}  // namespace
}  // namespace edgewise
