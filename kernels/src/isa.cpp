#include "edgewise/isa.hpp"

#include <array>
#include <atomic>
#include <cstdlib>
#include <stdexcept>
#include <string>

namespace edgewise {
namespace {

constexpr Isa kCompiled[] = {
    Isa::reference,
#if defined(__x86_64__) || defined(_M_X64)
    Isa::sse2,
    Isa::sse4_1,
    Isa::avx2,
#elif defined(__aarch64__)
    Isa::neon,
#endif
};

bool cpu_has(Isa isa) {
  switch (isa) {
    case Isa::reference:
      return true;
#if defined(__x86_64__)
    // GCC's checks include the OS's support for the wider registers (XGETBV).
    case Isa::sse2:
      return __builtin_cpu_supports("sse2");
    case Isa::sse4_1:
      return __builtin_cpu_supports("sse4.1");
    case Isa::avx2:
      return __builtin_cpu_supports("avx2") && __builtin_cpu_supports("fma");
#elif defined(__aarch64__)
    case Isa::neon:
      return true;  // Advanced SIMD is mandatory on AArch64
#endif
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
    names += isa_name(isa);
  }
  return names;
}

Isa isa_from_environment() {
  const char* value = std::getenv("EDGEWISE_ISA");
  if (value == nullptr || *value == '\0') return best_isa();
  const std::optional<Isa> isa = parse_isa(value);
  if (!isa) {
    throw std::invalid_argument(std::string("EDGEWISE_ISA=") + value +
                                ": unknown ISA; this machine supports " + supported_list());
  }
  if (!isa_supported(*isa)) {
    throw std::invalid_argument(std::string("EDGEWISE_ISA=") + value +
                                ": not supported here; this machine supports " + supported_list());
  }
  return *isa;
}

}  // namespace

std::string_view isa_name(Isa isa) {
  switch (isa) {
    case Isa::reference:
      return "reference";
    case Isa::sse2:
      return "sse2";
    case Isa::sse4_1:
      return "sse4_1";
    case Isa::avx2:
      return "avx2";
    case Isa::neon:
      return "neon";
  }
  return "unknown";
}

std::optional<Isa> parse_isa(std::string_view name) {
  for (Isa isa : {Isa::reference, Isa::sse2, Isa::sse4_1, Isa::avx2, Isa::neon}) {
    if (name == isa_name(isa)) return isa;
  }
  return std::nullopt;
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
    throw std::invalid_argument(std::string("force_isa: ") + std::string(isa_name(*isa)) +
                                " is not supported here; this machine supports " +
                                supported_list());
  }
  forced.store(isa ? static_cast<int>(*isa) : kNoOverride, std::memory_order_relaxed);
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
  std::string supported;
  for (Isa isa : supported_isas()) {
    if (!supported.empty()) supported += ", ";
    supported += isa_name(isa);
  }
  const std::optional<Isa> isa = parse_isa(name);
  if (!isa) {
    throw std::invalid_argument("unknown ISA '" + std::string(name) + "'; this machine supports " +
                                supported);
  }
  if (!isa_supported(*isa)) {
    throw std::invalid_argument("ISA " + std::string(name) +
                                " is not supported on this machine; it supports " + supported);
  }
  return *isa;
}

}  // namespace edgewise
