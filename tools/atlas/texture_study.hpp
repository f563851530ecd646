// The atlas's texture study: every texture filter on every ISA, and OpenImageIO's
// TextureSystem, against ground truth (the average of the bilinearly reconstructed texture over
// each pixel's exact footprint) on the checkerboard ground plane, error against time per sample
// (the Pareto chart); each filter's error as the footprint's anisotropy grows; and float32
// summed-area sums against exact ones as the texture grows.
#pragma once

#include <string>

#include "atlas/study_settings.hpp"
#include "atlas/study_output.hpp"

namespace edgewise::atlas {

StudyOutput texture_study(const StudySettings& settings, const std::string& cpu);

}  // namespace edgewise::atlas
