// `pneumachaos simulate`: a time response as CSV.

#include <fmt/format.h>

#include <iostream>
#include <optional>

#include "commands.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/io/csv_writer.hpp"
#include "pneumachaos/io/scenario_toml.hpp"
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
  cmd->add_option("-o,--output", args->output, "CSV file to write (default: standard output)");
  return [args]() {
    std::vector<std::string> sets = args->scenario.sets;
    if (args->duration_s) sets.push_back(fmt::format("run.duration_s={}", *args->duration_s));
    if (args->rate_Hz) sets.push_back(fmt::format("run.rate_Hz={}", *args->rate_Hz));
    const Scenario scenario = build_scenario(args->scenario.file, sets);
    const Plant plant(scenario);
    const SimulationResult result = simulate(plant, SimulationOptions::from(scenario.run));
    fmt::print(stderr, "simulate: {}\n", describe(result.summary));
    if (!result.summary.ok()) {
      fmt::print(stderr, "simulate: the run failed; no output written\n");
      return kExitRunFailed;
    }
    if (args->output.empty()) {
      write_csv(std::cout, result.series);
      std::cout.flush();
      return std::cout ? kExitOk : kExitRunFailed;
    }
    AtomicFile file(args->output);
    write_csv(file.stream(), result.series);
    file.commit();
    return kExitOk;
  };
}

}  // namespace pneumachaos::cli
