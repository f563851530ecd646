#include "common/value_options.hpp"

#include "common/option_values.hpp"
#include "common/usage_error.hpp"

namespace edgewise::tools {

CLI::Option* add_integer_option(CLI::App& app, const std::string& name, int& value, int lo, int hi,
                                const std::string& description) {
  const auto parse = [name, lo, hi](const std::string& text) {
    return static_cast<int>(integer_in(name, text, lo, hi));
  };
  return add_parsed_option(app, name, value, parse, description)->type_name("N");
}

CLI::Option* add_number_option(CLI::App& app, const std::string& name, float& value,
                               const std::string& description) {
  const auto parse = [name](const std::string& text) { return finite_number(name, text); };
  return add_parsed_option(app, name, value, parse, description)->type_name("F");
}

CLI::Option* add_mebibytes_option(CLI::App& app, const std::string& name, std::uint64_t& bytes,
                                  const std::string& description) {
  const auto parse = [name](const std::string& text) {
    return unsigned_in(name, text, 1, std::uint64_t{1} << 20) << 20;
  };
  return add_parsed_option(app, name, bytes, parse, description)->type_name("MB");
}

CLI::Option* add_path_option(CLI::App& app, const std::string& name,
                             std::optional<std::string>& value, const std::string& description) {
  const auto parse = [name](const std::string& text) {
    if (text.empty()) throw UsageError(name + " needs a non-empty path");
    return std::optional<std::string>(text);
  };
  return add_parsed_option(app, name, value, parse, description);
}

}  // namespace edgewise::tools
