// Sample positions for multisampling: the standard patterns of Direct3D 11 (also Vulkan's
// standard sample locations) for 1, 2, 4, 8 and 16 samples per pixel
// (docs/design/anti-aliasing.md).
//
// Offsets are from the pixel centre in 1/16 px, y down. Sample k of a pixel is bit k of the
// pixel's sample mask. Every offset lies on the 1/256 px snapping grid, so each sample is
// decided exactly, by the same edge functions and the same top-left rule as the pixel centre.
#pragma once

#include <cstdint>
#include <span>

namespace edgewise {

struct SampleOffset {
  std::int8_t x, y;  // 1/16 px from the pixel centre, each in [-8, 7]
};

// True for the sample counts with a standard pattern: 1, 2, 4, 8 and 16.
bool is_standard_sample_count(int samples);

// The standard pattern for `samples` per pixel, in sample order; throws std::invalid_argument for
// a count without one. One sample is the pixel centre.
std::span<const SampleOffset> standard_sample_pattern(int samples);

}  // namespace edgewise
