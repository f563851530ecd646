#include "tie_rules.hpp"

#include <algorithm>
#include <cstddef>
#include <utility>

namespace edgewise::test {
namespace {

// An edge from a to b, oriented so that E(P) = A (Px - ax) + B (Py - ay) is positive inside.
struct Edge {
  std::int64_t a, b, x, y;
  std::int64_t at(std::int64_t px, std::int64_t py) const { return a * (px - x) + b * (py - y); }
  // y down: a horizontal edge with the interior below it (B > 0) is a top edge; a sloped one
  // with the interior to its right (A > 0) is a left edge.
  bool takes_ties(TieRule rule) const {
    const bool top = a == 0 && b > 0, bottom = a == 0 && b<0, left = a> 0, right = a < 0;
    switch (rule) {
      case TieRule::top_left:
        return top || left;
      case TieRule::bottom_left:
        return bottom || left;
      case TieRule::top_right:
        return top || right;
      case TieRule::bottom_right:
        return bottom || right;
    }
    return false;
  }
};

Edge edge(const FixedPoint& from, const FixedPoint& to) {
  return {std::int64_t(from.y) - to.y, std::int64_t(to.x) - from.x, from.x, from.y};
}

}  // namespace

const char* name_of(TieRule rule) {
  switch (rule) {
    case TieRule::top_left:
      return "top-left";
    case TieRule::bottom_left:
      return "bottom-left";
    case TieRule::top_right:
      return "top-right";
    case TieRule::bottom_right:
      return "bottom-right";
  }
  return "?";
}

bool TieRuleImages::decided_by_fill_rule(std::size_t at) const {
  for (const auto& other : ids) {
    if (other[at] != ids[0][at]) return true;
  }
  return false;
}

std::uint64_t TieRuleImages::differing_samples(TieRule rule) const {
  const std::vector<std::uint32_t>& other = ids[std::size_t(rule)];
  std::uint64_t count = 0;
  for (std::size_t at = 0; at < other.size(); ++at)
    count += other[at] != ids[0][at] ? 1 : 0;
  return count;
}

TieRuleImages tie_rule_images(std::span<const FixedTriangle> triangles, std::int32_t width,
                              std::int32_t height, std::span<const SampleOffset> pattern) {
  TieRuleImages images;
  const std::size_t plane = std::size_t(width) * std::size_t(height);
  for (auto& ids : images.ids)
    ids.assign(plane * pattern.size(), 0);
  for (std::size_t t = 0; t < triangles.size(); ++t) {
    FixedTriangle v = triangles[t];
    const std::int64_t area = (std::int64_t(v[1].x) - v[0].x) * (std::int64_t(v[2].y) - v[0].y) -
                              (std::int64_t(v[1].y) - v[0].y) * (std::int64_t(v[2].x) - v[0].x);
    if (area == 0) continue;  // covers nothing
    if (area < 0) std::swap(v[1], v[2]);
    const Edge edges[3] = {edge(v[0], v[1]), edge(v[1], v[2]), edge(v[2], v[0])};
    // Pixels whose samples may be inside: every sample lies in its pixel's square.
    const auto [x_min, x_max] = std::minmax({v[0].x, v[1].x, v[2].x});
    const auto [y_min, y_max] = std::minmax({v[0].y, v[1].y, v[2].y});
    const std::int32_t i0 = std::max(0, x_min / kFixedOne - 1);
    const std::int32_t i1 = std::min(width - 1, x_max / kFixedOne + 1);
    const std::int32_t j0 = std::max(0, y_min / kFixedOne - 1);
    const std::int32_t j1 = std::min(height - 1, y_max / kFixedOne + 1);
    for (std::int32_t j = j0; j <= j1; ++j) {
      for (std::int32_t i = i0; i <= i1; ++i) {
        for (std::size_t k = 0; k < pattern.size(); ++k) {
          const std::int64_t px = std::int64_t(i) * kFixedOne + kFixedOne / 2 + 16 * pattern[k].x;
          const std::int64_t py = std::int64_t(j) * kFixedOne + kFixedOne / 2 + 16 * pattern[k].y;
          const std::int64_t e[3] = {edges[0].at(px, py), edges[1].at(px, py), edges[2].at(px, py)};
          if (e[0] < 0 || e[1] < 0 || e[2] < 0) continue;
          const bool tie = e[0] == 0 || e[1] == 0 || e[2] == 0;
          images.on_edge += tie ? 1 : 0;
          const std::size_t at =
              (k * std::size_t(height) + std::size_t(j)) * std::size_t(width) + std::size_t(i);
          for (std::size_t r = 0; r < kTieRules.size(); ++r) {
            bool covered = true;
            for (int n = 0; n < 3; ++n) {
              if (e[n] == 0 && !edges[n].takes_ties(kTieRules[r])) covered = false;
            }
            if (covered) images.ids[r][at] = std::uint32_t(t + 1);
          }
        }
      }
    }
  }
  return images;
}

}  // namespace edgewise::test
