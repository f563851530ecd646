#include "common/tool_app.hpp"

#include <memory>
#include <utility>

namespace edgewise::tools {
namespace {

class ToolHelp : public CLI::Formatter {
 public:
  explicit ToolHelp(std::vector<std::string> usage) : usage_(std::move(usage)) { column_width(28); }

  std::string make_usage(const CLI::App* app, std::string name) const override {
    if (name.empty()) name = app->get_name();
    std::string text;
    for (std::size_t i = 0; i < usage_.size(); ++i)
      text += (i == 0 ? "usage: " : "       ") + name + " " + usage_[i] + "\n";
    return text;
  }

  std::string make_help(const CLI::App* app, std::string name,
                        CLI::AppFormatMode mode) const override {
    if (mode == CLI::AppFormatMode::Sub) return make_expanded(app);
    std::string description = make_description(app);
    if (!description.empty()) description = "\n" + description;
    return make_usage(app, std::move(name)) + description + make_positionals(app) +
           make_groups(app, mode) + "\n" + make_footer(app);
  }

 private:
  std::vector<std::string> usage_;
};

}  // namespace

void apply_tool_conventions(CLI::App& app, std::vector<std::string> usage) {
  app.formatter(std::make_shared<ToolHelp>(std::move(usage)));
  app.option_defaults()->multi_option_policy(CLI::MultiOptionPolicy::TakeLast);
}

}  // namespace edgewise::tools
