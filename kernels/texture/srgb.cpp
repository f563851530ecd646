// The sRGB transfer functions (IEC 61966-2-1) and the 8-bit decode table built from them.
#include <array>
#include <cmath>
#include <span>

#include "edgewise/texture.hpp"

namespace edgewise {
namespace {

// Arguments outside [0, 1] are clamped, and NaN reads as 0, so that neither function can return
// NaN (pow of a negative base would).
double clamp_unit(double v) {
  return v > 0.0 ? (v < 1.0 ? v : 1.0) : 0.0;
}

}  // namespace

double srgb_to_linear(double encoded) {
  const double c = clamp_unit(encoded);
  return c <= 0.04045 ? c / 12.92 : std::pow((c + 0.055) / 1.055, 2.4);
}

double linear_to_srgb(double linear) {
  const double l = clamp_unit(linear);
  return l <= 0.0031308 ? 12.92 * l : 1.055 * std::pow(l, 1.0 / 2.4) - 0.055;
}

std::span<const float, 256> srgb_decode_table() {
  // A function-local static: built on first use, so a caller's own static initializer never
  // sees an unfilled table (namespace-scope statics have no order across files).
  static const std::array<float, 256> table = [] {
    std::array<float, 256> decoded{};
    for (int code = 0; code < 256; ++code) {
      decoded[code] = static_cast<float>(srgb_to_linear(code / 255.0));  // rounded once
    }
    return decoded;
  }();
  return table;
}

}  // namespace edgewise
