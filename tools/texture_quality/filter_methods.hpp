// The edgewise filter settings that are scored: every TextureFilter once with the default
// options, the anisotropic ones at the chosen max_anisotropy, and supersampling also at a denser
// grid, to show what more taps buy.
#pragma once

#include <string>
#include <vector>

#include "edgewise/sampler.hpp"

namespace edgewise::texture_quality {

// The denser supersampling grid scored beside the default SamplerOptions::supersample_taps.
inline constexpr int kDenseSupersampleTaps = 8;

struct FilterMethod {
  std::string name;  // the filter's name, with its setting where it has one: "ewa_16x"
  SamplerOptions options;
};

// In TextureFilter order; repeat wrap on both axes, exact level of detail, no bias.
// `max_anisotropy` must lie in 1 .. kMaxAnisotropyLimit.
std::vector<FilterMethod> filter_methods(int max_anisotropy);

}  // namespace edgewise::texture_quality
