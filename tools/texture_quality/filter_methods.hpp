// The edgewise filter settings that are scored: every TextureFilter (or those asked for) with the
// level-of-detail formula and bias asked for, the anisotropic ones at the chosen max_anisotropy,
// supersampling also at a denser grid, to show what more taps buy, and the filters made of
// bilinear taps in both precisions (FilterPrecision), to show what fixed point costs.
#pragma once

#include <string>
#include <vector>

#include "edgewise/sample.hpp"

namespace edgewise::texture_quality {

// The denser supersampling grid scored beside the default SamplerOptions::supersample_taps.
inline constexpr int kDenseSupersampleTaps = 8;

struct FilterMethod {
  std::string name;  // the filter's name, with its settings where it has them: "ewa_16x"
  SamplerOptions options;
};

// What the command line sets for every method.
struct MethodSettings {
  int max_anisotropy = 16;  // 1 .. kMaxAnisotropyLimit
  LodFormula lod = LodFormula::exact;
  float lod_bias = 0.0f;               // finite
  std::vector<TextureFilter> filters;  // empty: every filter
  // Of the filters made of bilinear taps (reads_bilinear_taps()): float32 or fixed16, in order;
  // empty: float32, then fixed16.
  std::vector<FilterPrecision> precisions;
};

// Whether a filter's result depends on SamplerOptions::lod_bias, and on SamplerOptions::lod.
bool reads_lod_bias(TextureFilter filter);
bool reads_lod_formula(TextureFilter filter);

// In TextureFilter order; repeat wrap on both axes. A method whose filter reads a formula or bias
// other than the default names it: "trilinear_max_axis_bias-0.5". Every method's precision is
// float32 or fixed16, never automatic; fixed16 ends the name: "trilinear_fixed16".
std::vector<FilterMethod> filter_methods(const MethodSettings& settings);

}  // namespace edgewise::texture_quality
