// `pneumachaos sweep`: repeated runs over a grid, each judged by the analysis; resumable.

#include <fmt/format.h>

#include <optional>

#include "commands.hpp"
#include "pneumachaos/io/scenario_toml.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"

namespace pneumachaos::cli {

Action add_sweep(CLI::App& app) {
  struct Args {
    ScenarioArgs scenario;
    std::vector<std::string> grids;
    std::optional<std::size_t> repeats;
    std::optional<std::uint64_t> seed;
    std::size_t threads = 0;
    std::string out;
    bool resume = false;
    bool wolf = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "sweep",
      "Repeated runs over a parameter grid (default: the paper's S1 x S2 grid, 5 repeats), "
      "each simulated and judged stick-slip / chaotic from its velocity record; resumable");
  add_scenario_options(cmd, args->scenario);
  cmd->add_option("--grid", args->grids,
                  "grid axis KEY=FROM:TO:STEP in the key's unit (repeatable)");
  cmd->add_option(
      "--repeats", args->repeats,
      "runs per grid point (default: the file's [sweep] repeats, else 5 as in the paper)");
  cmd->add_option("--seed", args->seed, "seed of the run-to-run variation (default 1)");
  cmd->add_option("--threads", args->threads, "worker threads (default 0: all cores)")
      ->check(CLI::Range(0, 4096));
  cmd->add_option("--out", args->out, "directory for the journal and the results")->required();
  cmd->add_flag("--resume", args->resume, "finish an interrupted sweep in --out");
  cmd->add_flag("--wolf", args->wolf, "also run Wolf's estimator on every record (slower)");
  return [args]() {
    SweepSpec spec;
    spec.base = build_scenario(args->scenario.file, args->scenario.sets);
    // The command line wins over the scenario file's [sweep] table, which wins over defaults.
    const SweepSettings file =
        args->scenario.file.empty() ? SweepSettings{} : read_sweep_settings(args->scenario.file);
    for (const auto& g : args->grids.empty() ? file.grid : args->grids) {
      spec.axes.push_back(parse_grid_axis(g));
    }
    if (spec.axes.empty()) spec.axes = paper_valve_grid();
    spec.repeats = args->repeats.value_or(file.repeats.value_or(5));
    spec.seed = args->seed.value_or(file.seed.value_or(1));
    spec.wolf = args->wolf;
    SweepOptions options;
    options.out_dir = args->out;
    options.resume = args->resume;
    options.threads = args->threads;
    const SweepSummary s = run_sweep(spec, options);
    if (!s.wrote_files) return kExitOk;  // another MPI rank reports
    fmt::print(
        "sweep: {} points x {} repeats = {} runs ({} failed); stick-slip region {} points, "
        "100 %-chaos region {} points, chaos anywhere {} points; results in {}\n",
        s.points, spec.repeats, s.runs, s.failed, s.stick_slip_points, s.chaos_full_points,
        s.chaos_any_points, args->out);
    return kExitOk;
  };
}

}  // namespace pneumachaos::cli
