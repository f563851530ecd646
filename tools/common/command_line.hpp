// A tool's command line: its options, their help and their rules, over CLI11. Only tools/common's
// command_line.cpp, tool_app.cpp and run_tool.cpp include CLI11: its header is most of the compile
// time of any file that includes it (several seconds at -O3, more under the sanitizers), and the
// tools' units need none of it. run_tool() makes the CommandLine and parses it.
//
// An option's value reaches the tool as written, through a function that stores it and throws
// UsageError for a mistake (value_options.hpp, choice_options.hpp do this for numbers and names),
// so that every mistake gets the tools' message and exit status.
#pragma once

#include <cstddef>
#include <functional>
#include <optional>
#include <string>
#include <vector>

namespace CLI {
class App;
class Option;
}  // namespace CLI

namespace edgewise::tools {

// One option of a CommandLine, to give its help and its rules. A handle: copies name the same
// option.
class Option {
 public:
  // The value's name in the help ("FILE"; "" for none).
  Option& type_name(const std::string& name);
  // The heading the help lists it under.
  Option& group(const std::string& group);
  // A command line without it is a usage error.
  Option& required();
  // Giving both is a usage error ("THIS excludes OTHER").
  Option& excludes(const Option& other);
  // Any value but one of `names` is a usage error ("unknown --filter value 'x'; expected a, b or
  // c"); the help lists the names.
  Option& one_of(std::vector<std::string> names);

  // "--filter", or a positional's name.
  std::string name() const;
  std::string group_name() const;
  // How many times it was given.
  std::size_t count() const;
  // Its values as given, in order (one per time for an option that takes a value).
  std::vector<std::string> values() const;

  bool operator==(const Option& other) const { return option_ == other.option_; }

 private:
  friend class CommandLine;
  explicit Option(CLI::Option* option) : option_(option) {}
  CLI::Option* option_;
};

class CommandLine {
 public:
  explicit CommandLine(CLI::App& app) : app_(&app) {}

  // The help's paragraph after the usage lines, and its last lines.
  void description(const std::string& text);
  void footer(const std::string& text);

  // NAME VALUE (or a positional NAME, when it has no leading dash): `store` receives the value as
  // written each time it is given, the last time last (a tool's options keep their last value).
  Option add_value(const std::string& name, std::function<void(const std::string&)> store,
                   const std::string& description);
  // NAME VALUE, repeatable: `store` receives every value given, in order, once all are read.
  Option add_values(const std::string& name,
                    std::function<void(const std::vector<std::string>&)> store,
                    const std::string& description);
  // A flag: sets `value` when given.
  Option add_flag(const std::string& name, bool& value, const std::string& description);
  // A flag: calls `given` when given.
  Option add_flag(const std::string& name, std::function<void()> given,
                  const std::string& description);

  // An option added before, by name. Throws std::logic_error if there is none.
  Option option(const std::string& name) const;
  // How many times the option named was given.
  std::size_t count(const std::string& name) const;
  // The options as they were given, in order, an option once each time.
  std::vector<Option> given_in_order() const;

 private:
  CLI::App* app_;
};

// A text value as written, into `value`.
Option add_text_option(CommandLine& line, const std::string& name, std::string& value,
                       const std::string& description);
Option add_text_option(CommandLine& line, const std::string& name,
                       std::optional<std::string>& value, const std::string& description);

}  // namespace edgewise::tools
