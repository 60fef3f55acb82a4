#include "pneumachaos/claims/example_run.hpp"

#include <algorithm>

#include "pneumachaos/model/variation.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/simulate/measured_channels.hpp"
#include "pneumachaos/claims/claim_rules.hpp"
#include "pneumachaos/stability/run_start.hpp"

namespace pneumachaos {

namespace {

// The example is one record, as the paper's Fig. 7: it carries the seal's random level when
// the scenario has one (the realisation of seed 1, the maps' first run's stream), not the
// scatter and texture, which stand for the maps' repeated measurements.
Scenario example_scenario(const Scenario& base, double record_s) {
  constexpr std::uint64_t kExampleSeed = 1;
  Scenario s = base;
  s.variation.friction_rel_sd = 0.0;
  s.variation.texture_rel = 0.0;
  s = vary(s, run_seed(kExampleSeed, 0, 0));
  s.run.duration_s = record_s;
  return s;
}

// The example's transducer noise is drawn from this seed, so a report is reproducible.
constexpr std::uint64_t kExampleTransducerSeed = 1;

}  // namespace

ExampleRun run_example(const Scenario& base, double record_s, bool model_exponent) {
  const Scenario s = example_scenario(base, record_s);
  ExampleRun e;
  const Plant plant(s);
  e.sim = simulate_from(plant, run_start_state(plant, s.run), s.run);
  if (!e.sim.summary.ok()) throw Error("reproduce", "a simulation failed: " + e.sim.summary.message);
  // The example is judged as the paper judged its record: from the velocity as the rig's
  // transducer records it, as every map run is (the series is left as simulated while the
  // transducers are ideal).
  add_scenario_measured_channels(e.sim.series, s, kExampleTransducerSeed);
  const bool measured = e.sim.series.has_channel("v_measured");
  const auto& v_all = e.sim.series.channel(measured ? "v_measured" : "v").values;
  e.settle = std::min(v_all.size(),
                      static_cast<std::size_t>(kExampleSettle_s * e.sim.series.rate_Hz()));
  e.v.assign(v_all.begin() + static_cast<std::ptrdiff_t>(e.settle), v_all.end());
  // Wolf's estimator on the record whatever its structure, as the paper ran it on every
  // record: the example is judged by both judges.
  AnalysisOptions judged_twice;
  judged_twice.paper_judge = true;
  e.analysis = analyze_series(e.v, e.sim.series.rate_Hz(), judged_twice);
  e.model.ok = false;  // not measured unless asked (the claims then leave it out)
  if (model_exponent) {
    // The model's exponent after 1 s of start-up over the rest of the record, which with the
    // volumes following the piston ends at the stroke end (docs/notes/virtual_rig.md).
    ModelLyapunovOptions lo;
    lo.transient_s = 1.0;
    lo.measure_s = record_s - lo.transient_s;
    lo.until_terminal_event = true;
    const Scenario m = example_scenario(base, base.run.duration_s);
    const Plant model_plant(m);
    e.model = plant_lyapunov_from(model_plant, run_start_state(model_plant, m.run), m.run, lo);
  }
  return e;
}

void add_example_inputs(ClaimInputs& ci, const ExampleRun& run) {
  const AnalysisResult& a = run.analysis;
  const std::vector<double>& v = run.v;
  const std::vector<double>& F = run.sim.series.channel("F_friction").values;
  if (a.divergence.found_linear_region) {
    ci.example_lambda = a.divergence.lambda_per_s;
    // The claim tests the rise (3 sigma), as the verdict does: the slope's uncertainty
    // (docs/notes/analysis.md "Divergence exponent's uncertainty").
    ci.example_uncertainty = a.divergence.slope_uncertainty_per_s;
  }
  if (a.wolf_run) ci.example_wolf = a.wolf.lambda_per_s;
  ci.example_chaotic = a.verdict.chaotic;
  if (const PaperJudgement j = paper_judge(a); j.evaluated) ci.example_paper_chaotic = j.chaotic;
  ci.example_regime = regime_name(a.verdict.regime);
  ci.example_peak_share = a.spectrum.peak_share;
  ci.example_spectrum_resolution_Hz = a.spectrum.resolution_Hz;
  ci.example_settled_s = static_cast<double>(v.size()) / a.rate_Hz;
  ci.example_acf_after_1s = acf_envelope_after(a.acf.r, a.acf.rate_Hz, 1.0);
  // Low speed: up to a quarter of the example's largest speed.
  const double vmax = v.empty() ? 0.0 : *std::max_element(v.begin(), v.end());
  ci.friction_slope_vmax = 0.25 * vmax;
  const std::vector<double> F_settled(F.begin() + static_cast<std::ptrdiff_t>(run.settle), F.end());
  ci.friction_line = low_speed_line(v, F_settled, ci.friction_slope_vmax);
  ci.friction_loop = measure_friction_loop(v, F_settled, a.rate_Hz);
  ci.fold_stretch = measure_fold_stretch(v, a.rate_Hz, a.dimension.dimension, a.delay.delay,
                                         a.theiler);
  if (run.model.ok) {
    ci.example_model_lambda = run.model.lambda_per_s;
    ci.example_model_uncertainty = run.model.uncertainty_per_s;
  }
}

}  // namespace pneumachaos
