// The conventions every tool's CLI11 App follows: --help starts with the tool's usage lines
// ("usage: edgewise-coverage W H TRIANGLES ...") and the description, then lists the options in
// their groups, with the footer last; an option given twice keeps its last value, as the tools
// always have.
#pragma once

#include <CLI/CLI.hpp>

#include <string>
#include <vector>

namespace edgewise::tools {

// `usage` holds the lines after the tool's name: {"W H TRIANGLES [-o FILE]", ...}.
void apply_tool_conventions(CLI::App& app, std::vector<std::string> usage);

}  // namespace edgewise::tools
