// A mistake on a tool's command line (an unknown option or name, a value out of range, options
// that do not go together, an EDGEWISE_ISA this machine cannot run): the tool writes one line on
// standard error and exits with kUsageExitStatus. Any other failure (a file that cannot be read
// or written, invalid contents) exits with kFailureExitStatus. run_tool.hpp does both.
#pragma once

#include <stdexcept>

namespace edgewise::tools {

inline constexpr int kFailureExitStatus = 1;
inline constexpr int kUsageExitStatus = 2;

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace edgewise::tools
