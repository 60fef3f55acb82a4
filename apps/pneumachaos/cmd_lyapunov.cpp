// `pneumachaos lyapunov`: the largest Lyapunov exponent of the model itself, with its
// convergence, as the ground truth for the time-series estimators.

#include <fmt/format.h>

#include <cmath>
#include <numbers>

#include "commands.hpp"
#include "stage_progress.hpp"
#include "flag_names.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/simulate/event_integrator.hpp"
#include "pneumachaos/simulate/lyapunov_output.hpp"
#include "pneumachaos/simulate/model_lyapunov.hpp"
#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos::cli {

Action add_lyapunov(CLI::App& app) {
  struct Args {
    ScenarioArgs scenario;
    ModelLyapunovOptions o;
    double tolerance_factor = 1.0;
    std::string running_out;
    bool json = false;
    bool quiet = false;
  };
  auto args = std::make_shared<Args>();
  CLI::App* cmd = app.add_subcommand(
      "lyapunov",
      "Largest Lyapunov exponent of the model (two nearby trajectories, renormalised; Benettin "
      "et al. 1980), correct across stick/slip events, with its convergence");
  add_scenario_options(cmd, args->scenario);
  cmd->add_option("--transient", args->o.transient_s, "seconds discarded first (default 5)");
  cmd->add_option("--measure", args->o.measure_s,
                  "seconds averaged (default 40, or up to the stroke end when the volumes "
                  "follow the piston and it comes first)");
  cmd->add_option("--renormalize", args->o.renormalize_s,
                  "renormalisation interval [s] (default 0.02)");
  cmd->add_option("--separation", args->o.separation,
                  fmt::format("initial separation in scaled units (1 = 10 kPa on P1; default "
                              "{:g}; at least {:g} x the relative tolerance, so smaller only "
                              "with --tolerance-factor)",
                              ModelLyapunovOptions{}.separation, kPlantSeparationPerTolerance));
  cmd->add_option(
      "--tolerance-factor", args->tolerance_factor,
      "multiply the integration tolerances (rtol 1e-9, atol 1e-12; e.g. 0.5 to confirm)");
  cmd->add_flag("--until-stroke-end,!--no-until-stroke-end", args->o.until_terminal_event,
                "a stroke end during the measurement ends it there (the exponent spans the "
                "time measured; the default); --no-until-stroke-end fails the run instead");
  cmd->add_option("--running-out", args->running_out, "CSV file for the running estimate")
      ->check(output_file_check());
  cmd->add_flag("--json", args->json, "print every number with its unit as JSON");
  add_quiet_flag(cmd, args->quiet);
  return [args]() {
    const Scenario scenario = build_scenario(args->scenario.file, args->scenario.sets);
    const Plant plant(scenario);
    const ModelLyapunovOptions& o = args->o;
    if (!(std::isfinite(args->tolerance_factor) && args->tolerance_factor > 0.0)) {
      throw Error("--tolerance-factor", "must be a positive number");
    }
    const FlagNames flags{{ModelLyapunovOptions::kMeasureField.id, "--measure"},
                          {ModelLyapunovOptions::kRenormalizeField.id, "--renormalize"},
                          {ModelLyapunovOptions::kTransientField.id, "--transient"},
                          {ModelLyapunovOptions::kSeparationField.id, "--separation"},
                          {IntegratorOptions::kRelativeToleranceField.id, "--tolerance-factor"},
                          {IntegratorOptions::kAbsoluteToleranceField.id, "--tolerance-factor"}};
    const ModelLyapunovResult r = with_flag_names(flags, [&] {
      return with_progress("lyapunov", "two trajectories, renormalised", !args->quiet,
                           [&] { return plant_lyapunov(plant, scenario.run, o, args->tolerance_factor); });
    });
    if (!r.ok) {
      fmt::print(stderr, "lyapunov: {}\n", r.message);
      return kExitRunFailed;
    }
    fmt::print("{}", args->json ? lyapunov_json(r, o) + "\n" : lyapunov_summary(r, o));
    if (!args->running_out.empty()) {
      AtomicFile f(args->running_out);
      f.stream() << "t[s],lambda[1/s]\n";
      for (std::size_t i = 0; i < r.running_per_s.size(); ++i)
        f.stream() << fmt::format("{},{}\n", r.running_time_s[i], r.running_per_s[i]);
      f.commit();
    }
    return kExitOk;
  };
}

}  // namespace pneumachaos::cli
