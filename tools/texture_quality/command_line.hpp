// edgewise-texture-quality's command line: every option parsed and range-checked before
// any texture is built or ground truth computed. Mistakes throw UsageError
// (common/usage_error.hpp) naming the option and the value.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <vector>

#include "common/command_line.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/texture.hpp"
#include "texture_quality/filter_methods.hpp"
#include "texture_quality/scenes.hpp"

namespace edgewise::texture_quality {

// The results of a screen are held in memory several times over (queries, results, ground
// truth): beyond 2^24 pixels (4096 x 4096) the tool refuses; the ground truth of such a screen
// would take hours anyway.
inline constexpr std::int64_t kMaxPixels = std::int64_t{1} << 24;
inline constexpr std::int64_t kMaxScreenSide = 32768;  // the views' limit
inline constexpr int kMaxRepetitions = 1000;

struct QualitySettings {
  std::int32_t width = 480, height = 270;  // --size WxH
  std::int32_t texture_size = 1024;        // --texture-size
  std::vector<SceneTexture> textures{std::begin(kSceneTextures), std::end(kSceneTextures)};
  std::vector<SceneView> views{std::begin(kSceneViews), std::end(kSceneViews)};
  PyramidFilter pyramid = PyramidFilter::box;  // --pyramid
  MethodSettings methods;                      // --filter, --lod, --lod-bias, --max-aniso
  std::vector<Isa> isas;                       // --isa (repeatable), --reference; empty: active
  bool peer = true;                            // --no-peer turns OpenImageIO's peer off
  bool draw = false;    // --draw: every method also drawn by draw(), quad and analytic derivatives
  int repetitions = 5;  // --repeat: timed runs per method, median kept
  std::optional<std::string> cache_directory;   // --cache; otherwise default_cache_directory()
  std::optional<std::string> csv_path;          // --csv
  std::optional<std::string> images_directory;  // --images
};

// The usage lines after the tool's name, for --help.
std::vector<std::string> usage_lines();
// Adds edgewise-texture-quality's options to `command_line`; they fill `settings` when it parses.
void add_options(tools::CommandLine& command_line, QualitySettings& settings);

// The ISAs to run, in the order given: those named on the command line, or active_isa(). Throws
// UsageError when EDGEWISE_ISA names an ISA this machine cannot run.
std::vector<Isa> resolve_isas(const QualitySettings& settings);

}  // namespace edgewise::texture_quality
