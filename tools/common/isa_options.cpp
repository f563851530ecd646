#include "common/isa_options.hpp"

#include <algorithm>
#include <stdexcept>

#include "common/option_values.hpp"
#include "common/usage_error.hpp"

namespace edgewise::tools {
namespace {

// parse_supported_isa() with its message as a UsageError.
Isa parse_isa(const std::string& name) {
  try {
    return parse_supported_isa(name);
  } catch (const std::invalid_argument& error) {
    throw UsageError(error.what());
  }
}

// What the help shows for NAME: the ISAs this machine supports.
std::string supported_isa_names() {
  std::string names = "{";
  for (Isa isa : supported_isas())
    names += (names.size() > 1 ? "," : "") + std::string(name_of(isa));
  return names + "}";
}

}  // namespace

void add_isa_options(CommandLine& line, std::optional<Isa>& isa, const std::string& isa_description,
                     const std::string& reference_description) {
  const Option named =
      line.add_value(
              "--isa", [&isa](const std::string& name) { isa = parse_isa(name); }, isa_description)
          .type_name("NAME:" + supported_isa_names());
  line.add_flag(
      "--reference",
      [&isa, named] {
        // --isa's function, added first, has run when it was given.
        if (named.count() > 0) throw UsageError("give at most one of --isa and --reference");
        isa = Isa::reference;
      },
      reference_description);
}

void add_isa_list_options(CommandLine& line, std::vector<Isa>& isas,
                          const std::string& isa_description,
                          const std::string& reference_description) {
  // Each option's values are kept apart; the order of --isa and --reference between them is the
  // order the command line gave them in, read once both options' functions may have run.
  const auto collect = [line, &isas] {
    const Option named = line.option("--isa"), reference = line.option("--reference");
    const std::vector<std::string> names = named.values();
    std::vector<Isa> given;
    std::size_t next_name = 0;
    for (const Option& option : line.given_in_order()) {
      Isa isa = Isa::reference;
      if (option == named) {
        isa = parse_isa(names.at(next_name++));
      } else if (!(option == reference)) {
        continue;
      }
      if (std::find(given.begin(), given.end(), isa) != given.end()) {
        throw UsageError("ISA " + tools::quoted(name_of(isa)) + " given twice");
      }
      given.push_back(isa);
    }
    isas = std::move(given);
  };
  line.add_values(
          "--isa", [collect](const std::vector<std::string>&) { collect(); }, isa_description)
      .type_name("NAME:" + supported_isa_names());
  line.add_flag("--reference", collect, reference_description);
}

Isa tool_isa(std::optional<Isa> requested) {
  try {
    return resolve_isa(requested);
  } catch (const std::invalid_argument& error) {
    throw UsageError(std::string(requested ? "" : "EDGEWISE_ISA: ") + error.what());
  }
}

}  // namespace edgewise::tools
