#include "common/command_line.hpp"

#include <CLI/CLI.hpp>

#include <algorithm>
#include <stdexcept>
#include <utility>

#include "common/choice_options.hpp"
#include "common/option_values.hpp"
#include "common/usage_error.hpp"

namespace edgewise::tools {

Option& Option::type_name(const std::string& name) {
  option_->type_name(name);
  return *this;
}

Option& Option::group(const std::string& group) {
  option_->group(group);
  return *this;
}

Option& Option::required() {
  option_->required();
  return *this;
}

Option& Option::excludes(const Option& other) {
  option_->excludes(other.option_);
  return *this;
}

Option& Option::one_of(std::vector<std::string> names) {
  std::string listed = "{";
  for (const std::string& name : names)
    listed += (listed.size() > 1 ? "," : "") + name;
  listed += "}";
  option_->check(CLI::Validator(
      [option = option_->get_name(), names = std::move(names)](std::string& text) -> std::string {
        if (std::find(names.begin(), names.end(), text) == names.end()) {
          throw UsageError("unknown " + option + " value " + tools::quoted(text) + "; expected " +
                           name_list(names));
        }
        return {};
      },
      listed));
  return *this;
}

std::string Option::name() const {
  return option_->get_name();
}

std::string Option::group_name() const {
  return option_->get_group();
}

std::size_t Option::count() const {
  return option_->count();
}

std::vector<std::string> Option::values() const {
  return option_->results();
}

void CommandLine::description(const std::string& text) {
  app_->description(text);
}

void CommandLine::footer(const std::string& text) {
  app_->footer(text);
}

Option CommandLine::add_value(const std::string& name,
                              std::function<void(const std::string&)> store,
                              const std::string& description) {
  return Option(app_->add_option_function<std::string>(name, std::move(store), description));
}

Option CommandLine::add_values(const std::string& name,
                               std::function<void(const std::vector<std::string>&)> store,
                               const std::string& description) {
  return Option(
      app_->add_option_function<std::vector<std::string>>(name, std::move(store), description)
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
          ->allow_extra_args(false));
}

Option CommandLine::add_flag(const std::string& name, bool& value, const std::string& description) {
  return Option(app_->add_flag(name, value, description));
}

Option CommandLine::add_flag(const std::string& name, std::function<void()> given,
                             const std::string& description) {
  return Option(app_->add_flag_callback(name, std::move(given), description));
}

Option CommandLine::option(const std::string& name) const {
  CLI::Option* option = app_->get_option_no_throw(name);
  if (option == nullptr) throw std::logic_error("no option " + name + " was added");
  return Option(option);
}

std::size_t CommandLine::count(const std::string& name) const {
  return option(name).count();
}

std::vector<Option> CommandLine::given_in_order() const {
  std::vector<Option> given;
  for (CLI::Option* option : app_->parse_order())
    given.push_back(Option(option));
  return given;
}

Option add_text_option(CommandLine& line, const std::string& name, std::string& value,
                       const std::string& description) {
  return line.add_value(
      name, [&value](const std::string& text) { value = text; }, description);
}

Option add_text_option(CommandLine& line, const std::string& name,
                       std::optional<std::string>& value, const std::string& description) {
  return line.add_value(
      name, [&value](const std::string& text) { value = text; }, description);
}

}  // namespace edgewise::tools
