// How `friction` and `fit` read a measured record (they live in the module that links identify).

#include "commands.hpp"
#include "pneumachaos/io/column_units.hpp"

namespace pneumachaos::cli {

identify::RecordReadOptions record_read_options(const Scenario& scenario, const ScenarioArgs& args,
                                                const std::vector<std::string>& units) {
  identify::RecordReadOptions read = identify::read_options_for(scenario);
  if (args.file.empty() && args.sets.empty()) read.plausible.supply_Pa.reset();
  read.units = parse_unit_overrides(units, "--units");
  return read;
}

}  // namespace pneumachaos::cli
