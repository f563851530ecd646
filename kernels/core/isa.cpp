#include "edgewise/isa.hpp"

#include <iterator>
#include <atomic>
#include <cstdlib>
#include <stdexcept>
#include <string>

#include "isa_list.hpp"

namespace edgewise {
namespace {

// Every value of the enum, in its order: isa_list.hpp's list must name them all.
constexpr Isa kEvery[] = {
#define EDGEWISE_ISA_VALUE(name) Isa::name,
    EDGEWISE_FOR_EACH_ISA(EDGEWISE_ISA_VALUE)
#undef EDGEWISE_ISA_VALUE
};
constexpr bool in_enum_order() {
  for (int i = 0; i < static_cast<int>(std::size(kEvery)); ++i) {
    if (static_cast<int>(kEvery[i]) != i) return false;
  }
  return true;
}
static_assert(in_enum_order(), "EDGEWISE_FOR_EACH_ISA must list the Isa enum in its order");

constexpr std::string_view kNames[] = {
#define EDGEWISE_ISA_NAME(name) #name,
    EDGEWISE_FOR_EACH_ISA(EDGEWISE_ISA_NAME)
#undef EDGEWISE_ISA_NAME
};

constexpr Isa kCompiled[] = {Isa::reference,
#define EDGEWISE_COMPILED_ISA(name, arch, cpu_check) Isa::name,
                             EDGEWISE_FOR_EACH_SIMD_ISA(EDGEWISE_COMPILED_ISA)
#undef EDGEWISE_COMPILED_ISA
};

bool cpu_has(Isa isa) {
  switch (isa) {
    case Isa::reference:
      return true;
#define EDGEWISE_CPU_CHECK(name, arch, cpu_check) \
  case Isa::name:                                 \
    return cpu_check;
      EDGEWISE_FOR_EACH_SIMD_ISA(EDGEWISE_CPU_CHECK)
#undef EDGEWISE_CPU_CHECK
    default:
      return false;
  }
}

constexpr int kNoOverride = -1;
std::atomic<int> forced{kNoOverride};

std::string supported_list() {
  std::string names;
  for (Isa isa : supported_isas()) {
    if (!names.empty()) names += ", ";
    names += name_of(isa);
  }
  return names;
}

// The one wording of each refusal, wherever an ISA is named.
std::string unknown_isa(std::string_view name) {
  return "unknown ISA '" + std::string(name) + "'; this machine supports " + supported_list();
}
std::string unsupported_isa(std::string_view name) {
  return "ISA " + std::string(name) + " is not supported on this machine; it supports " +
         supported_list();
}

Isa isa_from_environment() {
  const char* value = std::getenv("EDGEWISE_ISA");
  if (value == nullptr || *value == '\0') return best_isa();
  const std::optional<Isa> isa = parse_name<Isa>(value);
  if (!isa)
    throw std::invalid_argument(std::string("EDGEWISE_ISA=") + value + ": " + unknown_isa(value));
  if (!isa_supported(*isa)) {
    throw std::invalid_argument(std::string("EDGEWISE_ISA=") + value + ": " +
                                unsupported_isa(value));
  }
  return *isa;
}

}  // namespace

std::string_view name_of(Isa isa) {
  const auto index = static_cast<std::size_t>(isa);
  return index < std::size(kNames) ? kNames[index] : "unknown";
}

template <>
std::span<const Isa> values_of<Isa>() {
  return kEvery;
}

std::span<const Isa> compiled_isas() {
  return kCompiled;
}

bool isa_supported(Isa isa) {
  for (Isa compiled : kCompiled) {
    if (compiled == isa) return cpu_has(isa);
  }
  return false;
}

std::vector<Isa> supported_isas() {
  std::vector<Isa> isas;
  for (Isa isa : kCompiled) {
    if (cpu_has(isa)) isas.push_back(isa);
  }
  return isas;
}

Isa best_isa() {
  return supported_isas().back();
}

Isa active_isa() {
  const int override_isa = forced.load(std::memory_order_relaxed);
  if (override_isa != kNoOverride) return static_cast<Isa>(override_isa);
  static const Isa from_environment = isa_from_environment();
  return from_environment;
}

void force_isa(std::optional<Isa> isa) {
  if (isa && !isa_supported(*isa)) {
    throw std::invalid_argument("force_isa: " + unsupported_isa(name_of(*isa)));
  }
  forced.store(isa ? static_cast<int>(*isa) : kNoOverride, std::memory_order_relaxed);
}

Isa resolve_isa(std::optional<Isa> requested) {
  // An explicit ISA must not consult EDGEWISE_ISA (which may name one this CPU lacks).
  if (!requested) return active_isa();
  if (!isa_supported(*requested)) throw std::invalid_argument(unsupported_isa(name_of(*requested)));
  return *requested;
}

ScopedIsa::ScopedIsa(Isa isa) {
  const int previous = forced.load(std::memory_order_relaxed);
  if (previous != kNoOverride) previous_ = static_cast<Isa>(previous);
  force_isa(isa);
}

ScopedIsa::~ScopedIsa() {
  force_isa(previous_);
}

Isa parse_supported_isa(std::string_view name) {
  const std::optional<Isa> isa = parse_name<Isa>(name);
  if (!isa) throw std::invalid_argument(unknown_isa(name));
  if (!isa_supported(*isa)) throw std::invalid_argument(unsupported_isa(name));
  return *isa;
}

}  // namespace edgewise
