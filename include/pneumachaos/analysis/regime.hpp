#pragma once
// The regime verdict of a record (ANALYSIS.md "Regime verdict"): steady, periodic, stick-slip,
// chaotic or undetermined, with the evidence and the thresholds that decided it. Chaotic and
// stick-slip are separate flags, as the paper's maps overlay them.

#include <cstddef>
#include <string>
#include <vector>

namespace pneumachaos {

enum class Regime { kSteady, kPeriodic, kStickSlip, kChaotic, kUndetermined };
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
  /// Steady: the last half varies (std) by at most this fraction of max(|mean|, range).
  double steady_variation = 0.01;
  /// Chaotic needs all of: divergence exponent above lyapunov_sigmas x its uncertainty;
  /// broadband share of the spectrum at least min_broadband; late autocorrelation envelope at
  /// most max_late_acf (it has decayed); Cao's E2 away from 1 by min_determinism somewhere
  /// (E2 ~ 1 at every d marks a stochastic record).
  double lyapunov_sigmas = 3.0;
  double min_broadband = 0.1;  ///< a tone with 5 % noise: 0.005; Lorenz x: 0.24
  double max_late_acf = 0.35;
  double min_determinism = 0.1;
  /// Periodic: no significant positive exponent, and the spectrum concentrated (broadband
  /// share below this) or the ACF persisting. Conflicting evidence (a positive exponent on a
  /// phase-coherent record such as Rossler's) is "undetermined", with the reasons listed.
  double periodic_max_broadband = 0.3;
  double periodic_min_late_acf = 0.5;
};

/// The numbers the verdict reads (computed by analyze_series).
struct RegimeEvidence {
  std::size_t samples = 0;
  double mean = 0.0, range = 0.0, last_half_std = 0.0, last_half_mean = 0.0;
  std::size_t rest_intervals = 0;
  double rest_share = 0.0;  ///< fraction of samples at rest
  bool lyapunov_found = false;
  double lyapunov_per_s = 0.0, lyapunov_uncertainty_per_s = 0.0;
  double broadband_share = 0.0, late_acf = 0.0, determinism = 0.0;
};

struct Verdict {
  Regime regime = Regime::kUndetermined;
  bool chaotic = false;
  bool stick_slip = false;
  std::vector<std::string> evidence;  ///< one line per criterion: value, threshold, outcome
};

Verdict decide_regime(const RegimeEvidence& e, const VerdictOptions& o = {});

/// The steady criterion alone: a record damped to a constant has no dynamics to embed, so the
/// analysis stops before the embedding and the Lyapunov estimators.
bool is_steady(const RegimeEvidence& e, const VerdictOptions& o = {});

}  // namespace pneumachaos
