// Reading numbers from the command line, with the messages the tools give for a mistake:
// "LABEL 'text' is not an integer in lo..hi", "LABEL 'text' is not a finite number". LABEL is the
// option ("--repeat") or the argument's name ("width"). Mistakes throw UsageError.
#pragma once

#include <cstdint>
#include <optional>
#include <string>
#include <string_view>

namespace edgewise::tools {

// 'text', quoted for a message. (Appended piece by piece: g++ 12 warns falsely (-Wrestrict) on
// "'" + std::string + "'" inlined.)
std::string quoted(std::string_view text);

// The whole of `text` as a number, or nullopt.
std::optional<std::int64_t> parse_integer(std::string_view text);
std::optional<std::uint64_t> parse_unsigned(std::string_view text);
std::optional<float> parse_finite_float(std::string_view text);

// The whole of `text` as an integer in [lo, hi]; otherwise throws UsageError.
std::int64_t integer_in(std::string_view label, std::string_view text, std::int64_t lo,
                        std::int64_t hi);
std::uint64_t unsigned_in(std::string_view label, std::string_view text, std::uint64_t lo,
                          std::uint64_t hi);
// The whole of `text` as a finite float; otherwise throws UsageError.
float finite_number(std::string_view label, std::string_view text);

}  // namespace edgewise::tools
