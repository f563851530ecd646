// The Pareto front of methods measured by cost (time per sample) and error: the methods that no
// other method beats on both, i.e. the lowest error for its time.
#pragma once

#include <span>
#include <vector>

namespace edgewise::texture_quality {

struct CostAndError {
  double cost;
  double error;
};

// Errors within this fraction of each other count as equal. The same filter on two ISAs (or an
// ISA and the reference) differs only by rounding, a few parts in a million of its RMSE; without
// the allowance the slow reference would sit on the front beside the fast path whenever its
// rounding happened to land lower. A real improvement between methods is far larger.
inline constexpr double kEqualErrorFraction = 1e-3;

// front[i] is true when no point j dominates point i: j costs no more and its error is no
// larger (allowing kEqualErrorFraction), and j is cheaper or clearly more accurate (by more
// than kEqualErrorFraction). Equal points are all on the front. A point with a NaN cost or
// error is never on the front and dominates nothing.
std::vector<bool> pareto_front(std::span<const CostAndError> points);

}  // namespace edgewise::texture_quality
