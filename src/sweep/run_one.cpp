#include <cmath>
#include <random>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/variation.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

RunRecord run_one(const SweepSpec& spec, std::size_t point, std::size_t repeat) {
  RunRecord r;
  r.point = point;
  r.repeat = repeat;
  r.seed = run_seed(spec.seed, point, repeat);
  try {
    const Scenario scenario =
        vary(scenario_at(spec.base, spec.axes, grid_index(spec.axes, point)), r.seed);
    const Plant plant(scenario);
    const SimulationResult sim = simulate(plant, SimulationOptions::from(scenario.run));
    r.termination = termination_name(sim.summary.termination);
    r.t_final_s = sim.summary.t_final_s;
    r.steps = sim.summary.steps_accepted;
    r.sticks = sim.summary.events.stick;
    if (!sim.summary.ok()) {
      r.ok = false;
      r.reason = sim.summary.message;
      return r;
    }
    // The analysis sees only the sampled velocity, with the transducer's noise, as it would
    // see a measured record (no peeking at the model's state).
    std::vector<double> v = sim.series.channel("v").values;
    if (scenario.variation.sensor_noise_m_per_s > 0.0) {
      auto rng = noise_stream(r.seed);
      std::normal_distribution<double> noise(0.0, scenario.variation.sensor_noise_m_per_s);
      for (double& x : v) x += noise(rng);
    }
    r.mean_v = mean_of(v);
    r.std_v = standard_deviation(v);
    AnalysisOptions options;
    options.wolf = spec.wolf;
    try {
      const AnalysisResult a = analyze_series(v, sim.series.rate_Hz(), options);
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
    } catch (const Error& e) {
      r.reason = e.what();  // e.g. a record too short to judge: undetermined, not failed
    }
  } catch (const Error& e) {
    r.ok = false;
    r.reason = e.what();
  }
  return r;
}

}  // namespace pneumachaos
