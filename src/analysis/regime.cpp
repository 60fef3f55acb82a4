#include "pneumachaos/analysis/regime.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

namespace pneumachaos {

const char* regime_name(Regime r) {
  switch (r) {
    case Regime::kSteady:
      return "steady";
    case Regime::kPeriodic:
      return "periodic";
    case Regime::kStickSlip:
      return "stick-slip";
    case Regime::kChaotic:
      return "chaotic";
    case Regime::kUndetermined:
      return "undetermined";
  }
  return "?";
}

bool is_steady(const RegimeEvidence& e, const VerdictOptions& o) {
  return e.last_half_std <= o.steady_variation * std::max(std::abs(e.last_half_mean), e.range);
}

Verdict decide_regime(const RegimeEvidence& e, const VerdictOptions& o) {
  Verdict v;
  const auto note = [&](bool ok, const std::string& text) {
    v.evidence.push_back(fmt::format("[{}] {}", ok ? "yes" : "no", text));
    return ok;
  };
  if (e.samples < o.min_samples) {
    note(false,
         fmt::format("{} samples, at least {} needed for a verdict", e.samples, o.min_samples));
    return v;
  }
  v.stick_slip =
      note(e.rest_intervals >= o.min_rest_intervals && e.rest_share >= o.min_rest_share,
           fmt::format("stick-slip: {} flat rest intervals of >= {} samples at |x| <= {} x max|x| "
                       "(need {}), {:.1f} % of the time at rest (need {:.1f} %)",
                       e.rest_intervals, o.min_rest_samples, o.rest_fraction, o.min_rest_intervals,
                       100.0 * e.rest_share, 100.0 * o.min_rest_share));
  const double scale = std::max(std::abs(e.last_half_mean), e.range);
  const bool steady =
      note(is_steady(e, o), fmt::format("steady: std of the last half {:.4g} <= {} x {:.4g}",
                                        e.last_half_std, o.steady_variation, scale));
  const bool positive = note(
      e.lyapunov_found && e.lyapunov_per_s > o.lyapunov_sigmas * e.lyapunov_uncertainty_per_s &&
          e.lyapunov_per_s > 0.0,
      e.lyapunov_found
          ? fmt::format("divergence exponent {:.4g} +- {:.2g} 1/s above {} sigma", e.lyapunov_per_s,
                        e.lyapunov_uncertainty_per_s, o.lyapunov_sigmas)
          : std::string("divergence curve: no rising linear region"));
  const bool broad = note(e.broadband_share >= o.min_broadband,
                          fmt::format("broadband spectrum: share outside the strongest bins "
                                      "{:.3f} >= {}",
                                      e.broadband_share, o.min_broadband));
  const bool decays = note(e.late_acf <= o.max_late_acf,
                           fmt::format("autocorrelation decayed: late envelope {:.3f} <= {}",
                                       e.late_acf, o.max_late_acf));
  const bool deterministic = note(e.determinism >= o.min_determinism,
                                  fmt::format("deterministic: max |E2 - 1| = {:.3f} >= {} (Cao)",
                                              e.determinism, o.min_determinism));
  v.chaotic = !steady && positive && broad && decays && deterministic;
  const bool periodic =
      !steady && !v.chaotic && !positive &&
      (e.broadband_share < o.periodic_max_broadband || e.late_acf >= o.periodic_min_late_acf);
  v.regime = v.chaotic      ? Regime::kChaotic
             : v.stick_slip ? Regime::kStickSlip
             : steady       ? Regime::kSteady
             : periodic     ? Regime::kPeriodic
                            : Regime::kUndetermined;
  return v;
}

}  // namespace pneumachaos
