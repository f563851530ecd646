#include "texture_quality/pareto_front.hpp"

#include <algorithm>
#include <cmath>

namespace edgewise::texture_quality {
namespace {

bool comparable(const CostAndError& p) {
  return !std::isnan(p.cost) && !std::isnan(p.error);
}

bool dominates(const CostAndError& a, const CostAndError& b) {
  // Infinite errors compare exactly: an allowance of infinity would make every error equal.
  const double larger = std::max(a.error, b.error);
  const double allowance = std::isfinite(larger) ? kEqualErrorFraction * larger : 0.0;
  const bool as_accurate = a.error <= b.error || a.error - b.error <= allowance;
  const bool more_accurate = a.error < b.error && b.error - a.error > allowance;
  return a.cost <= b.cost && as_accurate && (a.cost < b.cost || more_accurate);
}

}  // namespace

std::vector<bool> pareto_front(std::span<const CostAndError> points) {
  // Quadratic, for a few dozen methods per scene.
  std::vector<bool> front(points.size(), false);
  for (std::size_t i = 0; i < points.size(); ++i) {
    if (!comparable(points[i])) continue;
    bool dominated = false;
    for (std::size_t j = 0; j < points.size() && !dominated; ++j) {
      dominated = comparable(points[j]) && dominates(points[j], points[i]);
    }
    front[i] = !dominated;
  }
  return front;
}

}  // namespace edgewise::texture_quality
