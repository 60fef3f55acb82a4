// `pneumachaos stability`: the linear analysis at one point, or its map over a grid.

#include <fmt/format.h>

#include <iostream>
#include <optional>

#include "commands.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/stability/stability_output.hpp"

namespace pneumachaos::cli {

Action add_stability(CLI::App& app) {
  struct Args {
    ScenarioArgs scenario;
    std::vector<std::string> grids;
    bool json = false;
    bool map = false;
    std::optional<double> position_mm;
    std::string output;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "stability",
      "Linear stability of the steady motion: the paper's a1/b1 and damping coefficient beside "
      "the full model's eigenvalues; --map evaluates it over a grid");
  add_scenario_options(cmd, args->scenario);
  cmd->add_flag("--json", args->json, "print every number with its unit as JSON");
  cmd->add_option("--position-mm", args->position_mm,
                  "piston position for the chamber volumes [mm] (default: "
                  "cylinder.frozen_position_mm when the scenario sets it, else mid-stroke)");
  cmd->add_flag("--map", args->map, "evaluate over a grid (default: the paper's S1 x S2 grid)");
  cmd->add_option("--grid", args->grids,
                  "grid axis KEY=FROM:TO:STEP in the key's unit (with --map; repeatable)");
  cmd->add_option("-o,--output", args->output, "with --map: CSV file (default: standard output)")
      ->check(output_file_check());
  return [args]() {
    const Scenario scenario = build_scenario(args->scenario.file, args->scenario.sets);
    for (const auto& n : scenario_notes(scenario)) fmt::print(stderr, "stability: note: {}\n", n);
    StabilityOptions options;
    if (args->position_mm)
      set_piston_position(options, scenario, *args->position_mm, "--position-mm");
    if (!args->map) {
      if (!args->grids.empty()) throw Error("--grid", "needs --map");
      const Plant plant(scenario);
      const StabilityResult r = analyze_stability(plant, options);
      fmt::print("{}",
                 args->json ? stability_json(scenario, r) + "\n" : stability_table(scenario, r));
      return kExitOk;
    }
    std::vector<GridAxis> axes;
    for (const auto& g : args->grids) axes.push_back(parse_grid_axis(g));
    if (axes.empty()) axes = paper_valve_grid();
    const StabilityMap map = stability_map(scenario, axes, options);
    fmt::print(stderr, "stability map: {} points, {} with steady motion, verdicts agree at {}\n",
               map.points.size(), map.with_equilibrium, map.agreeing);
    if (args->output.empty()) {
      write_stability_map_csv(std::cout, map, scenario.ambient_pressure_Pa);
      return kExitOk;
    }
    AtomicFile file(args->output);
    write_stability_map_csv(file.stream(), map, scenario.ambient_pressure_Pa);
    file.commit();
    return kExitOk;
  };
}

}  // namespace pneumachaos::cli
