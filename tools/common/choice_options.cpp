#include "common/choice_options.hpp"

#include <algorithm>
#include <memory>

#include "common/option_values.hpp"
#include "common/usage_error.hpp"

namespace edgewise::tools {

std::string name_list(const std::vector<std::string>& names) {
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) list += i + 1 == names.size() ? " or " : ", ";
    list += names[i];
  }
  return list;
}

CLI::Validator one_of(const std::string& option, std::vector<std::string> names) {
  std::string description = "{";
  for (const std::string& name : names)
    description += (description.size() > 1 ? "," : "") + name;
  description += "}";
  return CLI::Validator(
      [option, names = std::move(names)](std::string& text) -> std::string {
        if (std::find(names.begin(), names.end(), text) == names.end()) {
          throw UsageError("unknown " + option + " value " + tools::quoted(text) + "; expected " +
                           name_list(names));
        }
        return {};
      },
      description);
}

CLI::Option* add_choice_option(CLI::App& app, const std::string& name,
                               std::vector<std::string> names,
                               std::function<void(std::size_t)> choose,
                               const std::string& description) {
  auto shared = std::make_shared<const std::vector<std::string>>(names);
  return app
      .add_option_function<std::string>(
          name,
          [shared, choose = std::move(choose)](const std::string& text) {
            const auto found = std::find(shared->begin(), shared->end(), text);
            choose(static_cast<std::size_t>(found - shared->begin()));
          },
          description)
      ->type_name("NAME")
      ->check(one_of(name, std::move(names)));
}

}  // namespace edgewise::tools
