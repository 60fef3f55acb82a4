// `pneumachaos simulate`: a time response as CSV.

#include <fmt/format.h>

#include <cstdint>
#include <optional>

#include "commands.hpp"
#include "stage_progress.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/simulate/measured_channels.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "pneumachaos/stability/run_start.hpp"

namespace pneumachaos::cli {
namespace {

struct SimulateArgs {
  ScenarioArgs scenario;
  std::optional<double> duration_s;
  std::optional<double> rate_Hz;
  std::uint64_t seed = 0;
  std::string output;
  bool quiet = false;
};

// The scenario file, the --set overrides, then the typed flags, checked once all are applied.
Scenario scenario_of(const SimulateArgs& args) {
  SettingOrigins origins;
  Scenario scenario = args.scenario.file.empty() ? default_scenario()
                                                 : load_scenario_file(args.scenario.file, &origins);
  apply_overrides(scenario, args.scenario.sets, &origins);
  // The typed flags set their keys directly, so an error names the flag that was typed.
  const auto flag = [&](const char* key, std::optional<double> value, const char* name) {
    if (!value) return;
    apply_setting(scenario, key, *value, name);
    origins[key] = name;
  };
  flag("run.duration_s", args.duration_s, "--duration");
  flag("run.rate_Hz", args.rate_Hz, "--rate");
  validate_scenario(scenario, origins);
  return scenario;
}

}  // namespace

Action add_simulate(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Simulate the cylinder and write its time response as CSV (t, x, v, P1, P2, "
      "friction force and state, stuck flag; with any transducer.* key set, also v, P1 and P2 "
      "as measured through the transducers)");
  add_scenario_options(cmd, args->scenario);
  cmd->add_option("--duration", args->duration_s, "simulated time [s] (run.duration_s)");
  cmd->add_option("--rate", args->rate_Hz, "output sample rate [Hz] (run.rate_Hz)");
  cmd->add_option("--seed", args->seed,
                  "seed of the transducers' noise (default 0): the same seed gives the same "
                  "measured channels");
  cmd->add_option("-o,--output", args->output, "CSV file to write (default: standard output)")
      ->check(output_file_check());
  add_quiet_flag(cmd, args->quiet);
  return [args]() {
    const Scenario scenario = scenario_of(*args);
    for (const auto& n : scenario_notes(scenario)) fmt::print(stderr, "simulate: note: {}\n", n);
    const Plant plant(scenario);
    SimulationResult result = with_progress("simulate", "integrating", !args->quiet,
                                            [&] {
                                              return simulate_from(
                                                  plant, run_start_state(plant, scenario.run),
                                                  scenario.run);
                                            });
    fmt::print(stderr, "simulate: {}\n",
               describe(result.summary, !plant.seal_friction().has_stiction()));
    if (!result.summary.ok()) {
      fmt::print(stderr, "simulate: the run failed; no output written\n");
      return kExitRunFailed;
    }
    add_scenario_measured_channels(result.series, scenario, args->seed);
    return write_series_csv(result.series, args->output);
  };
}

}  // namespace pneumachaos::cli
