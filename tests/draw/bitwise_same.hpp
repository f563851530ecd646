// Floats, and vectors of them, compared bit for bit, with any NaN equal to any other: how the
// vertex stage's results are compared across ISAs and with the reference (-0 and 0 differ).
#pragma once

#include <cmath>
#include <cstring>

#include "edgewise/vector.hpp"

namespace edgewise::test {

inline bool same(float a, float b) {
  if (std::isnan(a) && std::isnan(b)) return true;
  return std::memcmp(&a, &b, sizeof(float)) == 0;
}
inline bool same(const Vec2& a, const Vec2& b) {
  return same(a.x, b.x) && same(a.y, b.y);
}
inline bool same(const Vec3& a, const Vec3& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z);
}
inline bool same(const Vec4& a, const Vec4& b) {
  return same(a.x, b.x) && same(a.y, b.y) && same(a.z, b.z) && same(a.w, b.w);
}

}  // namespace edgewise::test
