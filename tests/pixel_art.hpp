// Expected coverage drawn by hand: '#' marks a covered pixel, anything else an uncovered one;
// the first row is pixel row `origin_y`, its first character pixel column `origin_x`.
#pragma once

#include <gtest/gtest.h>

#include <algorithm>
#include <cstdint>
#include <initializer_list>
#include <string_view>
#include <vector>

#include "coverage_result.hpp"

namespace edgewise::test {

inline std::vector<Pixel> pixels_from_art(std::initializer_list<std::string_view> rows,
                                          std::int32_t origin_x = 0, std::int32_t origin_y = 0) {
  std::vector<Pixel> pixels;
  std::int32_t y = origin_y;
  for (std::string_view row : rows) {
    for (std::size_t x = 0; x < row.size(); ++x) {
      if (row[x] == '#') pixels.push_back({origin_x + static_cast<std::int32_t>(x), y});
    }
    ++y;
  }
  std::sort(pixels.begin(), pixels.end());
  return pixels;
}

// The covered pixels equal `expected` (sorted; duplicates mean "covered that many times").
// Every pixel of [x0, x1) x [y0, y1), once.
inline std::vector<Pixel> block(std::int32_t x0, std::int32_t y0, std::int32_t x1,
                                std::int32_t y1) {
  std::vector<Pixel> pixels;
  for (std::int32_t y = y0; y < y1; ++y) {
    for (std::int32_t x = x0; x < x1; ++x)
      pixels.push_back({x, y});
  }
  return pixels;
}

inline ::testing::AssertionResult covers_exactly(const std::vector<Pixel>& actual,
                                                 const std::vector<Pixel>& expected) {
  if (actual == expected) return ::testing::AssertionSuccess();
  std::vector<Pixel> missing, extra;
  std::set_difference(expected.begin(), expected.end(), actual.begin(), actual.end(),
                      std::back_inserter(missing));
  std::set_difference(actual.begin(), actual.end(), expected.begin(), expected.end(),
                      std::back_inserter(extra));
  return ::testing::AssertionFailure()
         << "missing " << format_pixels(missing) << "\nextra " << format_pixels(extra);
}

}  // namespace edgewise::test
