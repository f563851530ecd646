#include "common/value_options.hpp"

#include "common/option_values.hpp"
#include "common/usage_error.hpp"

namespace edgewise::tools {

Option add_integer_option(CommandLine& line, const std::string& name, int& value, int lo, int hi,
                          const std::string& description) {
  const auto parse = [name, lo, hi](const std::string& text) {
    return static_cast<int>(integer_in(name, text, lo, hi));
  };
  return add_parsed_option(line, name, value, parse, description).type_name("N");
}

Option add_number_option(CommandLine& line, const std::string& name, float& value,
                         const std::string& description) {
  const auto parse = [name](const std::string& text) { return finite_number(name, text); };
  return add_parsed_option(line, name, value, parse, description).type_name("F");
}

Option add_mebibytes_option(CommandLine& line, const std::string& name, std::uint64_t& bytes,
                            const std::string& description) {
  const auto parse = [name](const std::string& text) {
    return unsigned_in(name, text, 1, std::uint64_t{1} << 20) << 20;
  };
  return add_parsed_option(line, name, bytes, parse, description).type_name("MB");
}

Option add_path_option(CommandLine& line, const std::string& name,
                       std::optional<std::string>& value, const std::string& description) {
  const auto parse = [name](const std::string& text) {
    if (text.empty()) throw UsageError(name + " needs a non-empty path");
    return std::optional<std::string>(text);
  };
  return add_parsed_option(line, name, value, parse, description);
}

}  // namespace edgewise::tools
