#include "tool_run.hpp"

#include <sys/wait.h>

#include <cstdlib>
#include <fstream>
#include <sstream>

namespace edgewise::sample_cli_test {
namespace {

// Appends `text` for /bin/sh: in single quotes, where only a single quote needs care. (Built
// with append: g++ 12 warns falsely (-Wrestrict) on some chains of string operator+.)
void append_quoted(std::string& command, const std::string& text) {
  command.push_back('\'');
  for (char c : text) {
    if (c == '\'') {
      command.append("'\\''");
    } else {
      command.push_back(c);
    }
  }
  command.push_back('\'');
}

std::string file_contents(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  std::ostringstream contents;
  contents << in.rdbuf();
  return contents.str();
}

}  // namespace

std::string ToolRun::summary() const {
  return "exit status " + std::to_string(status) + (status == 0 ? "" : ", stderr: " + err);
}

ToolRun run_sample_tool(const std::vector<std::string>& args, const std::string& scratch_directory,
                        const std::optional<std::string>& piped_input) {
  const std::string out_path = scratch_directory + "/tool.stdout";
  const std::string err_path = scratch_directory + "/tool.stderr";
  std::string command;
  if (piped_input) {
    command.append("cat ");
    append_quoted(command, *piped_input);
    command.append(" | ");
  }
  append_quoted(command, EDGEWISE_SAMPLE_TOOL);
  for (const std::string& arg : args) {
    command.push_back(' ');
    append_quoted(command, arg);
  }
  command.append(" > ");
  append_quoted(command, out_path);
  command.append(" 2> ");
  append_quoted(command, err_path);

  const int wait_status = std::system(command.c_str());
  ToolRun run;
  // The shell reports a tool killed by a signal as 128 + the signal's number.
  run.status = WIFEXITED(wait_status) ? WEXITSTATUS(wait_status) : 128 + WTERMSIG(wait_status);
  run.out = file_contents(out_path);
  run.err = file_contents(err_path);
  return run;
}

}  // namespace edgewise::sample_cli_test
