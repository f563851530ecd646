// A mistake on edgewise-texture-quality's command line (an unknown option or name, a value out
// of range): exit status 2, as opposed to a file or directory that cannot be written (exit
// status 1).
#pragma once

#include <stdexcept>

namespace edgewise::texture_quality {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace edgewise::texture_quality
