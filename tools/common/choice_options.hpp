// CLI11 options whose value is one of a list of names: the help lists the names, and any other
// value throws UsageError("unknown --filter value 'x'; expected nearest, bilinear, ... or ewa").
// The API's enums give their names themselves (edgewise/names.hpp: values_of, name_of).
#pragma once

#include <CLI/CLI.hpp>

#include <functional>
#include <span>
#include <string>
#include <string_view>
#include <utility>
#include <vector>

#include "edgewise/names.hpp"

namespace edgewise::tools {

// "a, b or c".
std::string name_list(const std::vector<std::string>& names);

// A CLI11 check that accepts exactly `names` (its description, shown by the help, lists them).
CLI::Validator one_of(const std::string& option, std::vector<std::string> names);

// An option NAME VALUE whose value is one of `names`; `choose(i)` is called with the index of
// the name given.
CLI::Option* add_choice_option(CLI::App& app, const std::string& name,
                               std::vector<std::string> names,
                               std::function<void(std::size_t)> choose,
                               const std::string& description);

// An option whose value names one of `values` through `name_of_value` into `value`.
template <class T, class NameOf>
CLI::Option* add_named_option(CLI::App& app, const std::string& name, T& value,
                              std::vector<T> values, NameOf name_of_value,
                              const std::string& description) {
  std::vector<std::string> names;
  for (const T& v : values)
    names.emplace_back(name_of_value(v));
  return add_choice_option(
      app, name, std::move(names),
      [&value, values = std::move(values)](std::size_t i) { value = values[i]; }, description);
}

// An option whose value is the name of one of the enum's values (edgewise/names.hpp).
template <class Enum>
CLI::Option* add_enum_option(CLI::App& app, const std::string& name, Enum& value,
                             const std::string& description) {
  const std::span<const Enum> values = values_of<Enum>();
  return add_named_option(
      app, name, value, std::vector<Enum>(values.begin(), values.end()),
      [](Enum v) { return name_of(v); }, description);
}

}  // namespace edgewise::tools
