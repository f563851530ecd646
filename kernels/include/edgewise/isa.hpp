// Instruction sets: which kernels are compiled, which the CPU runs, and which one is used.
//
// The active ISA is, in order of precedence: a ScopedIsa/force_isa() override, the
// EDGEWISE_ISA environment variable (reference|sse2|sse4_1|avx2|avx512|neon), or the best ISA
// this CPU supports. `reference` is the scalar oracle, available everywhere.
//
// Thread safety: every function may be called from any thread. EDGEWISE_ISA is read once, at the
// first call that needs it. The override (force_isa(), ScopedIsa) is one value for the whole
// process, not per thread: setting it while other threads run entry points without an explicit
// ISA changes the ISA their next calls use. Code that runs several threads, and tests that force
// an ISA, should name the ISA in each call's options instead.
#pragma once

#include <optional>
#include <span>
#include <string_view>
#include <vector>

#include "edgewise/names.hpp"

namespace edgewise {

enum class Isa : int { reference, sse2, sse4_1, avx2, avx512, neon };

// ISAs built into this library, worst first (reference first).
std::span<const Isa> compiled_isas();
// Compiled and runnable on this CPU.
bool isa_supported(Isa isa);
std::vector<Isa> supported_isas();
Isa best_isa();
// The ISA `name` names, when this CPU supports it; otherwise throws std::invalid_argument with a
// message for people ("unknown ISA 'x'; this machine supports reference, sse2, ...").
Isa parse_supported_isa(std::string_view name);

// The ISA that entry points use when their options do not name one. Throws
// std::invalid_argument if EDGEWISE_ISA names an unknown or unsupported ISA.
Isa active_isa();

// The ISA an entry point runs: `requested` when given (without consulting EDGEWISE_ISA), else
// active_isa(). Throws std::invalid_argument if it is not supported here.
Isa resolve_isa(std::optional<Isa> requested);

// Process-wide override; std::nullopt returns to the environment/CPU choice.
// Throws std::invalid_argument for an ISA that is not supported here.
void force_isa(std::optional<Isa> isa);

// Forces an ISA for the lifetime of the object (tests, benchmarks), then restores.
class ScopedIsa {
 public:
  explicit ScopedIsa(Isa isa);
  ~ScopedIsa();
  ScopedIsa(const ScopedIsa&) = delete;
  ScopedIsa& operator=(const ScopedIsa&) = delete;

 private:
  std::optional<Isa> previous_;
};

// Names of the values (names.hpp).
std::string_view name_of(Isa value);
template <>
std::span<const Isa> values_of<Isa>();

}  // namespace edgewise
