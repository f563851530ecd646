// The rectangle-query workload shared by edgewise's benchmark and its peers': a screen of
// occluders (the fill-rate triangles of 50 px) and rectangles of 4 to 128 px at random depths.
#pragma once

#include <cstdint>
#include <vector>

#include "edgewise/isa.hpp"
#include "edgewise/occlusion.hpp"

namespace edgewise::bench {

// The 50-px fill-rate triangles drawn into a 1920x1080 buffer (once per ISA, reduction and
// partial coverage).
const OcclusionBuffer& query_scene(Isa isa, std::int32_t reduction = 1,
                                   PartialCoverage partial = PartialCoverage::ignored);

// 65,536 rectangles in pixels, each with a depth in the occluders' range.
const std::vector<OcclusionRect>& query_rects();

// The triangles of query_scene(): 2^16 of 50 px.
inline constexpr int kQuerySceneSize = 50;
inline constexpr std::size_t kQuerySceneTriangles = 65536;

}  // namespace edgewise::bench
