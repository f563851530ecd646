// The atlas's anti-aliasing study: each coverage mode (the pixel centre, 2 to 16 samples, exact
// area; aa_accuracy/coverage_modes.hpp) against the exact area of each pixel: its error at the
// pixels edges cross and over a Siemens star, against its time per triangle on every ISA.
#pragma once

#include <string>

#include "atlas/study_settings.hpp"
#include "atlas/study_output.hpp"

namespace edgewise::atlas {

StudyOutput aa_study(const StudySettings& settings, const std::string& cpu);

}  // namespace edgewise::atlas
