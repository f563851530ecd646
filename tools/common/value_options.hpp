// Options whose value the tools read themselves, so that a mistake gets the tools' message
// (option_values.hpp) and exit status (UsageError). The value is read when the whole command line
// has been taken in, before the tool does any work; the last of an option given twice wins
// (tool_app.hpp).
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <utility>

#include "common/command_line.hpp"

namespace edgewise::tools {

// An option NAME VALUE stored into `value` as `parse(text)` returns it; `parse` throws
// UsageError for a mistake.
template <class T, class Parse>
Option add_parsed_option(CommandLine& line, const std::string& name, T& value, Parse parse,
                         const std::string& description) {
  return line.add_value(
      name, [&value, parse = std::move(parse)](const std::string& text) { value = parse(text); },
      description);
}

// An integer in [lo, hi] (type name N).
Option add_integer_option(CommandLine& line, const std::string& name, int& value, int lo, int hi,
                          const std::string& description);
// A finite number (type name F).
Option add_number_option(CommandLine& line, const std::string& name, float& value,
                         const std::string& description);
// A memory limit in MiB, 1 to 2^20 (1 TiB), stored in bytes (type name MB).
Option add_mebibytes_option(CommandLine& line, const std::string& name, std::uint64_t& bytes,
                            const std::string& description);
// A path or other text that may not be empty ("NAME needs a non-empty path").
Option add_path_option(CommandLine& line, const std::string& name,
                       std::optional<std::string>& value, const std::string& description);

}  // namespace edgewise::tools
