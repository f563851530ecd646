// Names of enum values, one convention for every enum of the API: name_of(value) is the value's
// name (lower case, as the tools' options spell it), values_of<Enum>() lists every value in
// order, and parse_name<Enum>(text) reads a name back (std::nullopt for anything else). The
// headers that define the enums declare name_of() and values_of<>() for each.
#pragma once

#include <optional>
#include <span>
#include <string_view>

namespace edgewise {

template <class Enum>
std::span<const Enum> values_of();

template <class Enum>
std::optional<Enum> parse_name(std::string_view text) {
  for (Enum value : values_of<Enum>()) {
    if (name_of(value) == text) return value;
  }
  return std::nullopt;
}

}  // namespace edgewise
