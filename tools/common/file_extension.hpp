// A file name's extension, as the tools choose a file's format by it.
#pragma once

#include <cstddef>
#include <string>
#include <string_view>

namespace edgewise::tools {

// Where the extension starts in `path` (at its last '.' after the last '/'); path.size() if none.
std::size_t extension_start(std::string_view path);

// The extension with its dot, in lower case (".png"); empty if none.
std::string lower_case_extension(std::string_view path);

}  // namespace edgewise::tools
