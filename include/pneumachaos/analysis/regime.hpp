#pragma once
// The regime verdict of a record (docs/notes/analysis.md "Regime verdict"): steady, periodic,
// quasi-periodic, stick-slip, chaotic, stochastic or undetermined, with the evidence, the
// thresholds and the rule that decided it. Chaotic and stick-slip are separate flags, as the
// paper's maps overlay them. No single index vetoes: the spectrum and the autocorrelation are
// reported, and only decide between regular regimes.

#include <cstddef>
#include <string>
#include <vector>

#include "pneumachaos/analysis/self_repetition.hpp"

namespace pneumachaos {

enum class Regime {
  kSteady,
  kPeriodic,
  kStickSlip,
  kChaotic,
  kUndetermined,
  kQuasiPeriodic,
  kStochastic
};
const char* regime_name(Regime r);

struct VerdictOptions {
  std::size_t min_samples = 1000;  ///< fewer: undetermined
  /// Rest (stick): |x| at most this fraction of max |x| and flat (its spread within the run at
  /// most half that level, which a mere zero crossing is not) for at least min_rest_samples
  /// in a row, at least min_rest_intervals times. Meaningful where zero means rest (a velocity).
  double rest_fraction = 0.01;
  std::size_t min_rest_samples = 5;
  std::size_t min_rest_intervals = 2;
  /// ...and together at least this share of the record: stick-slip rests for a good part of
  /// each cycle, while a chaotic record may linger near zero now and then (Lorenz's origin).
  double min_rest_share = 0.02;
  /// With white noise of sd sigma in the record (AnalysisResult::noise), a rest's band widens
  /// by this many sigma (a resting sample stays within 3.5 sigma with probability 99.95 %),
  /// and a run counts only if its fitted change along it stays within rest_trend_sigmas
  /// standard errors of what the noise alone gives (a real rest fails that 1 time in 20; the
  /// flag needs several rests): a smooth passage through zero keeps its slope.
  double rest_noise_sigmas = 3.5;
  double rest_trend_sigmas = 2.0;
  /// ...and its samples' RMS about zero at most this many sigma: a rest is the noise about
  /// zero (n >= 5 resting samples exceed 1.5 sigma with a chance below 5 %, 10 below 1.5 %),
  /// while a noise-driven motion lingering near zero (an AR(1) process) sits off it.
  double rest_max_rms = 1.5;
  /// Under noise the band is judged on the running median over this many samples (20 ms at
  /// 1 kHz): a noise-driven motion (an AR(1) process) passes through the raw samples' widened
  /// band in a few samples looking at rest, while the median over the window follows its
  /// wander out of the band; a body at rest keeps the median at zero while it rests for more
  /// than half the window.
  std::size_t rest_window_in_noise = 20;
  /// Rests are told from noise only where the band the noise widens stays within this
  /// fraction of max|x| (ten times the clean band): beyond, a record of noise alone would
  /// rest all the time, and rests are not judged.
  double max_rest_band = 0.1;
  /// Steady: the last half varies (std) by at most this fraction of max(|mean|, range).
  double steady_variation = 0.01;
  /// Exponential divergence: the divergence exponent above lyapunov_sigmas x its slope's
  /// uncertainty (the curve rises significantly; docs/notes/analysis.md "Divergence exponent's
  /// uncertainty").
  double lyapunov_sigmas = 3.0;
  /// The 0-1 test's K tends to 0 for regular and to 1 for chaotic (or stochastic) dynamics;
  /// the midpoint splits them.
  double zero_one_split = 0.5;
  /// Determinism: the local-constant predictor's error at most this fraction of the linear
  /// predictor's (for a linear Gaussian process the linear one is optimal: ratio >= ~1).
  double max_prediction_ratio = 0.5;
  /// With the surrogate test run, determinism also needs the local-constant predictor to beat
  /// the linear one clearly (ratio below this). A linear record beats all 39 surrogates by
  /// chance once in 40, and a noise-driven nonlinear oscillator beats them every time, yet
  /// both are forecast about as well linearly (ratio 0.9-1.4); noisy chaos reads 0.6-0.76
  /// (docs/validation.md, the blind-records row).
  double surrogate_max_prediction_ratio = 0.8;
  /// Regular motion keeps its autocorrelation: late envelope at least this (a tone: ~0.8).
  double periodic_min_late_acf = 0.5;
  /// Without a 0-1 test, regular also needs a concentrated spectrum (broadband share below).
  double periodic_max_broadband = 0.3;
  /// Quasi-periodic: a second spectral line, not a rational multiple p/q (q <= 3) of the
  /// first, carrying at least this fraction of the first line's power.
  double second_line_min_power = 0.01;
  /// Self-repetition veto: a record that repeats itself at one lag over most of its length,
  /// with a mismatch that does not grow at the claimed rate, has no exponential divergence.
  SelfRepetitionOptions repetition;
  /// Throws Error naming the first threshold out of its range (a NaN is out of every range).
  void validate() const;
};

/// The numbers the verdict reads (computed by analyze_series).
struct RegimeEvidence {
  std::size_t samples = 0;
  double mean = 0.0, range = 0.0, last_half_std = 0.0, last_half_mean = 0.0;
  /// Rests are looked for only in a velocity, where zero means rest (AnalysisOptions::velocity).
  bool rests_judged = true;
  /// The record's white noise the rests were judged with: 0 where none is resolved or it is
  /// too small to break the clean rule (rest_statistics).
  double rest_noise_sd = 0.0;
  /// The band |x| <= rest_level a rest stays in (under noise: on the running median over
  /// rest_window_in_noise samples); where rests are not judged, the raw samples' band.
  double rest_level = 0.0;
  /// The raw samples' band is narrow enough to tell rests from the noise
  /// (VerdictOptions::max_rest_band).
  bool rests_above_noise = true;
  /// The record's white noise floor (estimate_noise_floor), 0 where none is resolved.
  double noise_sd = 0.0;
  std::size_t rest_intervals = 0;
  double rest_share = 0.0;  ///< fraction of samples at rest
  bool lyapunov_found = false;
  /// Without a linear region: the divergence curve's one-orbit local slopes over its rise,
  /// their 10 % quantile and median [1/s] (0 where they were not computed). Evidence of
  /// divergence only with the other indices' support (verdict_rule).
  double rising_low_per_s = 0.0, rising_median_per_s = 0.0;
  /// The curve rises all along its rise: even the 10 % quantile of its local slopes is above 0.
  [[nodiscard]] bool rises_throughout() const { return rising_low_per_s > 0.0; }
  double lyapunov_per_s = 0.0, lyapunov_uncertainty_per_s = 0.0;
  double lyapunov_slope_uncertainty_per_s = 0.0;  ///< the chosen window's slope alone
  double broadband_share = 0.0, late_acf = 0.0;
  double determinism = 0.0;  ///< Cao's max |E2 - 1| (reported)
  bool zero_one_run = false;
  std::string zero_one_note;  ///< why not run, when not
  double zero_one_K = 0.0, zero_one_q25 = 0.0, zero_one_q75 = 0.0;
  bool prediction_computed = false;
  double prediction_nonlinear = 0.0, prediction_linear = 0.0;
  bool surrogate_run = false;
  std::string surrogate_note;  ///< why not run, when not
  std::size_t surrogate_count = 0, surrogate_rank = 0;
  double surrogate_p = 1.0;
  bool surrogate_rejected = false, surrogate_more_predictable = false;
  /// Second spectral line (relative power; 0 when none) and its frequency ratio to the first.
  double second_line_power = 0.0, second_line_ratio = 0.0;
  bool second_line_incommensurate = false;
  SelfRepetition repetition;  ///< computed with VerdictOptions::repetition
};

struct Verdict {
  Regime regime = Regime::kUndetermined;
  bool chaotic = false;
  bool stick_slip = false;
  std::vector<std::string> evidence;  ///< one line per criterion: value, threshold, outcome
};

Verdict decide_regime(const RegimeEvidence& e, const VerdictOptions& o = {});

/// The rule that combines the criteria, in words (printed with every verdict).
std::string verdict_rule(const VerdictOptions& o = {});

/// The steady criterion alone: a record damped to a constant has no dynamics to embed, so the
/// analysis stops before the embedding and the Lyapunov estimators.
bool is_steady(const RegimeEvidence& e, const VerdictOptions& o = {});

/// Whether the record rests often and long enough for stick-slip (VerdictOptions'
/// min_rest_intervals and min_rest_share); false where rests are not judged.
bool rests_like_stick_slip(const RegimeEvidence& e, const VerdictOptions& o = {});

}  // namespace pneumachaos
