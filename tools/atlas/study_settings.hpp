// What every study of the atlas is run with.
#pragma once

#include <filesystem>

#include "atlas/benchmark_timer.hpp"

namespace edgewise::atlas {

struct StudySettings {
  bool quick = false;  // few cases and short timings: a smoke run, its figures rough
  TimerSettings timer;
  std::filesystem::path cache;  // where results computed once are kept (texture ground truths)
};

}  // namespace edgewise::atlas
