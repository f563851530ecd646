// Comparing two result arrays bit for bit (NaN included), with a message naming the first
// mismatch.
#pragma once

#include <gtest/gtest.h>

#include <bit>
#include <cstdint>
#include <span>
#include <sstream>

#include "edgewise/vector.hpp"

namespace edgewise::sample_cli_test {

inline bool same_bits(const Vec4& a, const Vec4& b) {
  const float fa[4] = {a.x, a.y, a.z, a.w}, fb[4] = {b.x, b.y, b.z, b.w};
  for (int c = 0; c < 4; ++c) {
    if (std::bit_cast<std::uint32_t>(fa[c]) != std::bit_cast<std::uint32_t>(fb[c])) return false;
  }
  return true;
}

inline ::testing::AssertionResult bitwise_equal(std::span<const Vec4> tool,
                                                std::span<const Vec4> library) {
  if (tool.size() != library.size()) {
    return ::testing::AssertionFailure()
           << "the tool wrote " << tool.size() << " results, the library made " << library.size();
  }
  std::size_t mismatches = 0, first = 0;
  for (std::size_t i = 0; i < tool.size(); ++i) {
    if (!same_bits(tool[i], library[i]) && mismatches++ == 0) first = i;
  }
  if (mismatches == 0) return ::testing::AssertionSuccess();
  std::ostringstream message;
  message.precision(9);
  const Vec4 &a = tool[first], &b = library[first];
  message << mismatches << " of " << tool.size() << " results differ; first, query " << first
          << ": tool (" << a.x << ", " << a.y << ", " << a.z << ", " << a.w << "), library (" << b.x
          << ", " << b.y << ", " << b.z << ", " << b.w << ")";
  return ::testing::AssertionFailure() << message.str();
}

}  // namespace edgewise::sample_cli_test
