// edgewise-sample's command line: every option parsed and range-checked before any file is
// touched. Mistakes throw UsageError naming the option and the value.
#pragma once

#include <optional>
#include <span>
#include <string>
#include <string_view>

#include "edgewise/isa.hpp"
#include "edgewise/sample.hpp"
#include "edgewise/texture.hpp"

namespace edgewise::sample_tool {

extern const std::string_view kUsage;

struct SampleSettings {
  std::string texture_path;  // --texture
  std::string queries_path;  // --queries
  std::string output_path;   // --out
  SamplerOptions sampler;    // --filter, --wrap*, --lod, --lod-bias, --max-aniso, --taps
  PyramidFilter pyramid = PyramidFilter::box;  // --pyramid
  bool srgb = false;                           // --srgb
  std::optional<Isa> isa;                      // --isa or --reference; otherwise active_isa()
  bool help = false;
};

SampleSettings parse_command_line(std::span<char* const> args);

// The ISA to run: the one named on the command line, or active_isa(). Throws UsageError when
// EDGEWISE_ISA names an ISA this machine cannot run.
Isa resolve_isa(const SampleSettings& settings);

}  // namespace edgewise::sample_tool
