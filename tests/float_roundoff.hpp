// float32's unit roundoff u = 2^-24: the largest relative error of rounding a real number to the
// nearest float, the unit the tests' error bounds on float32 arithmetic are counted in.
#pragma once

namespace edgewise::test {

inline constexpr double kFloatUnitRoundoff = 0x1p-24;

}  // namespace edgewise::test
