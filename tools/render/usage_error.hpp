// A mistake on edgewise-render's command line or in what it names (a file, a value): reported as
// one line on standard error with exit status 1, as opposed to a failure of the program itself.
#pragma once

#include <stdexcept>

namespace edgewise::render_tool {

struct UsageError : std::runtime_error {
  using std::runtime_error::runtime_error;
};

}  // namespace edgewise::render_tool
