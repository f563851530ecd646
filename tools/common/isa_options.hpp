// --isa NAME and --reference, the ISA a tool runs: NAME must be an ISA this machine supports
// (parse_supported_isa(), whose message names the ones it does), and without either option the
// tool runs active_isa(): the best ISA of this CPU, or EDGEWISE_ISA.
#pragma once

#include <optional>
#include <string>
#include <vector>

#include "common/command_line.hpp"
#include "edgewise/isa.hpp"

namespace edgewise::tools {

// --isa NAME and --reference (the scalar reference), at most one of them, into `isa`.
void add_isa_options(CommandLine& line, std::optional<Isa>& isa, const std::string& isa_description,
                     const std::string& reference_description);

// --isa NAME, repeatable, and --reference, appended to `isas` in the order given. An ISA named
// twice throws UsageError("ISA 'x' given twice").
void add_isa_list_options(CommandLine& line, std::vector<Isa>& isas,
                          const std::string& isa_description,
                          const std::string& reference_description);

// resolve_isa(requested): the ISA named on the command line, or active_isa(). Throws UsageError
// ("EDGEWISE_ISA: ...") when EDGEWISE_ISA names an ISA this machine cannot run.
Isa tool_isa(std::optional<Isa> requested);

}  // namespace edgewise::tools
