#include "common/median.hpp"

#include <algorithm>
#include <stdexcept>

namespace edgewise::tools {

double median(std::span<const double> values) {
  if (values.empty()) throw std::invalid_argument("median: no values");
  std::vector<double> sorted(values.begin(), values.end());
  std::sort(sorted.begin(), sorted.end());
  const std::size_t middle = sorted.size() / 2;
  return sorted.size() % 2 == 1 ? sorted[middle] : 0.5 * (sorted[middle - 1] + sorted[middle]);
}

}  // namespace edgewise::tools
