#include "pneumachaos/analysis/regime.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace pneumachaos {
namespace {

// The outcome of every criterion; see verdict_rule for how they combine.
struct Criteria {
  bool steady = false, positive = false, deterministic = false;
  bool diffusive = false, regular_K = false;  ///< 0-1 test median (both false when not run)
  bool clearly_regular = false;               ///< 0-1 test: even the upper quartile is low
  bool noise_like = false;  ///< surrogates run: null kept; else: prediction ratio not low
  bool persistent = false, concentrated = false, second_line = false;
  bool repeats = false;  ///< the record repeats itself over most of its length
  bool noisy = false;    ///< a white noise floor is resolved
};

class Notes {
 public:
  explicit Notes(Verdict& v) : v_(v) {}
  bool operator()(bool ok, const std::string& text) {
    v_.evidence.push_back(fmt::format("[{}] {}", ok ? "yes" : "no", text));
    return ok;
  }
  void info(const std::string& text) { v_.evidence.push_back("[--] " + text); }

 private:
  Verdict& v_;
};

// Without a linear region, a curve that rises all along its rise still says the separation
// grows, but so does a torus's (a power of time) or a noisy cycle's (diffusion): the rise is
// taken only where the paper's two other indices of chaos agree — a broadband spectrum and a
// dying autocorrelation — the 0-1 test reads the motion irregular, and the record does not
// rest like stick-slip (its rests are all one state: the rise then measures when the next
// slip starts). A record that repeats itself is weighed in note_repetition against the local
// slopes' 10 % quantile (docs/notes/analysis.md "Regime verdict").
bool autocorrelation_persists(const RegimeEvidence& e, const VerdictOptions& o) {
  return e.late_acf >= o.periodic_min_late_acf;
}
bool spectrum_concentrated(const RegimeEvidence& e, const VerdictOptions& o) {
  return e.broadband_share < o.periodic_max_broadband;
}

bool rise_counts(const RegimeEvidence& e, const VerdictOptions& o) {
  return !e.lyapunov_found && e.rises_throughout() && !spectrum_concentrated(e, o) &&
         !autocorrelation_persists(e, o) && e.zero_one_run && e.zero_one_K >= o.zero_one_split &&
         !rests_like_stick_slip(e, o);
}

void note_exponent(const RegimeEvidence& e, const VerdictOptions& o, Notes& note, Criteria& c) {
  c.positive = note(
      e.lyapunov_found && e.lyapunov_per_s > 0.0 &&
          e.lyapunov_per_s > o.lyapunov_sigmas * e.lyapunov_slope_uncertainty_per_s,
      e.lyapunov_found
          ? fmt::format("exponential divergence: the curve's slope {:.4g} +- {:.2g} 1/s above {} "
                        "sigma (the exponent's value: +- {:.2g} with the spread over segments)",
                        e.lyapunov_per_s, e.lyapunov_slope_uncertainty_per_s, o.lyapunov_sigmas,
                        e.lyapunov_uncertainty_per_s)
          : std::string("exponential divergence: the divergence curve has no rising linear "
                        "region"));
  if (rise_counts(e, o)) {
    c.positive = note(true, fmt::format("a rise without a straight stretch: the divergence "
                                        "curve's one-orbit local slopes stay positive all along "
                                        "its rise (median {:.4g}, 10 % quantile {:.4g} 1/s), with "
                                        "a broadband spectrum, a dying autocorrelation, the 0-1 "
                                        "test's K = {:.3f} >= {} and no stick-slip rests",
                                        e.rising_median_per_s, e.rising_low_per_s, e.zero_one_K,
                                        o.zero_one_split));
  }
}

// A near-repeat x(t + L) ~ x(t) is a pair of nearby states; under a positive exponent its
// mismatch would grow at that rate until it reached the attractor's size. Staying small over
// most of the record and growing slower than the slowest exponent the divergence test
// supports refutes the divergence (docs/notes/analysis.md "Regime verdict").
void note_repetition(const RegimeEvidence& e, const VerdictOptions& o, Notes& note,
                     Criteria& c) {
  const SelfRepetition& s = e.repetition;
  if (!s.run) {
    note.info("self-repetition: " + s.reason);
    return;
  }
  c.repeats = s.repeats;
  const std::string found = fmt::format(
      "record repeats itself: at lag {:.4g} s (drifting {:+.3g} s) the one-period windows' "
      "mismatch stays <= {:.3g} of the attractor's size over {:.3g} s = {:.0f} % of the record "
      "(need {:.0f} %; largest {:.3g}; at the fixed lag over the whole overlap {:.3g})",
      s.lag_s, s.lag_drift_s, s.max_mismatch, s.stretch_s, 100.0 * s.share,
      100.0 * o.repetition.min_share, s.stretch_max_mismatch, s.mismatch);
  if (!c.positive) {
    note(s.repeats, found);
    return;
  }
  const double slowest =
      e.lyapunov_found ? e.lyapunov_per_s - o.lyapunov_sigmas * e.lyapunov_slope_uncertainty_per_s
                       : e.rising_low_per_s;
  const bool veto = s.repeats && s.growth_per_s < slowest;
  note(veto, fmt::format("{}; the mismatch grows along it at {:.3g} 1/s (a veto needs less than "
                         "{:.3g} 1/s, the slowest exponent the divergence supports): {}",
                         found, s.growth_per_s, slowest,
                         veto ? "no exponential divergence (veto)" : "no veto"));
  c.positive = !veto;
}

void note_zero_one(const RegimeEvidence& e, const VerdictOptions& o, Notes& note, Criteria& c) {
  if (!e.zero_one_run) {
    note.info("0-1 test: " + e.zero_one_note);
    return;
  }
  c.diffusive = note(e.zero_one_K >= o.zero_one_split,
                     fmt::format("0-1 test: K = {:.3f} (quartiles {:.3f} .. {:.3f}) >= {} "
                                 "(chaotic or stochastic; below: regular)",
                                 e.zero_one_K, e.zero_one_q25, e.zero_one_q75, o.zero_one_split));
  c.regular_K = !c.diffusive;
  c.clearly_regular = e.zero_one_q75 < o.zero_one_split;
}

// Where the record's prediction error lies among the surrogates' (rank = how many are
// smaller), as the evidence line states it: it must say "above" when it is above.
std::string surrogate_position(std::size_t rank, std::size_t count) {
  if (rank == 0) return fmt::format("below all {} IAAFT surrogates", count);
  if (rank >= count) return fmt::format("above all {} IAAFT surrogates", count);
  return fmt::format("above {} of {} IAAFT surrogates", rank, count);
}

// Determinism: with the surrogate test run, "more predictable than every IAAFT surrogate"
// (a calibrated test against linear noise); without it, the prediction-error ratio alone.
void note_determinism(const RegimeEvidence& e, const VerdictOptions& o, Notes& note,
                      Criteria& c) {
  const double ratio =
      e.prediction_linear > 0 ? e.prediction_nonlinear / e.prediction_linear : 1.0;
  const std::string line = fmt::format(
      "local-constant prediction error {:.3g}, linear {:.3g} (ratio {:.3g}; deterministic "
      "below {})",
      e.prediction_nonlinear, e.prediction_linear, ratio, o.max_prediction_ratio);
  const bool by_ratio = e.prediction_computed && ratio <= o.max_prediction_ratio;
  note.info(fmt::format("Cao's max |E2 - 1| = {:.3f} (reported; ~0 for white noise)",
                        e.determinism));
  if (!e.surrogate_run) {
    note.info("surrogate test: " + e.surrogate_note);
    if (!e.prediction_computed) {
      note.info("determinism: the record is too short for the prediction test");
      return;
    }
    c.deterministic = note(by_ratio, "deterministic: " + line);
    c.noise_like = !c.deterministic;
    return;
  }
  note.info(line);
  const bool nonlinear_wins =
      !e.prediction_computed || ratio < o.surrogate_max_prediction_ratio;
  c.deterministic = note(
      e.surrogate_more_predictable && nonlinear_wins,
      fmt::format("deterministic: the record's prediction error is {} (needs below all; rank "
                  "{}, p = {:.3f}; linear-stochastic null {}), and the local-constant "
                  "predictor {} the linear one (ratio {:.3g}; needs below {})",
                  surrogate_position(e.surrogate_rank, e.surrogate_count), e.surrogate_rank,
                  e.surrogate_p,
                  e.surrogate_rejected ? "rejected" : "kept",
                  nonlinear_wins ? "beats" : "does not beat", ratio,
                  o.surrogate_max_prediction_ratio));
  c.noise_like = !e.surrogate_rejected;
}

void note_regularity(const RegimeEvidence& e, const VerdictOptions& o, Notes& note,
                     Criteria& c) {
  c.persistent = note(autocorrelation_persists(e, o),
                      fmt::format("autocorrelation persists: late envelope {:.3f} >= {}",
                                  e.late_acf, o.periodic_min_late_acf));
  c.concentrated = note(spectrum_concentrated(e, o),
                        fmt::format("concentrated spectrum: broadband share {:.3f} < {}",
                                    e.broadband_share, o.periodic_max_broadband));
  c.second_line = note(
      e.second_line_incommensurate && e.second_line_power >= o.second_line_min_power,
      e.second_line_power > 0.0
          ? fmt::format("second spectral line: {:.3g} of the first's power (>= {}), frequency "
                        "ratio {:.4f} ({})",
                        e.second_line_power, o.second_line_min_power, e.second_line_ratio,
                        e.second_line_incommensurate ? "no p/q with q <= 3" : "rational")
          : std::string("second spectral line: none"));
}

// IAAFT surrogates keep the record's values and its spectrum, so they hold as many samples
// near zero as the record: where the record is no more predictable than they are (the null
// of a linear process seen through a static transform kept), its "rests" are passages through
// zero of such a process (cubed low-passed noise lingers there), not a body at rest.
bool rests_in_noise(bool stochastic, bool surrogate_run) { return surrogate_run && stochastic; }

// A divergence that every sign of regularity contradicts — the 0-1 test's upper quartile low,
// a concentrated spectrum and a persisting autocorrelation — is the phase diffusion of a noisy
// cycle: noise moves neighbours along the cycle, and their separation creeps up over a few
// orbits (docs/notes/analysis.md "Noise floor").
// Only a record with a resolved noise floor has a noise to diffuse: on a clean record such a
// rise stays undetermined.
bool divergence_contradicted(const Criteria& c) {
  return c.noisy && c.positive && c.clearly_regular && c.concentrated && c.persistent;
}

Regime combine(const Criteria& c, const Verdict& v, bool zero_one_run, bool surrogate_run) {
  const bool chaotic = !c.steady && c.positive && c.deterministic && !c.clearly_regular;
  // The 0-1 test tells regular from irregular motion on any waveform; without it, a
  // concentrated spectrum and a persisting autocorrelation must both say so. A record that
  // repeats itself over most of its length is regular whatever K says: sharp relaxation
  // edges read K ~ 0.9.
  const bool regular = !c.steady && (!c.positive || divergence_contradicted(c)) &&
                       (c.repeats || (zero_one_run ? c.regular_K : c.concentrated && c.persistent));
  // Irregular: K high; without the 0-1 test (too few points after down-sampling), a broadband
  // spectrum and a dying autocorrelation, but only where the surrogates calibrated the null.
  const bool irregular =
      zero_one_run ? c.diffusive : surrogate_run && !c.concentrated && !c.persistent;
  const bool stochastic = !c.steady && !regular && !c.deterministic && c.noise_like && irregular;
  if (chaotic) return Regime::kChaotic;
  if (v.stick_slip && !rests_in_noise(stochastic, surrogate_run)) return Regime::kStickSlip;
  if (c.steady) return Regime::kSteady;
  if (regular) return c.second_line ? Regime::kQuasiPeriodic : Regime::kPeriodic;
  if (stochastic) return Regime::kStochastic;
  return Regime::kUndetermined;
}

}  // namespace

const char* regime_name(Regime r) {
  switch (r) {
    case Regime::kSteady:
      return "steady";
    case Regime::kPeriodic:
      return "periodic";
    case Regime::kQuasiPeriodic:
      return "quasi-periodic";
    case Regime::kStickSlip:
      return "stick-slip";
    case Regime::kChaotic:
      return "chaotic";
    case Regime::kStochastic:
      return "stochastic";
    case Regime::kUndetermined:
      return "undetermined";
  }
  return "?";
}

std::string verdict_rule(const VerdictOptions&) {
  return "exponential divergence = (the divergence curve rises above 3 sigma, or without a "
         "linear region its one-orbit local slopes stay positive all along its rise where the "
         "spectrum is broadband, the autocorrelation dies, the 0-1 test runs and reads K high "
         "and the record does not rest like stick-slip) AND NOT "
         "the record repeats itself (a small mismatch at one lag over most of the record, "
         "growing slower than that rise); deterministic = more predictable than every surrogate and by the "
         "local-constant predictor more than the linear one (where run; else prediction ratio "
         "low); chaotic = exponential divergence AND deterministic AND "
         "NOT (0-1 K's upper quartile low, where run); else stick-slip if flagged (unless "
         "stochastic with the surrogates run: rests of a linear process seen through a static "
         "transform); else "
         "steady; else regular = (no exponential divergence OR, with a noise floor resolved, 0-1 K's upper "
         "quartile low AND a concentrated spectrum AND a persisting autocorrelation) AND (the record repeats itself OR 0-1 K "
         "low, where run; else a concentrated spectrum AND a persisting autocorrelation): "
         "quasi-periodic with a second incommensurate line, periodic without; else stochastic = "
         "NOT deterministic AND (surrogates keep the linear null, where run) AND (0-1 K high, "
         "where run; else surrogates run AND a broadband spectrum AND a dying autocorrelation); "
         "else undetermined";
}

bool is_steady(const RegimeEvidence& e, const VerdictOptions& o) {
  return e.last_half_std <= o.steady_variation * std::max(std::abs(e.last_half_mean), e.range);
}

bool rests_like_stick_slip(const RegimeEvidence& e, const VerdictOptions& o) {
  return e.rests_judged && e.rests_above_noise && e.rest_intervals >= o.min_rest_intervals &&
         e.rest_share >= o.min_rest_share;
}

Verdict decide_regime(const RegimeEvidence& e, const VerdictOptions& o) {
  Verdict v;
  Notes note(v);
  if (e.samples < o.min_samples) {
    note(false,
         fmt::format("{} samples, at least {} needed for a verdict", e.samples, o.min_samples));
    return v;
  }
  Criteria c;
  c.noisy = e.noise_sd > 0.0;
  if (e.rests_judged && !e.rests_above_noise) {
    v.stick_slip = note(false, fmt::format("stick-slip: not judged: the noise floor {:.3g} widens "
                                           "the rest band to {:.3g}, more than {} x max|x|: "
                                           "rests cannot be told from the noise",
                                           e.rest_noise_sd, e.rest_level, o.max_rest_band));
  } else if (e.rests_judged) {
    v.stick_slip =
        note(rests_like_stick_slip(e, o),
             fmt::format(
                 "stick-slip: {} flat rest intervals of >= {} samples at |x| <= {:.4g} "
                 "({} x max|x|{}) (need {}), {:.1f} % of the time at rest (need {:.1f} %)",
                 e.rest_intervals, o.min_rest_samples, e.rest_level, o.rest_fraction,
                 e.rest_noise_sd > 0.0 ? fmt::format(" + {} x 1.25 x the noise floor {:.3g} / "
                                                "sqrt({}) (a median's sd), on the running "
                                                "median over {} samples; without a "
                                                "trend and within {} x the noise about zero",
                                                o.rest_noise_sigmas, e.rest_noise_sd,
                                                o.rest_window_in_noise, o.rest_window_in_noise,
                                                o.rest_max_rms)
                                  : std::string(),
                 o.min_rest_intervals, 100.0 * e.rest_share, 100.0 * o.min_rest_share));
  } else {
    note.info("stick-slip: not judged: the record is not a velocity, and a rest is a run at zero "
              "velocity");
  }
  const double scale = std::max(std::abs(e.last_half_mean), e.range);
  c.steady = note(is_steady(e, o), fmt::format("steady: std of the last half {:.4g} <= {} x {:.4g}",
                                               e.last_half_std, o.steady_variation, scale));
  if (!c.steady) {
    note_exponent(e, o, note, c);
    note_repetition(e, o, note, c);
    note_zero_one(e, o, note, c);
    note_determinism(e, o, note, c);
    note_regularity(e, o, note, c);
  }
  if (!c.steady && divergence_contradicted(c)) {
    note.info("the divergence is not taken: the 0-1 test's upper quartile, the spectrum and the "
              "autocorrelation all read the motion regular (a noisy cycle's phase diffusion)");
  }
  v.regime = combine(c, v, e.zero_one_run, e.surrogate_run);
  v.chaotic = v.regime == Regime::kChaotic;
  if (v.stick_slip && v.regime == Regime::kStochastic) {
    v.stick_slip = note(false, "stick-slip: the rests are a linear process's passages through "
                               "zero: surrogates with the same values are as predictable");
  }
  // "stochastic" is what the tests could establish, not where the record came from: a
  // noise-free simulation can earn it, so the verdict says what it means.
  if (v.regime == Regime::kStochastic) {
    note.info("stochastic means: irregular, and not distinguishable from linearly filtered "
              "noise by these tests; it does not say the source is random (a noise-free "
              "simulation can be judged so)");
  }
  note.info("rule: " + verdict_rule(o));
  return v;
}

}  // namespace pneumachaos
