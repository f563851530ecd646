// edgewise-sample's command line: every option parsed and range-checked before any file
// is touched. Mistakes throw UsageError (common/usage_error.hpp) naming the option and the value.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/command_line.hpp"
#include "edgewise/isa.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"
#include "texture_io/texture_loader.hpp"

namespace edgewise::sample_tool {

struct SampleSettings {
  std::string texture_path;  // --texture
  std::string queries_path;  // --queries
  std::string output_path;   // --out
  SamplerOptions sampler;    // --filter, --wrap*, --lod, --lod-bias, --max-aniso, --taps
  PyramidFilter pyramid = PyramidFilter::box;  // --pyramid
  bool srgb = false;                           // --srgb
  texture_io::LoadLimits limits;               // --max-texture-mb
  std::optional<Isa> isa;                      // --isa or --reference; otherwise active_isa()
};

// The usage lines after the tool's name, for --help.
std::vector<std::string> usage_lines();
// Adds edgewise-sample's options to `command_line`; they fill `settings` when it parses
// (--wrap-s and --wrap-t win over --wrap wherever they stand).
void add_options(tools::CommandLine& command_line, SampleSettings& settings);

}  // namespace edgewise::sample_tool
