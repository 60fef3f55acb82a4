// `pneumachaos simulate`: a time response as CSV.

#include <fmt/format.h>

#include <iostream>
#include <optional>

#include "commands.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/io/csv_writer.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos::cli {
namespace {

struct SimulateArgs {
  ScenarioArgs scenario;
  std::optional<double> duration_s;
  std::optional<double> rate_Hz;
  std::string output;
};

}  // namespace

Action add_simulate(CLI::App& app) {
  auto args = std::make_shared<SimulateArgs>();
  CLI::App* cmd = app.add_subcommand(
      "simulate",
      "Simulate the cylinder and write its time response as CSV (t, x, v, P1, P2, "
      "friction force and state, stuck flag)");
  add_scenario_options(cmd, args->scenario);
  cmd->add_option("--duration", args->duration_s, "simulated time [s] (run.duration_s)");
  cmd->add_option("--rate", args->rate_Hz, "output sample rate [Hz] (run.rate_Hz)");
  cmd->add_option("-o,--output", args->output, "CSV file to write (default: standard output)")
      ->check(output_file_check());
  return [args]() {
    SettingOrigins origins;
    Scenario scenario = args->scenario.file.empty()
                            ? default_scenario()
                            : load_scenario_file(args->scenario.file, &origins);
    apply_overrides(scenario, args->scenario.sets, &origins);
    // The typed flags set their keys directly, so an error names the flag that was typed; the
    // cross-key checks run once all are applied.
    const auto flag = [&](const char* key, std::optional<double> value, const char* name) {
      if (!value) return;
      apply_setting(scenario, key, *value, name);
      origins[key] = name;
    };
    flag("run.duration_s", args->duration_s, "--duration");
    flag("run.rate_Hz", args->rate_Hz, "--rate");
    validate_scenario(scenario, origins);
    for (const auto& n : scenario_notes(scenario)) fmt::print(stderr, "simulate: note: {}\n", n);
    const Plant plant(scenario);
    const SimulationResult result = simulate(plant, scenario.run);
    fmt::print(stderr, "simulate: {}\n", describe(result.summary));
    if (!result.summary.ok()) {
      fmt::print(stderr, "simulate: the run failed; no output written\n");
      return kExitRunFailed;
    }
    if (args->output.empty()) {
      write_csv(std::cout, result.series);
      return kExitOk;  // main checks that standard output took it all
    }
    AtomicFile file(args->output);
    write_csv(file.stream(), result.series);
    file.commit();
    return kExitOk;
  };
}

}  // namespace pneumachaos::cli
