// The atlas's coverage study: the library's exact fixed-point rasterizer against edge functions
// in float64 and float32 (edge_function_methods.hpp), by the pixels each decides differently and
// by the watertightness of shared edges (holes, pixels covered twice), as the coordinates grow
// to the guard band, as triangles thin to slivers and shrink below a pixel; and each method's
// time per triangle.
#pragma once

#include "atlas/benchmark_timer.hpp"
#include "atlas/study_output.hpp"

namespace edgewise::atlas {

struct CoverageStudySettings {
  bool quick = false;  // fewer meshes and triangles: a smoke run
  TimerSettings timer;
};

StudyOutput coverage_study(const CoverageStudySettings& settings, const std::string& cpu);

}  // namespace edgewise::atlas
