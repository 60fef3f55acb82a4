#include <fmt/format.h>

#include <cmath>
#include <string>
#include <utility>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/analysis/paper_judge.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/variation.hpp"
#include "pneumachaos/simulate/measured_channels.hpp"
#include "pneumachaos/simulate/model_lyapunov.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "pneumachaos/stability/run_start.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {
namespace {

void record_analysis(const SweepSpec& spec, const AnalysisResult& a, RunRecord& r) {
  if (a.divergence.found_linear_region) {
    r.lambda = a.divergence.lambda_per_s;
    r.lambda_uncertainty = a.divergence.uncertainty_per_s;
  }
  if (a.wolf_run) r.wolf = a.wolf.lambda_per_s;
  r.broadband = a.spectrum.broadband_share;
  r.late_acf = a.acf.late_envelope;
  r.regime = regime_name(a.verdict.regime);
  r.chaotic = a.verdict.chaotic;
  r.stick_slip = a.verdict.stick_slip;
  if (a.zero_one.run) r.zero_one_K = a.zero_one.K;
  if (a.prediction.computed) r.prediction_ratio = a.prediction.ratio();
  if (a.evidence.repetition.run) r.repeat_share = a.evidence.repetition.share;
  if (!spec.paper_judge) return;
  const PaperJudgement j = paper_judge(a);
  if (j.evaluated) r.paper_chaotic = j.chaotic;
}

void add_reason(RunRecord& r, const std::string& why) {
  r.reason = r.reason.empty() ? why : r.reason + "; " + why;
}

// The model's own exponent of the run's (varied) scenario, over the rest of its stroke. A
// stroke end before the measurement is over is expected with moving volumes; a run that
// cannot be measured keeps NaN and says why (the record's verdict still stands).
void record_model_exponent(const SweepSpec& spec, const SweepRun& run, RunRecord& r) {
  const ModelLyapunovOptions o = spec.model_exponent.options(run.scenario.run.duration_s);
  const Plant plant(run.scenario);
  const ModelLyapunovResult m =
      plant_lyapunov_from(plant, run_start_state(plant, run.scenario.run), run.scenario.run, o);
  if (!m.ok) {
    add_reason(r, "model exponent: " + m.message);
    return;
  }
  r.lambda_model = m.lambda_per_s;
  r.lambda_model_uncertainty = m.uncertainty_per_s;
  r.lambda_model_span_s = m.measured_s;
}

}  // namespace

SweepRun simulate_run(const SweepSpec& spec, std::size_t point, std::size_t repeat) {
  SweepRun run;
  run.point = point;
  run.repeat = repeat;
  run.seed = run_seed(spec.seed, point, repeat);
  run.scenario = vary(scenario_at(spec.base, spec.axes, grid_index(spec.axes, point)), run.seed);
  const Plant plant(run.scenario);
  run.sim = simulate_from(plant, run_start_state(plant, run.scenario.run), run.scenario.run);
  if (!run.sim.summary.ok()) return run;
  // The analysis sees only the velocity as its transducer records it, as it would see a
  // measured record (no peeking at the model's state).
  TimeSeries& series = run.sim.series;
  add_measured_channels(series, run.scenario.transducer, run.scenario.ambient_pressure_Pa,
                        run.seed);
  run.measured_v = series.channel("v_measured").values;
  return run;
}

RunRecord judge_run(const SweepSpec& spec, const SweepRun& run) {
  RunRecord r;
  r.point = run.point;
  r.repeat = run.repeat;
  r.seed = run.seed;
  const IntegrationSummary& summary = run.sim.summary;
  r.termination = termination_name(summary.termination);
  r.t_final_s = summary.t_final_s;
  r.steps = summary.steps_accepted;
  r.sticks = summary.events.stick;
  if (!summary.ok()) {
    r.ok = false;
    r.reason = summary.message;
    return r;
  }
  r.mean_v = mean_of(run.measured_v);
  r.std_v = standard_deviation(run.measured_v);
  AnalysisOptions options;
  options.wolf = spec.runs_wolf();
  options.surrogates.count = spec.surrogates;
  try {
    record_analysis(spec, analyze_series(run.measured_v, run.sim.series.rate_Hz(), options), r);
  } catch (const Error& e) {
    r.reason = e.what();  // e.g. a record too short to judge: undetermined, not failed
  }
  if (spec.model_exponent.enabled) record_model_exponent(spec, run, r);
  return r;
}

RunRecord run_one(const SweepSpec& spec, std::size_t point, std::size_t repeat) {
  return run_one(spec, point, repeat, {});
}

RunRecord run_one(const SweepSpec& spec, std::size_t point, std::size_t repeat,
                  const std::function<void(const SweepRun&)>& observe) {
  try {
    const SweepRun run = simulate_run(spec, point, repeat);
    if (observe) observe(run);
    return judge_run(spec, run);
  } catch (const Error& e) {
    RunRecord r;
    r.point = point;
    r.repeat = repeat;
    r.seed = run_seed(spec.seed, point, repeat);
    r.ok = false;
    r.reason = e.what();
    return r;
  }
}

std::pair<SweepRun, RunRecord> replay_run(const SweepSpec& spec, std::size_t point,
                                          std::size_t repeat, const std::string& name) {
  spec.validate();
  if (point >= spec.points() || repeat >= spec.repeats) {
    throw Error(name, fmt::format("run {}:{} is outside the sweep ({} points x {} repeats)", point,
                                  repeat, spec.points(), spec.repeats));
  }
  SweepRun run = simulate_run(spec, point, repeat);
  RunRecord record = judge_run(spec, run);
  return {std::move(run), std::move(record)};
}

}  // namespace pneumachaos
