// `pneumachaos fit`: identify scenario keys (valve areas, dead volumes, seal friction) from a
// measured record by segment-wise simulation and Ceres least squares (docs/notes/model_fit.md).

#include <fmt/format.h>

#include <optional>

#include "commands.hpp"
#include "stage_progress.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/identify/fit.hpp"
#include "pneumachaos/identify/measured_record_csv.hpp"
#include "pneumachaos/io/atomic_file.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/plot/figure.hpp"

namespace pneumachaos::cli {
namespace {

struct FitArgs {
  std::string record;
  ScenarioArgs scenario;
  std::vector<std::string> free;
  std::string json, scenario_out, plot_out;
  identify::RecordColumns columns;
  std::vector<std::string> units;
  std::optional<double> segment_s, pressure_scale_Pa, velocity_scale_mm_s;
  std::optional<int> max_iterations;
  bool verbose = false;
  bool quiet = false;
};

void add_fit_options(CLI::App* cmd, FitArgs& a) {
  cmd->add_option("record", a.record, "CSV record: t[s], v[m/s], P1[Pa], P2[Pa] (absolute), optional x[m]")
      ->required()
      ->check(CLI::ExistingFile);
  add_scenario_options(cmd, a.scenario);
  add_quiet_flag(cmd, a.quiet);
  cmd->add_option("--free", a.free,
                  "a scenario key to fit (repeatable), e.g. --free circuit.S1_mm2 "
                  "--free cylinder.dead_volume_head_cm3; default: circuit.S1_mm2, "
                  "circuit.S2_mm2, friction.Fc_N, friction.Fs_N");
  cmd->add_option("--json", a.json, "write the fitted values, standard errors and fit statistics as JSON")
      ->check(output_file_check());
  cmd->add_option("--scenario-out", a.scenario_out, "write the fitted scenario as TOML")
      ->check(output_file_check());
  cmd->add_option("--plot-out", a.plot_out,
                  "directory for the validation series (measured vs simulated CSV), its gnuplot "
                  "scripts and figure")
      ->check(output_directory_check());
  add_record_column_options(cmd, a.columns);
  add_units_option(cmd, a.units);
  cmd->add_option("--segment", a.segment_s, "segment length [s] of the final fit (default 0.2)")
      ->check(positive_number_check());
  cmd->add_option("--pressure-scale", a.pressure_scale_Pa,
                  "noise scale dividing the pressure residuals [Pa] (default 1000)")
      ->check(positive_number_check());
  cmd->add_option("--velocity-scale", a.velocity_scale_mm_s,
                  "noise scale dividing the velocity residuals [mm/s] (default 30)")
      ->check(positive_number_check());
  cmd->add_option("--max-iterations", a.max_iterations,
                  "Ceres iterations allowed per fit (default 50); a fit that needs more has "
                  "not converged (exit 3)")
      ->check(positive_number_check());
  cmd->add_flag("--verbose", a.verbose, "print Ceres's iterations to standard error");
}

identify::FitOptions fit_options_from(const FitArgs& a) {
  identify::FitOptions options;
  if (a.segment_s) options.segment_length_s = *a.segment_s;
  if (a.pressure_scale_Pa) options.pressure_scale_Pa = *a.pressure_scale_Pa;
  if (a.velocity_scale_mm_s) options.velocity_scale_m_per_s = *a.velocity_scale_mm_s * 1e-3;
  if (a.max_iterations) options.max_iterations = *a.max_iterations;
  options.verbose = a.verbose;
  return options;
}

void print_fit(const identify::MeasuredRecord& record, const identify::FitResult& r,
               const identify::FitOptions& options) {
  fmt::print("fit: {} samples, {} segments of {:g} s, {} Ceres iterations, {:.1f} s\n",
             record.size(), r.segments, options.segment_length_s, r.iterations, r.wall_time_s);
  for (const auto& p : r.parameters) {
    fmt::print("  {:<34} {:>12.6g} +- {:<10.3g} {:<6} (start {:g})\n", p.key, p.value,
               p.standard_error, p.unit, p.start);
  }
  fmt::print("  rms error: P1 {:.0f} Pa, P2 {:.0f} Pa, v {:.2f} mm/s; reduced chi2 {:.3g}\n",
             r.rms_P1_Pa, r.rms_P2_Pa, r.rms_v_m_per_s * 1e3, r.reduced_chi2);
}

// The validation figure, after the results are committed: without gnuplot the series and
// scripts are still written, with a warning.
void write_validation_figure(const identify::FitResult& r, const std::string& dir) {
  FigureSpec spec;
  spec.name = "fit_validation";
  spec.caption = "Measured and segment-wise simulated v, P1, P2 with the fitted parameters";
  spec.data = {{"fit_validation.csv", identify::validation_csv(r.validation)}};
  spec.plot = identify::validation_plot_commands("fit_validation.csv");
  spec.height = 800;
  try {
    render_figure(spec, dir);
  } catch (const Error& e) {
    fmt::print(stderr, "fit: warning: figure not rendered: {}\n", e.what());
  }
}

}  // namespace

Action add_fit(CLI::App& app) {
  auto args = std::make_shared<FitArgs>();
  CLI::App* cmd = app.add_subcommand(
      "fit",
      "Identify the model from a measured record (t, v, P1, P2[, x]): fit the scenario keys "
      "named by --free (default S1, S2, Fc, Fs) by segment-wise simulation; values with "
      "standard errors, a validation plot and the fitted scenario");
  add_fit_options(cmd, *args);
  return [args]() {
    const Scenario start = build_scenario(args->scenario.file, args->scenario.sets);
    const std::vector<std::string> free =
        args->free.empty() ? identify::default_free_keys(start) : args->free;
    identify::check_free_keys(start, free);  // before reading: a bad key is exit 2 at once
    const identify::MeasuredRecord record = identify::read_measured_record(
        args->record, args->columns, record_read_options(start, args->scenario, args->units));
    const identify::FitOptions options = fit_options_from(*args);
    // A fit that does not converge throws RunError: exit 3 and nothing written.
    const identify::FitResult r =
        with_progress("fit", "segment-wise simulation and least squares", !args->quiet,
                      [&] { return identify::fit_model(record, start, free, options); });
    print_fit(record, r, options);
    OutputSet outputs;
    if (!args->json.empty()) outputs.add(args->json) << identify::fit_json(r, options, record);
    if (!args->scenario_out.empty()) {
      outputs.add(args->scenario_out)
          << "# Fitted by `pneumachaos fit` from " << args->record << ": "
          << fmt::format("{}", fmt::join(free, ", ")) << "\n"
          << scenario_to_toml(r.scenario);
    }
    outputs.commit();
    if (!args->plot_out.empty()) write_validation_figure(r, args->plot_out);
    return kExitOk;
  };
}

}  // namespace pneumachaos::cli
