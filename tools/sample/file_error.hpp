// The one-line message for a file the tool cannot use: "PATH: cannot read: reason".
#pragma once

#include <cstring>
#include <stdexcept>
#include <string>
#include <string_view>

namespace edgewise::sample_tool {

// `action` says what failed ("cannot open", "cannot write"), `errnum` why (an errno value).
inline std::runtime_error file_error(std::string_view path, std::string_view action, int errnum) {
  return std::runtime_error(std::string(path) + ": " + std::string(action) + ": " +
                            std::strerror(errnum));
}

}  // namespace edgewise::sample_tool
