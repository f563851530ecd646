// Rectangles and boxes of the occlusion queries turned into ranges of samples with a depth that
// bounds what they hold (docs/design/occlusion.md, "Queries"). Shared by every ISA and the
// reference: the kernels only compare those ranges with the stored depths.
#pragma once

#include <cstddef>
#include <cstdint>

#include "edgewise/camera.hpp"
#include "edgewise/occlusion.hpp"
#include "../draw/vertex_stage/clip.hpp"
#include "occlusion_call.hpp"

namespace edgewise::detail {

// The samples of a view of width x height whose centres lie in the rectangle, with its depth;
// empty (outside) for a depth beyond 1. Throws std::invalid_argument, naming rectangle `index`,
// for a NaN or an inverted rectangle.
SampleRect rect_samples(const OcclusionRect& rect, std::int32_t width, std::int32_t height,
                        std::size_t index);

// rect_samples() without the throw: false for a rectangle it rejects, `out` then unspecified.
bool rect_sample_range(const OcclusionRect& rect, std::int32_t width, std::int32_t height,
                       SampleRect& out);

// A range of the view's samples as the range of blocks of `reduction` x `reduction` samples that
// hold them (non-negative, so plain division rounds down); an empty range stays as it is.
inline SampleRect sample_blocks(SampleRect samples, std::int32_t reduction) {
  if (reduction > 1 && samples.x0 <= samples.x1 && samples.y0 <= samples.y1) {
    samples.x0 /= reduction;
    samples.y0 /= reduction;
    samples.x1 /= reduction;
    samples.y1 /= reduction;
  }
  return samples;
}

enum class BoxReach : std::uint8_t {
  bounded,    // `samples` bounds what the box's faces cover, and the depth they get
  outside,    // every corner beyond one plane of the view volume
  unbounded,  // a corner that draw() would clip: the box counts as visible
};

struct BoxSamples {
  BoxReach reach = BoxReach::unbounded;
  SampleRect samples;
};

// Throws std::invalid_argument, naming box `index`, for a non-finite or inverted box.
BoxSamples box_samples(const OcclusionBox& box, const Mat4& to_clip, const Viewport& viewport,
                       const GuardBandPlanes& planes, std::size_t index);

}  // namespace edgewise::detail
