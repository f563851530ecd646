#include "common/run_tool.hpp"

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

}  // namespace

int run_tool(int argc, char** argv, const std::string& name, std::vector<std::string> usage,
             const std::function<ToolWork(CLI::App&)>& configure) {
  try {
    CLI::App app("", name);
    apply_tool_conventions(app, std::move(usage));
    const ToolWork work = configure(app);
    try {
      app.parse(argc, argv);
    } catch (const CLI::CallForHelp&) {
      std::cout << app.help();
      return 0;
    } catch (const CLI::CallForAllHelp&) {
      std::cout << app.help("", CLI::AppFormatMode::All);
      return 0;
    }
    return work();
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
