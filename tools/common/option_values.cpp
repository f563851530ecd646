#include "common/option_values.hpp"

#include <charconv>
#include <cmath>
#include <system_error>

#include "common/usage_error.hpp"

namespace edgewise::tools {
namespace {

template <class Number>
std::optional<Number> parse_whole(std::string_view text) {
  Number value{};
  const char* last = text.data() + text.size();
  const auto [end, ec] = std::from_chars(text.data(), last, value);
  if (ec != std::errc() || end != last || text.empty()) return std::nullopt;
  return value;
}

UsageError not_an_integer(std::string_view label, std::string_view text, const std::string& lo,
                          const std::string& hi) {
  return UsageError(std::string(label) + " " + quoted(text) + " is not an integer in " + lo + ".." +
                    hi);
}

}  // namespace

std::string quoted(std::string_view text) {
  std::string result;
  result.reserve(text.size() + 2);
  result += '\'';
  result += text;
  result += '\'';
  return result;
}

std::optional<std::int64_t> parse_integer(std::string_view text) {
  return parse_whole<std::int64_t>(text);
}

std::optional<std::uint64_t> parse_unsigned(std::string_view text) {
  return parse_whole<std::uint64_t>(text);
}

std::optional<float> parse_finite_float(std::string_view text) {
  const std::optional<float> value = parse_whole<float>(text);
  if (!value || !std::isfinite(*value)) return std::nullopt;
  return value;
}

std::int64_t integer_in(std::string_view label, std::string_view text, std::int64_t lo,
                        std::int64_t hi) {
  const std::optional<std::int64_t> value = parse_integer(text);
  if (!value || *value < lo || *value > hi) {
    throw not_an_integer(label, text, std::to_string(lo), std::to_string(hi));
  }
  return *value;
}

std::uint64_t unsigned_in(std::string_view label, std::string_view text, std::uint64_t lo,
                          std::uint64_t hi) {
  const std::optional<std::uint64_t> value = parse_unsigned(text);
  if (!value || *value < lo || *value > hi) {
    throw not_an_integer(label, text, std::to_string(lo), std::to_string(hi));
  }
  return *value;
}

float finite_number(std::string_view label, std::string_view text) {
  const std::optional<float> value = parse_finite_float(text);
  if (!value) throw UsageError(std::string(label) + " " + quoted(text) + " is not a finite number");
  return *value;
}

}  // namespace edgewise::tools
