// The coverage benchmarks' triangles (Coverage/, Area/): `batch` random triangles of exactly
// `area` px^2 inside the full-HD target, one seed for all, each set made once.
#pragma once

#include <cstddef>
#include <cstdint>
#include <map>
#include <utility>
#include <vector>

#include "../benchmarks.hpp"
#include "edgewise/vector.hpp"
#include "exact_area_triangles.hpp"

namespace edgewise::bench {

// One benchmark's triangles: their area and how many go to each call.
struct AreaCase {
  int area;           // px^2 per triangle
  std::size_t batch;  // triangles per call (count_coverage(), rasterize_areas())
};

inline const std::vector<Vec2>& exact_area_workload(int area, std::size_t batch) {
  constexpr std::uint64_t kSeed = 0x5eed'ed6e'0000'0001;
  static std::map<std::pair<int, std::size_t>, std::vector<Vec2>> cache;
  auto [it, inserted] = cache.try_emplace({area, batch});
  if (inserted) it->second = workload::exact_area_triangles(batch, area, kWidth, kHeight, kSeed);
  return it->second;
}

}  // namespace edgewise::bench
