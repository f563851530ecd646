// A mistake on edgewise-sample's command line (an unknown option or name, a value out of range,
// a missing option): exit status 2, as opposed to a file that cannot be read or written or whose
// contents are invalid (exit status 1).
#pragma once

#include <stdexcept>

namespace edgewise::sample_tool {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace edgewise::sample_tool
