#include "common/run_tool.hpp"

#include <CLI/CLI.hpp>

#include <cerrno>
#include <cstdio>
#include <cstring>
#include <iostream>
#include <new>

#include "common/tool_app.hpp"
#include "common/usage_error.hpp"

namespace edgewise::tools {
namespace {

int report(const std::string& name, const std::string& message, bool usage) {
  std::cout.flush();
  std::cerr << name << ": " << message;
  if (usage) std::cerr << " (" << name << " --help for usage)";
  std::cerr << '\n';
  return usage ? kUsageExitStatus : kFailureExitStatus;
}

// Standard output is an output file too: a full disk behind `> file` fails the tool. Returns the
// error's description, or an empty string when everything printed was written.
std::string standard_output_failure() {
  std::cout.flush();
  errno = 0;
  const bool flushed = std::fflush(stdout) == 0;
  const int error = errno;
  if (flushed && !std::ferror(stdout) && !std::cout.fail()) return {};
  return std::string("standard output: cannot write: ") +
         (error != 0 ? std::strerror(error) : "write error");
}

}  // namespace

int run_tool(int argc, char** argv, const std::string& name, std::vector<std::string> usage,
             const std::function<ToolWork(CommandLine&)>& configure) {
  const auto finished = [&name](int status) {
    const std::string output_failure = standard_output_failure();
    return output_failure.empty() ? status : report(name, output_failure, false);
  };
  try {
    CLI::App app("", name);
    apply_tool_conventions(app, std::move(usage));
    CommandLine line(app);
    const ToolWork work = configure(line);
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
      std::cout << app.help();
      return finished(0);
    } catch (const CLI::CallForAllHelp&) {
      std::cout << app.help("", CLI::AppFormatMode::All);
      return finished(0);
    }
    return finished(work());
  } catch (const CLI::ParseError& error) {
    return report(name, error.what(), true);
  } catch (const UsageError& error) {
    return report(name, error.what(), true);
  } catch (const std::bad_alloc&) {
    return report(name, "not enough memory", false);
  } catch (const std::exception& error) {
    return report(name, error.what(), false);
  }
}

}  // namespace edgewise::tools
