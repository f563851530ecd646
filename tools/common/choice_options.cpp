#include "common/choice_options.hpp"

#include <algorithm>
#include <memory>

namespace edgewise::tools {

std::string name_list(const std::vector<std::string>& names) {
  std::string list;
  for (std::size_t i = 0; i < names.size(); ++i) {
    if (i > 0) list += i + 1 == names.size() ? " or " : ", ";
    list += names[i];
  }
  return list;
}

Option add_choice_option(CommandLine& line, const std::string& name, std::vector<std::string> names,
                         std::function<void(std::size_t)> choose, const std::string& description) {
  auto shared = std::make_shared<const std::vector<std::string>>(names);
  return line
      .add_value(
          name,
          [shared, choose = std::move(choose)](const std::string& text) {
            const auto found = std::find(shared->begin(), shared->end(), text);
            choose(static_cast<std::size_t>(found - shared->begin()));
          },
          description)
      .type_name("NAME")
      .one_of(std::move(names));
}

}  // namespace edgewise::tools
