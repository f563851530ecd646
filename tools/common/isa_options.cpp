#include "common/isa_options.hpp"

#include <algorithm>
#include <memory>
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

void add_isa_options(CLI::App& app, std::optional<Isa>& isa, const std::string& isa_description,
                     const std::string& reference_description) {
  CLI::Option* named =
      app.add_option_function<std::string>(
             "--isa", [&isa](const std::string& name) { isa = parse_isa(name); }, isa_description)
          ->type_name("NAME:" + supported_isa_names());
  app.add_flag_callback(
      "--reference",
      [&isa, named] {
        // --isa's callback, defined first, has run when it was given.
        if (named->count() > 0) throw UsageError("give at most one of --isa and --reference");
        isa = Isa::reference;
      },
      reference_description);
}

void add_isa_list_options(CLI::App& app, std::vector<Isa>& isas, const std::string& isa_description,
                          const std::string& reference_description) {
  // CLI11 keeps each option's values apart; the order of --isa and --reference between them is
  // in the app's parse order, read once both options' callbacks may have run.
  struct Options {
    CLI::Option* named = nullptr;
    CLI::Option* reference = nullptr;
  };
  auto options = std::make_shared<Options>();
  const auto collect = [&app, &isas, options] {
    std::vector<Isa> given;
    std::size_t next_name = 0;
    for (const CLI::Option* option : app.parse_order()) {
      Isa isa = Isa::reference;
      if (option == options->named) {
        isa = parse_isa(options->named->results().at(next_name++));
      } else if (option != options->reference) {
        continue;
      }
      if (std::find(given.begin(), given.end(), isa) != given.end()) {
        throw UsageError("ISA " + tools::quoted(name_of(isa)) + " given twice");
      }
      given.push_back(isa);
    }
    isas = std::move(given);
  };
  options->named =
      app.add_option_function<std::vector<std::string>>(
             "--isa", [collect](const std::vector<std::string>&) { collect(); }, isa_description)
          ->type_name("NAME:" + supported_isa_names())
          ->multi_option_policy(CLI::MultiOptionPolicy::TakeAll)
          ->allow_extra_args(false);
  options->reference = app.add_flag_callback("--reference", collect, reference_description);
}

Isa tool_isa(std::optional<Isa> requested) {
  try {
    return resolve_isa(requested);
  } catch (const std::invalid_argument& error) {
    throw UsageError(std::string(requested ? "" : "EDGEWISE_ISA: ") + error.what());
  }
}

}  // namespace edgewise::tools
