// The Framebuffer's storage as the kernels see it, and its per-tile depth bounds: an upper bound
// on every depth value of each tile, so that a tile a triangle cannot pass the depth test in is
// skipped whole (hierarchical depth rejection).
#pragma once

#include <algorithm>
#include <cmath>
#include <limits>
#include <span>

#include "edgewise/framebuffer.hpp"
#include "edgewise/multisample.hpp"

namespace edgewise::detail {

// The smallest bound on a tile's depth values (64 per sample) that no depth test can be wrongly
// rejected by: their maximum, or +inf when one is NaN (NaN compares false against everything).
inline float tile_depth_bound(const float* tile, int samples = 1) {
  float bound = -std::numeric_limits<float>::infinity();
  for (std::size_t i = 0; i < 64 * static_cast<std::size_t>(samples); ++i) {
    bound = std::isnan(tile[i]) ? std::numeric_limits<float>::infinity() : std::max(bound, tile[i]);
  }
  return bound;
}

struct FramebufferAccess {
  static std::uint32_t* color(Framebuffer& f) { return f.color_.data(); }
  static float* depth(Framebuffer& f) { return f.depth_.data(); }
  static std::size_t index(const Framebuffer& f, std::int32_t x, std::int32_t y, int sample = 0) {
    return f.index(x, y, sample);
  }

  // The bounds, rebuilt from the depth values when something wrote depth around draw().
  static float* tile_max_depth(Framebuffer& f) {
    if (!f.depth_bounds_valid_) {
      for (std::size_t tile = 0; tile < f.tile_max_depth_.size(); ++tile)
        f.tile_max_depth_[tile] = tile_depth_bound(&f.depth_[tile * 64 * f.samples_], f.samples_);
      f.depth_bounds_valid_ = true;
    }
    return f.tile_max_depth_.data();
  }
  static void invalidate_depth_bounds(Framebuffer& f) { f.depth_bounds_valid_ = false; }

  // The kernels' sample pattern for the target: empty for one sample (the pixel centres).
  static std::span<const SampleOffset> sample_pattern(const Framebuffer& f) {
    return f.samples() > 1 ? standard_sample_pattern(f.samples()) : std::span<const SampleOffset>{};
  }
};

}  // namespace edgewise::detail
