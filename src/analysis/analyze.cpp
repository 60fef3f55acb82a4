#include "pneumachaos/analysis/analyze.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "analysis/rests.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "exponent_spread.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "seed_agreement.hpp"

namespace pneumachaos {
namespace {

// The evidence beyond the exponents: the 0-1 test on the record down-sampled, the prediction
// errors (determinism) and, when asked, the surrogate test. They read the record at one
// scale: the delay, but at most a quarter of the orbital period. The mutual information's
// first minimum can lie beyond that on a short oversampled record (Lorenz at dt = 0.005,
// 1e4 samples: 125 samples, two thirds of an orbit), where samples a quarter period apart are
// already far from redundant. The period here is the maxima spacing of the record smoothed
// over one delay, which noise does not shorten (docs/notes/analysis.md "Evidence scale").
SeededTestSetup run_evidence_tests(std::span<const double> x, const AnalysisOptions& o,
                                   AnalysisResult& r) {
  const double period = smoothed_period(x, r.delay.delay);
  const auto quarter = static_cast<std::size_t>(std::lround(period * kDelayShareOfOrbit));
  SeededTestSetup setup;
  setup.zero_one_step = std::clamp<std::size_t>(quarter, 1, r.delay.delay);
  ZeroOneOptions z = o.zero_one;
  z.seed = o.seed;
  // An oversampled flow walks smoothly at the sample scale and reads K ~ 0 even when chaotic.
  r.zero_one = zero_one_test(x, setup.zero_one_step, z);
  setup.prediction.dimension = r.dimension.dimension;
  setup.prediction.delay = setup.zero_one_step;
  setup.prediction.theiler = r.theiler;
  r.prediction = prediction_errors(x, setup.prediction);
  SurrogateOptions s = o.surrogates;
  s.seed = o.seed;
  r.surrogate = surrogate_test(x, setup.prediction, s);

  RegimeEvidence& e = r.evidence;
  note_zero_one(r.zero_one, e);
  e.prediction_computed = r.prediction.computed;
  e.prediction_nonlinear = r.prediction.nonlinear;
  e.prediction_linear = r.prediction.linear;
  note_surrogates(r.surrogate, e);
  return setup;
}

// Wolf's program on a record without deterministic structure measures nothing (white noise
// reads ~300 /s) and is the analysis's most expensive part there (1e5 samples: 10 s of 11.5):
// it is not run when the local-constant predictor does no better than the linear one, the
// signature of linear noise (docs/notes/analysis.md "Wolf's status") — unless the paper's
// judge is asked for: the paper ran Wolf's program on every record.
void run_wolf(std::span<const double> x, double rate_Hz, const DivergenceOptions& d, bool paper,
              AnalysisResult& r) {
  // For a linear Gaussian process the linear predictor is optimal: a local-constant error at
  // or above the linear one means no nonlinear structure (docs/notes/analysis.md "Determinism").
  constexpr double kLinearNoiseRatio = 1.0;
  if (!paper && r.prediction.computed && r.prediction.ratio() >= kLinearNoiseRatio) {
    r.wolf_status = fmt::format(
        "not run: no deterministic structure (local-constant prediction error {:.3g} >= linear "
        "{:.3g}); an exponent is not defined for noise",
        r.prediction.nonlinear, r.prediction.linear);
    return;
  }
  WolfOptions w;
  w.dimension = d.dimension;
  w.delay = d.delay;
  w.theiler = d.theiler;
  w.typical_period = d.typical_period;
  r.wolf = wolf_exponent(x, rate_Hz, w);
  r.wolf_run = true;
  r.wolf_status = r.wolf.measured_s > 0.0
                      ? fmt::format("measured over {:.4g} s (all chains)", r.wolf.measured_s)
                      : "nothing measured: every pair collapsed below the smallest scale (a "
                        "strictly periodic record); 0 is reported";
}

// The second estimate of the exponents, on the divergence curve's embedding. A record the
// local fits cannot use (every neighbourhood flat, too short for the maps) gets a status, not
// a failed analysis; whether the fits found a map at all is the estimate's own diagnostic
// (JacobianResult::reliable), reported beside it.
void run_jacobian(std::span<const double> x, double rate_Hz, const DivergenceOptions& d,
                  AnalysisResult& r) {
  JacobianOptions j;
  j.dimension = d.dimension;
  j.delay = d.delay;
  j.theiler = d.theiler;
  j.typical_period = d.typical_period;
  try {
    r.jacobian = jacobian_exponents(x, rate_Hz, j);
  } catch (const Error& e) {
    r.jacobian_status = "not computed: " + e.message();
    return;
  }
  r.jacobian_run = true;
  r.jacobian_status = fmt::format(
      "{} local maps of {} neighbours over {} steps, delay {}; median unexplained share {:.3g} "
      "({})",
      r.jacobian.maps, r.jacobian.neighbours, r.jacobian.evolve, r.jacobian.delay,
      r.jacobian.unexplained,
      r.jacobian.reliable ? "the neighbourhoods follow linear maps"
                          : fmt::format("unreliable: above {:.2g}, no smooth map: noise?",
                                        j.max_unexplained));
}

void note_lines(AnalysisResult& r) {
  r.evidence.second_line_power = r.lines.second_power;
  r.evidence.second_line_ratio =
      r.lines.first_frequency > 0 ? r.lines.second_frequency / r.lines.first_frequency : 0.0;
  r.evidence.second_line_incommensurate = r.lines.incommensurate;
}

}  // namespace

void AnalysisOptions::validate() const {
  // The upper end of the range AnalysisOptions::verdict_seeds documents (odd, 1 to 99).
  constexpr std::size_t kMaxVerdictSeeds = 99;
  zero_one.validate();
  surrogates.validate();
  verdict.validate();
  validation::require(
      verdict_seeds >= 1 && verdict_seeds <= kMaxVerdictSeeds && verdict_seeds % 2 == 1,
      kVerdictSeedsField, static_cast<double>(verdict_seeds),
      fmt::format("odd, from 1 to {} (a majority must exist)", kMaxVerdictSeeds));
}

namespace {

void check_record(std::span<const double> x, double rate_Hz) {
  // analyze()'s documented minimum (analyze.hpp), above the exponents' own
  // kMinExponentSamples: shorter records are refused before any estimator runs.
  constexpr std::size_t kMinSamples = 200;
  if (x.size() < kMinSamples) {
    throw Error("analyze", fmt::format("{} samples is too short to analyse: at least {} are needed",
                                       x.size(), kMinSamples));
  }
  for (std::size_t i = 0; i < x.size(); ++i) {
    if (!std::isfinite(x[i])) throw Error("analyze", fmt::format("sample {} is not finite", i));
  }
  if (!(std::isfinite(rate_Hz) && rate_Hz > 0.0)) {
    throw Error("analyze", fmt::format("the sample rate must be positive, got {}", rate_Hz));
  }
}

// Mean, spread, range and rests: the evidence every record gets, constant or not.
void describe_record(std::span<const double> x, const AnalysisOptions& o, AnalysisResult& r) {
  r.samples = x.size();
  r.mean = mean_of(x);
  r.standard_deviation = standard_deviation(x);
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double max_abs = std::max(std::abs(*lo), std::abs(*hi));
  if (!std::isfinite(r.standard_deviation)) {
    // Finite samples whose squares overflow: every index would be NaN or "constant".
    throw Error("analyze", fmt::format("values up to {:g} are too large to analyse in double "
                                       "precision; rescale the record (e.g. another unit)",
                                       max_abs));
  }
  RegimeEvidence& e = r.evidence;
  e.samples = x.size();
  e.mean = r.mean;
  e.range = *hi - *lo;
  const std::span<const double> last = x.subspan(x.size() / 2);
  e.last_half_mean = mean_of(last);
  e.last_half_std = standard_deviation(last);
  e.rests_judged = o.velocity;
  r.noise = estimate_noise_floor(x);
  e.noise_sd = r.noise.sd;
  if (o.velocity) rest_statistics(x, o.verdict, r.noise.sd, e);
}

// Delay (mutual information), Theiler window, dimension (Cao), unless given.
void choose_embedding(std::span<const double> x, double rate_Hz, const AnalysisOptions& o,
                      AnalysisResult& r) {
  r.delay = o.delay > 0 ? DelayChoice{o.delay, "given", {}} : choose_delay(x, 0, r.noise.sd);
  // The orbit is the oscillation's; a record that rests between slips has none to speak of
  // (its maxima are the slips), and there the cap turned the rig's stick-slip records chaotic
  // against the model's own exponent (docs/notes/exponent_validation.md, "The delay within an
  // orbit").
  if (o.delay == 0 && !rests_like_stick_slip(r.evidence, o.verdict))
    r.delay = delay_within_an_orbit(r.delay, r.period_samples);
  const std::size_t tau = r.delay.delay;
  const std::size_t zero_lag =
      r.acf.first_zero_s > 0 ? static_cast<std::size_t>(std::lround(r.acf.first_zero_s * rate_Hz))
                             : 1;
  r.theiler = o.theiler > 0 || o.theiler_given ? o.theiler : std::max(tau, zero_lag);
  r.dimension =
      o.dimension > 0 ? DimensionChoice{o.dimension, {}, {}} : choose_dimension(x, tau, r.theiler);
}

// White noise of sd s adds s / std to the windows' RMS mismatch relative to the attractor's
// size (sqrt(2) s over sqrt(2) std), in quadrature with the motion's own: "small" is judged
// above that, so a noisy cycle still repeats itself (docs/notes/analysis.md "Noise floor").
SelfRepetitionOptions repetition_above_noise(SelfRepetitionOptions o, const AnalysisResult& r) {
  if (r.noise.sd > 0.0 && r.standard_deviation > 0.0) {
    o.max_mismatch = std::hypot(o.max_mismatch, r.noise.sd / r.standard_deviation);
  }
  return o;
}

// What the divergence curve measured. Without a linear region, a deterministic record (the
// local-constant predictor beats the linear one) whose curve still rises gets the spread of its
// local slopes as a wide estimate (dysts's BurkeShaw: its curve bends all the way, its slope
// falling from 3.5 to 0 /time, with the flow's exponent 2.3 inside; docs/notes/
// exponent_validation.md) unless the verdict found it regular or steady: on a torus the
// separation grows like a power of time, which a log curve also shows as a rise (dysts's
// HenonHeiles read 0.035 /time against 0.0005).
void describe_divergence(double rate_Hz, const AnalysisOptions& o, AnalysisResult& r) {
  const DivergenceResult& d = r.divergence;
  if (d.found_linear_region) {
    r.divergence_status = fmt::format("linear region {}..{} samples", d.fit_first, d.fit_last);
    return;
  }
  r.divergence_status =
      "no rising linear region: no exponential divergence, or the record is too short";
  const bool deterministic = r.prediction.computed &&
                             r.prediction.ratio() <= o.verdict.max_prediction_ratio;
  const Regime v = r.verdict.regime;
  const bool regular =
      v == Regime::kPeriodic || v == Regime::kQuasiPeriodic || v == Regime::kSteady;
  r.divergence_estimate =
      deterministic && !regular && d.local_slopes.found && d.local_slopes.median > 0.0;
  if (!r.divergence_estimate) return;
  r.divergence_status = fmt::format(
      "no rising linear region; the curve rises without one straight stretch (a deterministic "
      "record): its one-orbit local slopes over the rise give {:.4g} 1/s, 10-90 % {:.4g} .. "
      "{:.4g} (a wide estimate; the verdict reads only whether the curve rises all along)",
      d.local_slopes.median * rate_Hz, d.local_slopes.low * rate_Hz,
      d.local_slopes.high * rate_Hz);
}

// The orbit's scales for the divergence curve and the self-repetition windows. Under a
// resolved noise floor the maxima are counted above the noise (mean_maxima_spacing with its
// sd): counted on the raw record, the noise's own wiggles make a rig's noisy cycle of 67 ms read
// 21 ms, its divergence curve is read over a third of an orbit and its windows do not repeat
// (docs/notes/analysis.md "Noise floor"). The embedding and the 0-1 test keep the clean count.
struct OrbitScales {
  double maxima_spacing = 0.0, period = 0.0;
};
OrbitScales orbit_above_noise(std::span<const double> x, const AnalysisResult& r) {
  if (!(r.noise.sd > 0.0)) return {r.maxima_spacing_samples, r.period_samples};
  const double spacing = mean_maxima_spacing(x, r.noise.sd);
  return {spacing, orbital_period(spacing, r.lines, x.size())};
}

void run_exponents(std::span<const double> x, double rate_Hz, const AnalysisOptions& o,
                   const OrbitScales& orbit, AnalysisResult& r) {
  DivergenceOptions d;
  d.dimension = r.dimension.dimension;
  d.delay = r.delay.delay;
  d.theiler = r.theiler;
  d.typical_period = static_cast<std::size_t>(std::lround(orbit.period));
  // The slope spacing stays at half the maxima spacing: the curve carries the fastest
  // oscillation the maxima follow, and a linear region can be shorter than one orbit.
  d.slope_spacing =
      std::max<std::size_t>(1, static_cast<std::size_t>(std::lround(orbit.maxima_spacing)) / 2);
  r.divergence = divergence_exponent(x, rate_Hz, d);
  if (r.divergence.found_linear_region) {
    r.exponent_spread = exponent_spread(x, rate_Hz, d, r.divergence, o.embedding_spread);
    r.divergence.uncertainty_per_s = widened_uncertainty(r.divergence, r.exponent_spread);
  }
  if (o.wolf) run_wolf(x, rate_Hz, d, o.paper_judge, r);
  if (o.jacobian) run_jacobian(x, rate_Hz, d, r);
  RegimeEvidence& e = r.evidence;
  e.lyapunov_found = r.divergence.found_linear_region;
  // Computed only without a linear region (divergence_exponent).
  const SlopeSpread& rising = r.divergence.local_slopes;
  if (!e.lyapunov_found && rising.found) {
    e.rising_low_per_s = rising.low * rate_Hz;
    e.rising_median_per_s = rising.median * rate_Hz;
  }
  e.lyapunov_per_s = r.divergence.lambda_per_s;
  e.lyapunov_uncertainty_per_s = r.divergence.uncertainty_per_s;
  e.lyapunov_slope_uncertainty_per_s = r.divergence.slope_uncertainty_per_s;
}

void stage(const AnalysisOptions& o, const char* what) {
  if (o.on_stage) o.on_stage(what);
}

}  // namespace

AnalysisResult analyze_series(std::span<const double> x, double rate_Hz, const AnalysisOptions& o) {
  check_record(x, rate_Hz);
  o.validate();
  AnalysisResult r;
  r.rate_Hz = rate_Hz;
  stage(o, "statistics and noise floor");
  describe_record(x, o, r);
  RegimeEvidence& e = r.evidence;
  if (!(r.standard_deviation > 0.0)) {
    // A constant record: steady by definition; no index is defined.
    r.verdict = decide_regime(e, o.verdict);
    return r;
  }
  stage(o, "spectrum and autocorrelation");
  r.maxima_spacing_samples = mean_maxima_spacing(x);
  r.period_samples = r.maxima_spacing_samples;
  r.spectrum = welch_spectrum(x, rate_Hz, o.spectrum);
  r.acf = autocorrelation(x, rate_Hz);
  e.broadband_share = r.spectrum.broadband_share;
  e.late_acf = r.acf.late_envelope;
  if (is_steady(e, o.verdict)) {
    // Damped to a constant: nothing to embed; the exponents are not computed.
    r.verdict = decide_regime(e, o.verdict);
    return r;
  }
  // The spectral lines before the exponents: they tell whether the maxima follow a harmonic.
  r.lines = spectral_lines(x);
  r.period_samples = orbital_period(r.maxima_spacing_samples, r.lines, x.size());
  stage(o, "embedding (mutual information, Cao)");
  choose_embedding(x, rate_Hz, o, r);
  stage(o, "0-1 test, prediction and surrogates");
  const SeededTestSetup seeded = run_evidence_tests(x, o, r);
  const OrbitScales orbit = orbit_above_noise(x, r);
  stage(o, "divergence curve and Wolf's estimator");
  run_exponents(x, rate_Hz, o, orbit, r);
  stage(o, "self-repetition and Poincare section");
  e.repetition = self_repetition(x, rate_Hz, orbit.period,
                                 repetition_above_noise(o.verdict.repetition, r),
                                 r.acf.lag_products);
  r.poincare = poincare_section(x, r.delay.delay, rate_Hz);
  r.maxima_map = successive_maxima(x);
  for (double v : r.dimension.E2) e.determinism = std::max(e.determinism, std::abs(v - 1.0));
  note_lines(r);
  r.verdict = decide_regime(e, o.verdict);
  stage(o, "the verdict on more seeds");
  check_seed_agreement(x, o, seeded, r);
  describe_divergence(rate_Hz, o, r);
  return r;
}

}  // namespace pneumachaos
