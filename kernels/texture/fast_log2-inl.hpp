// log2 of positive floats from the exponent bits plus a short series on the mantissa: the level of
// detail needs about 16 bits of it, not the last ulp, and no library call.
#pragma once

#include <cstdint>
#include <limits>

#include <xsimd/xsimd.hpp>

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

// x = 2^e m with m in [sqrt(1/2), sqrt(2)); log2(m) = (2 / ln 2) atanh(z), z = (m - 1) / (m + 1),
// |z| <= 0.1716, summed to the z^9 term. The first dropped term, (2 / ln 2) z^11 / 11, is below
// 1.0e-9; float rounding in the few operations adds a few ulps of the result, so
// |error| <= kLog2Error = 2^-20 (|log2 x| + 1) covers both (used by the tests' bounds).
// Zero gives -inf, +inf and NaN give +inf; negative inputs are not expected (callers pass
// squared lengths and absolute values).
inline constexpr double kLog2RelativeError = 0x1p-20;

template <class Arch>
[[gnu::always_inline]] inline xsimd::batch<float, Arch> fast_log2(xsimd::batch<float, Arch> x) {
  using Floats = xsimd::batch<float, Arch>;
  using Ints = xsimd::batch<std::int32_t, Arch>;
  // Subnormals: scale by 2^24 first so that the exponent field is meaningful.
  const auto tiny = x < Floats(std::numeric_limits<float>::min());
  const Floats scaled = xsimd::select(tiny, x * Floats(0x1p24f), x);
  const Ints bits = xsimd::bitwise_cast<Ints>(scaled);
  // Exponent relative to the mantissa range [sqrt(1/2), sqrt(2)): subtract the bits of sqrt(1/2).
  constexpr std::int32_t kSqrtHalfBits = 0x3f3504f3;
  const Ints shifted = bits - Ints(kSqrtHalfBits);
  const Ints exponent = shifted >> 23;  // arithmetic shift: floor
  const Floats m = xsimd::bitwise_cast<Floats>(bits - (exponent << 23));
  const Floats z = (m - Floats(1.0f)) / (m + Floats(1.0f));
  const Floats z2 = z * z;
  // 2/ln2 * (z + z^3/3 + z^5/5 + z^7/7 + z^9/9), Horner in z^2.
  constexpr float k = 2.8853900817779268f;  // 2 / ln 2
  Floats series = Floats(k / 9.0f);
  series = series * z2 + Floats(k / 7.0f);
  series = series * z2 + Floats(k / 5.0f);
  series = series * z2 + Floats(k / 3.0f);
  series = series * z2 + Floats(k);
  const Floats e = xsimd::to_float(exponent) - xsimd::select(tiny, Floats(24.0f), Floats(0.0f));
  Floats result = e + series * z;
  result =
      xsimd::select(x == Floats(0.0f), Floats(-std::numeric_limits<float>::infinity()), result);
  // +inf and NaN: +inf (the coarsest level).
  result = xsimd::select(x < Floats(std::numeric_limits<float>::infinity()), result,
                         Floats(std::numeric_limits<float>::infinity()));
  return result;
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
