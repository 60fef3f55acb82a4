#include "commands.hpp"

namespace pneumachaos::cli {

void add_scenario_options(CLI::App* cmd, ScenarioArgs& args) {
  cmd->add_option("scenario", args.file, "scenario TOML file (default: built-in scenario)")
      ->check(CLI::ExistingFile);
  cmd->add_option("--set", args.sets, "override a scenario key, e.g. --set circuit.S2_mm2=0.05");
}

void add_record_column_options(CLI::App* cmd, identify::RecordColumns& columns) {
  cmd->add_option("--column-t", columns.t, "header name of the time column (default t, or time)");
  cmd->add_option("--column-v", columns.v, "header name of the velocity column (default v)");
  cmd->add_option("--column-P1", columns.P1, "header name of chamber 1's pressure (default P1)");
  cmd->add_option("--column-P2", columns.P2, "header name of chamber 2's pressure (default P2)");
  cmd->add_option("--column-x", columns.x, "header name of the position column (default x; optional)");
  cmd->add_option("--column-a", columns.a,
                  "header name of an acceleration column (default a; optional)");
}

}  // namespace pneumachaos::cli
