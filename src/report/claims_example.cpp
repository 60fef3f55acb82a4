// The claims of the chaotic example (Fig. 7), the circuits' responses (Fig. 2), the friction
// loop (Fig. 3) and the paper's linear analysis (eqs. 9, 11), each judged by a rule of
// claim_rules.hpp.
#include <fmt/format.h>

#include <cmath>

#include "pneumachaos/report/claim_rules.hpp"
#include "pneumachaos/report/claims.hpp"

namespace pneumachaos {
namespace {

const char* verdict(bool ok) { return ok ? "agrees" : "disagrees"; }

Claim missing(Claim c, const char* why) {
  c.ours = why;
  c.verdict = "not reproduced";
  return c;
}

Claim exponent(const ClaimInputs& in) {
  Claim c{"the chaotic example (S1 2.70, S2 0.35 mm^2): the maximum Lyapunov exponent converged "
          "to a positive value",
          "Fig. 7b: 3.41 (unit not stated)", "", "",
          "agrees if the settled record is judged chaotic (docs/analysis.md) and its divergence "
          "exponent exceeds 3 times its uncertainty",
          "fig7b_indices"};
  if (!in.example_lambda || !in.example_uncertainty || !in.example_chaotic)
    return missing(c, "no rising divergence curve");
  c.ours = fmt::format(
      "record: {:.2f} +- {:.2f} 1/s, regime {}{}", *in.example_lambda, *in.example_uncertainty,
      *in.example_chaotic ? "chaotic" : "not chaotic",
      in.example_model_lambda
          ? fmt::format("; model: {:.2f}{} 1/s", *in.example_model_lambda,
                        in.example_model_uncertainty
                            ? fmt::format(" +- {:.2f}", *in.example_model_uncertainty)
                            : std::string())
          : std::string());
  c.verdict = verdict(positive_exponent_of_chaos(*in.example_lambda, *in.example_uncertainty,
                                                 *in.example_chaotic));
  return c;
}

Claim spectrum(const ClaimInputs& in) {
  Claim c{"the power spectrum exhibits wide and even distribution without dominant peaks",
          "Fig. 7b", "", "", "agrees if no spectral peak (+-1 bin) holds more than 25 % of the power",
          "fig7b_indices"};
  if (!in.example_peak_share) return missing(c, "no record");
  c.ours = fmt::format("strongest peak: {:.0f} % of the power", 100 * *in.example_peak_share);
  c.verdict = verdict(spectrum_without_dominant_peak(*in.example_peak_share));
  return c;
}

Claim acf(const ClaimInputs& in) {
  Claim c{"the auto-correlation function converged to zero", "Fig. 7b", "", "",
          "agrees if |ACF| stays at most 0.2 at every lag of 1 s or more", "fig7b_indices"};
  if (!in.example_acf_after_1s) return missing(c, "no record");
  c.ours = fmt::format("largest |ACF| after 1 s: {:.2f}", *in.example_acf_after_1s);
  c.verdict = verdict(acf_converged(*in.example_acf_after_1s));
  return c;
}

Claim contrast(const ClaimInputs& in) {
  Claim c{"meter-out: the velocity fluctuates considerably; meter-in: slight oscillation and "
          "high attenuation; the speed depends on S in both",
          "Fig. 2 (paper's model)", "", "",
          "agrees if every meter-out fluctuation (std/mean after 1 s) is at least 3 times every "
          "meter-in one, and the mean speed rises with S in both circuits",
          "fig2_time_responses"};
  if (!in.fig2) return missing(c, "no records");
  const auto list = [](const std::vector<double>& x, double scale) {
    std::string s;
    for (double v : x) s += fmt::format("{}{:.2g}", s.empty() ? "" : ", ", scale * v);
    return s;
  };
  const CircuitContrast& f = *in.fig2;
  c.ours = fmt::format(
      "fluctuation meter-out {}, meter-in {}; mean speed [mm/s] meter-out {}, meter-in {}",
      list(f.meter_out_fluctuation, 1), list(f.meter_in_fluctuation, 1),
      list(f.meter_out_mean, 1e3), list(f.meter_in_mean, 1e3));
  c.verdict = verdict(fluctuates_much_more(f.meter_out_fluctuation, f.meter_in_fluctuation) &&
                      strictly_increasing(f.meter_out_mean) &&
                      strictly_increasing(f.meter_in_mean));
  return c;
}

Claim friction(const ClaimInputs& in) {
  Claim c{"the friction-velocity characteristic has a negative slope (B < 0) at low velocity",
          "Fig. 3, Section 3.4", "", "",
          "agrees if the least-squares slope dF/dv of the chaotic record's samples with "
          "0 < v <= the stated speed is negative",
          "fig3_friction_velocity"};
  if (!in.friction_slope || std::isnan(*in.friction_slope)) return missing(c, "too few samples");
  c.ours = fmt::format("{:.0f} N s/m for 0 < v <= {:.1f} mm/s", *in.friction_slope,
                       1e3 * in.friction_slope_vmax);
  c.verdict = verdict(*in.friction_slope < 0.0);
  return c;
}

Claim sign_rule(const ClaimInputs& in) {
  Claim c{"a1 < 0 (eq. 9) or b1 < 0 (eq. 11): self-excited oscillation; otherwise damped",
          "Section 3.4", "", "",
          "agrees if >= 80 % of the map's points the sign rule calls damped are steady in at "
          "least half of their runs, and >= 80 % of those it calls self-excited are not",
          "stability_map"};
  if (!in.sign_rule) return missing(c, "no map");
  const SignRuleCounts& s = *in.sign_rule;
  c.ours = fmt::format("damped: {} of {} points steady; self-excited: {} of {} moving",
                       s.damped_steady, s.damped, s.excited_moving, s.excited);
  c.verdict = verdict(5 * s.damped_steady >= 4 * s.damped && 5 * s.excited_moving >= 4 * s.excited &&
                      s.damped + s.excited > 0);
  return c;
}

Claim damping(const std::string& what, const char* paper, const std::optional<DampingChange>& d,
              bool need_a1_b1) {
  Claim c{what, paper, "", "",
          need_a1_b1 ? "agrees if a1 (eq. 9) and b1 (eq. 11) both increase at the example point"
                     : "agrees if b1 (eq. 11) increases and the full model's largest real part "
                       "decreases at the example point",
          "stability_map"};
  if (!d) return missing(c, "no steady motion");
  c.ours = fmt::format("a1 {:.1f} -> {:.1f} N s/m, b1 {:.1f} -> {:.1f} N s/m, largest real part "
                       "{:.2f} -> {:.2f} 1/s",
                       d->a1_before, d->a1_after, d->b1_before, d->b1_after, d->max_re_before,
                       d->max_re_after);
  const bool b1_up = d->b1_after > d->b1_before;
  c.verdict = verdict(need_a1_b1 ? b1_up && d->a1_after > d->a1_before
                                 : b1_up && d->max_re_after < d->max_re_before);
  return c;
}

Claim fold(const ClaimInputs& in) {
  Claim c{"the trajectory is folded between 180 and 140 and stretched between 140 and 0",
          "Fig. 7c (velocities in mm/s)", "", "",
          "agrees if at least half of the velocity maxima (where the trajectory turns back) lie in "
          "140-180 mm/s and nearby trajectories separate faster in 0-140 mm/s than in "
          "140-180 mm/s, the rate there positive, each beyond 3 standard errors",
          "fig7c_trajectory"};
  if (!in.fold_stretch) return missing(c, "no record");
  const FoldStretch& f = *in.fold_stretch;
  c.ours = fmt::format("{:.0f} % of {} maxima in 140-180 mm/s; local stretching {:.1f} +- {:.1f} "
                       "1/s in 0-140, {:.1f} +- {:.1f} 1/s in 140-180 mm/s",
                       100 * f.maxima_in_fold_band, f.maxima, f.stretch_rate, f.stretch_se,
                       f.fold_rate, f.fold_se);
  c.verdict = verdict(folded_and_stretched(f));
  return c;
}

Claim loop(const ClaimInputs& in) {
  Claim c{"near the border the friction force makes a loop (A-B-C-B-D-A) and greatly fluctuates "
          "without a standstill",
          "Fig. 3, Section 4", "", "",
          "agrees if the chaotic record is below 1 mm/s less than 1 % of the time and, in at least "
          "half of 10 velocity bins, accelerating and decelerating friction differ beyond 3 "
          "standard errors",
          "fig3_friction_velocity"};
  if (!in.friction_loop) return missing(c, "no record");
  const FrictionLoop& l = *in.friction_loop;
  c.ours = fmt::format("standstill {:.1f} % of the time; hysteresis in {} of {} velocity bins",
                       100 * l.standstill_share, l.hysteretic_bins, l.bins);
  c.verdict = verdict(loops_without_standstill(l));
  return c;
}

}  // namespace

std::vector<Claim> example_claims(const ClaimInputs& in) {
  return {exponent(in),
          spectrum(in),
          acf(in),
          contrast(in),
          friction(in),
          sign_rule(in),
          damping("increased supply pressure (0.25 -> 0.30 MPa) improves damping", "Fig. 5, eq. 11",
                  in.higher_ps, false),
          damping("additional load (1.5 -> 3.0 kg) increases a damping coefficient",
                  "Fig. 6, eqs. 9 and 11", in.heavier, true),
          fold(in),
          loop(in)};
}

}  // namespace pneumachaos
