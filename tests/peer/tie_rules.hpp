// Which triangle each sample ends up with, decided exactly (64-bit integer edge functions on the
// 1/256 px grid) under each of the four fill rules that differ only for samples exactly on an
// edge: top-left (edgewise's, docs/design/rasterization.md "Fill rule and watertightness") and its
// mirror images. Samples whose triangle differs between the rules are the ones the fill rule
// decides, so a comparison that agrees on all of them has checked the rule.
#pragma once

#include <array>
#include <cstddef>
#include <cstdint>
#include <span>
#include <vector>

#include "edgewise/multisample.hpp"
#include "sample_edge_triangles.hpp"

namespace edgewise::test {

enum class TieRule : std::uint8_t { top_left, bottom_left, top_right, bottom_right };
constexpr std::array<TieRule, 4> kTieRules = {TieRule::top_left, TieRule::bottom_left,
                                              TieRule::top_right, TieRule::bottom_right};
const char* name_of(TieRule rule);

struct TieRuleImages {
  // Per rule (in kTieRules order), for every sample: 1 + the index of the last triangle that
  // covers it, 0 for none. Sample k of pixel (x, y) is element (k * height + y) * width + x.
  std::array<std::vector<std::uint32_t>, 4> ids;
  // (triangle, sample) pairs with the sample exactly on an edge of the closed triangle.
  std::uint64_t on_edge = 0;

  // Whether the rules give sample `at` different triangles: the fill rule decides it.
  bool decided_by_fill_rule(std::size_t at) const;
  // Samples where `rule` gives another triangle than the top-left rule.
  std::uint64_t differing_samples(TieRule rule) const;
};

TieRuleImages tie_rule_images(std::span<const FixedTriangle> triangles, std::int32_t width,
                              std::int32_t height, std::span<const SampleOffset> pattern);

}  // namespace edgewise::test
