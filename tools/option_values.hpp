// The values the command-line tools parse from their options, with the messages they give for a
// mistake: "OPTION 'text' is not an integer in lo..hi", "... is not a finite number", "unknown
// OPTION value 'text'; expected NAMES". Each tool throws its own UsageError (its exit status),
// so the parsers take it as a parameter: using Values = OptionValues<UsageError>.
#pragma once

#include <charconv>
#include <cmath>
#include <cstdint>
#include <optional>
#include <string>
#include <string_view>
#include <system_error>

namespace edgewise::tools {

// Appended piece by piece: GCC 12 warns falsely (-Wrestrict) on "'" + std::string + "'" inlined.
inline std::string quoted(std::string_view text) {
  std::string result;
  result.reserve(text.size() + 2);
  result += '\'';
  result += text;
  result += '\'';
  return result;
}

// The whole of `text` as a number, or nullopt.
inline std::optional<std::int64_t> parse_integer(std::string_view text) {
  std::int64_t value = 0;
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(text.data(), last, value);
  if (ec != std::errc() || end != last || text.empty()) return std::nullopt;
  return value;
}

inline std::optional<float> parse_finite_float(std::string_view text) {
  float value = 0.0f;
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(text.data(), last, value);
  if (ec != std::errc() || end != last || !std::isfinite(value)) return std::nullopt;
  return value;
}

template <class Error>
struct OptionValues {
  static int integer_in(std::string_view option, std::string_view text, int lo, int hi) {
    const std::optional<std::int64_t> value = parse_integer(text);
    if (!value || *value < lo || *value > hi) {
      throw Error(std::string(option) + " " + quoted(text) + " is not an integer in " +
                  std::to_string(lo) + ".." + std::to_string(hi));
    }
    return static_cast<int>(*value);
  }

  static float number(std::string_view option, std::string_view text) {
    const std::optional<float> value = parse_finite_float(text);
    if (!value) throw Error(std::string(option) + " " + quoted(text) + " is not a finite number");
    return *value;
  }

  // `parse` is one of the library's name parsers; `names` lists the accepted values.
  template <class Parse>
  static auto named(std::string_view option, std::string_view text, Parse parse,
                    std::string_view names) {
    const auto value = parse(text);
    if (!value) {
      throw Error("unknown " + std::string(option) + " value " + quoted(text) + "; expected " +
                  std::string(names));
    }
    return *value;
  }
};

}  // namespace edgewise::tools
