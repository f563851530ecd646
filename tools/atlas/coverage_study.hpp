// The atlas's coverage study: the library's exact fixed-point rasterizer against edge functions
// in float64 and float32 (edge_function_methods.hpp), by the pixels each decides differently and
// by the watertightness of shared edges (holes, pixels covered twice), as the coordinates grow
// to the guard band, as triangles thin to slivers and shrink below a pixel; and each method's
// time per triangle.
#pragma once

#include "atlas/study_settings.hpp"
#include "atlas/study_output.hpp"

namespace edgewise::atlas {

StudyOutput coverage_study(const StudySettings& settings, const std::string& cpu);

}  // namespace edgewise::atlas
