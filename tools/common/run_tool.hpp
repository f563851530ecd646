// A tool's main(): makes its command line (tool_app.hpp's conventions), lets `configure` add the
// options, parses the command line, then runs the work `configure` returned.
//
//   --help                        CLI11's help on standard output; exit status 0
//   a mistake on the command      "<tool>: <message> (<tool> --help for usage)" on standard
//   line: CLI11's parse errors,   error; exit status kUsageExitStatus (2)
//   UsageError
//   any other exception           "<tool>: <message>" ("not enough memory" for std::bad_alloc);
//                                 exit status kFailureExitStatus (1)
//   otherwise                     the work's exit status
#pragma once

#include <functional>
#include <string>
#include <vector>

#include "common/command_line.hpp"

namespace edgewise::tools {

using ToolWork = std::function<int()>;

// `name` is the tool's ("edgewise-coverage"); `usage` holds the usage lines after it.
int run_tool(int argc, char** argv, const std::string& name, std::vector<std::string> usage,
             const std::function<ToolWork(CommandLine&)>& configure);

}  // namespace edgewise::tools
