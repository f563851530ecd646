#include "common/file_extension.hpp"

#include <algorithm>
#include <cctype>

namespace edgewise::tools {

std::size_t extension_start(std::string_view path) {
  const std::size_t slash = path.find_last_of('/');
  const std::size_t dot = path.find_last_of('.');
  if (dot == std::string_view::npos || (slash != std::string_view::npos && dot < slash)) {
    return path.size();
  }
  return dot;
}

std::string lower_case_extension(std::string_view path) {
  std::string extension(path.substr(extension_start(path)));
  std::transform(extension.begin(), extension.end(), extension.begin(),
                 [](unsigned char c) { return static_cast<char>(std::tolower(c)); });
  return extension;
}

}  // namespace edgewise::tools
