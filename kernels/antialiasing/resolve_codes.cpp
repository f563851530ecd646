// The 8-bit codes of resolved values (resolve_call.hpp): linear, or sRGB by the thresholds
// between codes.
#include <algorithm>
#include <cmath>
#include <stdexcept>

#include "edgewise/texture.hpp"
#include "resolve_call.hpp"

namespace edgewise::detail {

const std::array<float, 255>& srgb_code_thresholds() {
  static const std::array<float, 255> thresholds = [] {
    std::array<float, 255> values{};
    for (int c = 0; c < 255; ++c)
      values[c] = static_cast<float>(srgb_to_linear((c + 0.5) / 255.0));
    return values;
  }();
  return thresholds;
}

std::uint8_t encode_resolved(float v, bool srgb_colour) {
  const float clamped = v > 0.0f ? (v < 1.0f ? v : 1.0f) : 0.0f;  // NaN: 0
  if (!srgb_colour) return static_cast<std::uint8_t>(std::lrint(clamped * 255.0f));
  const std::array<float, 255>& thresholds = srgb_code_thresholds();
  return static_cast<std::uint8_t>(std::upper_bound(thresholds.begin(), thresholds.end(), clamped) -
                                   thresholds.begin());
}

const SrgbCodeCells& srgb_code_cells() {
  static const SrgbCodeCells cells = [] {
    const std::array<float, 255>& thresholds = srgb_code_thresholds();
    SrgbCodeCells table{};
    constexpr float kCell = 1.0f / SrgbCodeCells::kCells;
    for (int cell = 0; cell <= SrgbCodeCells::kCells; ++cell) {
      const float low = static_cast<float>(cell) * kCell, high = low + kCell;
      const auto first = std::upper_bound(thresholds.begin(), thresholds.end(), low);
      table.first_code[cell] = static_cast<std::uint8_t>(first - thresholds.begin());
      table.next_threshold[cell] = first == thresholds.end() ? 2.0f : *first;
      if (first != thresholds.end() && first + 1 != thresholds.end() && first[1] < high)
        throw std::logic_error("srgb_code_cells: two thresholds in one cell");
    }
    return table;
  }();
  return cells;
}

}  // namespace edgewise::detail
