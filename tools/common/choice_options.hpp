// Options whose value is one of a list of names: the help lists the names, and any other
// value throws UsageError("unknown --filter value 'x'; expected nearest, bilinear, ... or ewa").
// The API's enums give their names themselves (edgewise/names.hpp: values_of, name_of).
#pragma once

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "common/command_line.hpp"
#include "edgewise/names.hpp"

namespace edgewise::tools {

// "a, b or c".
std::string name_list(const std::vector<std::string>& names);

// An option NAME VALUE whose value is one of `names`; `choose(i)` is called with the index of
// the name given.
Option add_choice_option(CommandLine& line, const std::string& name, std::vector<std::string> names,
                         std::function<void(std::size_t)> choose, const std::string& description);

// An option whose value names one of `values` through `name_of_value` into `value`.
template <class T, class NameOf>
Option add_named_option(CommandLine& line, const std::string& name, T& value, std::vector<T> values,
                        NameOf name_of_value, const std::string& description) {
  std::vector<std::string> names;
  for (const T& v : values)
    names.emplace_back(name_of_value(v));
  return add_choice_option(
      line, name, std::move(names),
      [&value, values = std::move(values)](std::size_t i) { value = values[i]; }, description);
}

// An option whose value is the name of one of the enum's values (edgewise/names.hpp).
template <class Enum>
Option add_enum_option(CommandLine& line, const std::string& name, Enum& value,
                       const std::string& description) {
  const std::span<const Enum> values = values_of<Enum>();
  return add_named_option(
      line, name, value, std::vector<Enum>(values.begin(), values.end()),
      [](Enum v) { return name_of(v); }, description);
}

}  // namespace edgewise::tools
