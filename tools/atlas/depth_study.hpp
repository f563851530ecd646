// The atlas's depth study: how small a separation of two surfaces each depth encoding still
// resolves, as a function of the distance and of the far/near ratio: float32 z/w with `less`
// (perspective() as it is), reversed depth (near at 1, far at 0, `greater`, cleared to 0), both
// drawn by draw(), and a linear depth (view distance scaled to [0, 1], rounded to float32: a
// w-buffer, which draw() does not offer; computed for comparison). And the course's question,
// why interpolate z, as a pair of rendered images: per-pixel depth against one depth per
// triangle.
#pragma once

#include <string>

#include "atlas/study_output.hpp"
#include "atlas/study_settings.hpp"

namespace edgewise::atlas {

// Writes its images into `dir` (the study's output folder).
StudyOutput depth_study(const StudySettings& settings, const std::string& cpu,
                        const std::string& dir);

}  // namespace edgewise::atlas
