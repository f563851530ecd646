// Random 8-bit RGBA texels, each code uniform in [0, 255] from a seeded generator: neighbours are
// unrelated, so a filter or table that reads the wrong texel shows.
#pragma once

#include <cstddef>
#include <cstdint>
#include <vector>

#include "random.hpp"

namespace edgewise::test {

inline std::vector<std::uint8_t> random_codes(std::int32_t width, std::int32_t height,
                                              std::uint64_t seed) {
  Random random(seed);
  std::vector<std::uint8_t> texels(static_cast<std::size_t>(width) * height * 4);
  for (std::uint8_t& v : texels)
    v = static_cast<std::uint8_t>(random.integer(0, 255));
  return texels;
}

}  // namespace edgewise::test
