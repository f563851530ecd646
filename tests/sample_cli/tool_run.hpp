// Running edgewise-sample from a test: its exit status and what it printed.
#pragma once

#include <optional>
#include <string>
#include <vector>

namespace edgewise::sample_cli_test {

struct ToolRun {
  int status = -1;  // the exit status; 128 + the signal's number when the tool was killed
  std::string out, err;

  // The exit status and, for a failure, standard error, for assertion messages.
  std::string summary() const;
};

// Runs the tool with `args` through /bin/sh, capturing standard output and error in files of
// `scratch_directory`. With `piped_input`, that file is copied into the tool's standard input
// through a pipe (for --queries /dev/stdin).
ToolRun run_sample_tool(const std::vector<std::string>& args, const std::string& scratch_directory,
                        const std::optional<std::string>& piped_input = std::nullopt);

}  // namespace edgewise::sample_cli_test
