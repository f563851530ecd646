// The atlas's interpolation study: every interpolation method of draw() (interpolation.hpp), with
// perspective-correct and affine weights, against the exact perspective-correct value of a
// vertex attribute at each pixel centre: its error and its time per fragment on every ISA (the
// Pareto chart), affine against perspective-correct as the triangle's depth range w_max / w_min
// grows (to w near 0), and each method as triangles thin to slivers.
#pragma once

#include <string>

#include "atlas/study_settings.hpp"
#include "atlas/study_output.hpp"

namespace edgewise::atlas {

StudyOutput interpolation_study(const StudySettings& settings, const std::string& cpu);

}  // namespace edgewise::atlas
