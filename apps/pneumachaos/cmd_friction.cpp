// `pneumachaos friction`: seal friction from a measured record (docs/friction.md).

#include <fmt/format.h>

#include <algorithm>
#include <iostream>
#include <optional>

#include "commands.hpp"
#include "stage_progress.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/identify/friction_estimate.hpp"
#include "pneumachaos/identify/friction_fits.hpp"
#include "pneumachaos/identify/friction_output.hpp"
#include "pneumachaos/identify/measured_record_csv.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/model/scenario_toml.hpp"

namespace pneumachaos::cli {

namespace {

struct FrictionArgs {
  std::string file;
  ScenarioArgs scenario;
  std::string json, series_out, scenario_out;
  std::vector<std::string> models;
  identify::RecordColumns columns;
  std::vector<std::string> units;
  bool pressure_dependent = false;
  bool quiet = false;
  std::optional<int> window;
  int max_iterations = 200;
};

// Reads the record, estimates the friction force, fits the laws and writes what was asked.
int run_friction(const FrictionArgs& a) {
  const Scenario scenario = build_scenario(a.scenario.file, a.scenario.sets);
  identify::FrictionFitOptions fit = identify::fit_options_for(
      scenario, a.models, a.pressure_dependent, "--model");
  fit.max_iterations = a.max_iterations;
  identify::EstimateSpec settings = identify::estimate_spec_from(scenario);
  if (a.window) identify::set_smoothing_window(settings, *a.window, "--window");
  const identify::MeasuredRecord record = identify::read_measured_record(
      a.file, a.columns, record_read_options(scenario, a.scenario, a.units));
  const bool show = !a.quiet;
  const identify::FrictionEstimate estimate =
      with_progress("friction", "the friction force from the record", show,
                    [&] { return identify::estimate_friction(record, settings); });
  const identify::FrictionFits fits = with_progress(
      "friction", "fitting the friction laws", show,
      [&] { return identify::fit_friction(estimate, fit); });
  fmt::print("{}", identify::friction_summary(estimate, fits));
  for (const auto& w : fits.warnings) fmt::print(stderr, "friction: warning: {}\n", w);
  identify::require_converged(fits);  // none converged: its reason, exit 3, nothing written
  const identify::ModelFit* preferred = fits.preferred();
  if (!a.scenario_out.empty() && !preferred)
    throw RunError("--scenario-out",
                   "no model converged with Fc <= Fs (see above); no output written");
  OutputSet outputs;
  if (!a.json.empty())
    outputs.add(a.json) << identify::friction_json(estimate, fits, settings, record.source) << '\n';
  if (!a.series_out.empty()) identify::write_friction_series(estimate, fits, a.series_out, outputs);
  if (!a.scenario_out.empty())
    outputs.add(a.scenario_out) << identify::friction_scenario_toml(*preferred, record.source);
  outputs.commit();
  return kExitOk;
}

}  // namespace

Action add_friction(CLI::App& app) {
  auto args = std::make_shared<FrictionArgs>();
  CLI::App* cmd = app.add_subcommand(
      "friction",
      "Seal friction from a measured record (t, v, P1, P2): force from the equation of motion, "
      "stick intervals, breakaway forces, the friction-velocity curve and loops, and fitted "
      "friction models (classic, Stribeck, LuGre) with standard errors");
  cmd->add_option("file", args->file,
                  "record: CSV with a header naming columns and units, e.g. t[s],v[m/s],"
                  "P1[Pa],P2[Pa] (also mm/s, kPa, MPa, bar, [MPa gauge]); - reads standard input")
      ->required()
      ->check(input_record_check());
  add_scenario_options(cmd, args->scenario);
  cmd->add_option("--json", args->json, "write every result with its unit as JSON to this file")
      ->check(output_file_check());
  cmd->add_option("--series-out", args->series_out,
                  "directory for F(t), F(v), the binned curve, each model's curve and the loop "
                  "marks as CSV")
      ->check(output_directory_check());
  cmd->add_option("--scenario-out", args->scenario_out,
                  "write the preferred model as a scenario [friction] table (TOML)")
      ->check(output_file_check());
  cmd->add_option("--model", args->models,
                  "model to fit (repeatable): classic | stribeck | stribeck_delta | lugre "
                  "(default: all)");
  cmd->add_flag("--pressure-dependent", args->pressure_dependent,
                "fit Fc and Fs growing with P1+P2-2Pa (Fc_gain_N_per_MPa, Fs_gain_N_per_MPa)");
  cmd->add_option("--window", args->window,
                  "Savitzky-Golay window in samples (odd, >= 3; default: chosen from the noise)");
  cmd->add_option("--max-iterations", args->max_iterations,
                  "iterations allowed to each fit (default 200); a fit that has not converged "
                  "by then is reported, marked and not used (a warning); the command fails "
                  "(exit 3) only when no model converged")
      ->check(positive_number_check());
  add_record_column_options(cmd, args->columns);
  add_units_option(cmd, args->units);
  add_quiet_flag(cmd, args->quiet);
  return [args]() { return run_friction(*args); };
}

}  // namespace pneumachaos::cli
