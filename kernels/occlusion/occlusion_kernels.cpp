// The occlusion kernels (occlusion.hpp's rectangle and box queries), compiled once per ISA.
#include "../core/isa_build.hpp"

#include "rect_test-inl.hpp"
#include "../core/isa_kernels.hpp"

namespace edgewise::EDGEWISE_ISA_NAMESPACE {

using Arch = RowArch<EDGEWISE_ARCH>;

void test_sample_rects(const detail::OcclusionDepth& depth, const detail::SampleRect* rects,
                       std::size_t count, Visibility* out) {
  for (std::size_t i = 0; i < count; ++i)
    out[i] = test_rect<Arch>(depth, rects[i]);
}

void occlusion_tile_maxima(const float* tiles, std::size_t first, std::size_t last, float* out) {
  tile_maxima<Arch>(tiles, first, last, out);
}

}  // namespace edgewise::EDGEWISE_ISA_NAMESPACE
