#include "commands.hpp"

namespace pneumachaos::cli {

void add_scenario_options(CLI::App* cmd, ScenarioArgs& args) {
  cmd->add_option("scenario", args.file, "scenario TOML file (default: built-in scenario)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--set", args.sets, "override a scenario key, e.g. --set circuit.S2_mm2=0.05");
}

}  // namespace pneumachaos::cli
