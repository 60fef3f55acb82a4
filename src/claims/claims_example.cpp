// The claims of the chaotic example (Fig. 7), the circuits' responses (Fig. 2), the friction
// (Fig. 3) and the paper's linear analysis (Section 3), each judged by a rule of
// claim_rules.hpp.
#include <fmt/format.h>

#include <cmath>

#include "pneumachaos/claims/claims.hpp"

namespace pneumachaos {
namespace {

constexpr double kBitsPerNat = 1.4426950408889634;  // 1 / ln 2

const char* kFig7Exponent = "The maximum Lyapunov exponent converged to a positive value (3.41).";
const char* kFig2 =
    "In Fig. 2a, the velocity fluctuates considerably and, on the contrary, Figure 2b presents "
    "slight oscillation and high attenuation.";
const char* kLoop =
    "Closely investigating frictional characteristics around there, it can be seen that the "
    "friction force makes a loop, such as A -> B -> C -> B -> D -> A in Fig. 3, and that it "
    "greatly fluctuates without a standstill.";

Claim missing(Claim c, const char* why) {
  c.ours = "not measured";
  judge(c, {kNaN, why});
  return c;
}

std::string list(const std::vector<double>& x, double scale, const char* format) {
  std::string s;
  for (double v : x) s += (s.empty() ? "" : ", ") + fmt::format(fmt::runtime(format), scale * v);
  return s;
}

Claim exponent(const ClaimInputs& in) {
  Claim c{"fig7_exponent", kFig7Exponent, "Section 4.2, Fig. 7b",
          "the record's largest exponent is positive (the paper's unit is not stated: 3.41 1/s "
          "or 3.41 bits/s = 2.36 1/s)",
          "the settled record's divergence exponent above 3 times its uncertainty; its size is "
          "shown in 1/s and bits/s beside 3.41, not scored (it depends on the rig)",
          "fig7b_indices"};
  if (!in.example_lambda || !in.example_uncertainty)
    return missing(c, "the divergence curve of the record has no linear region");
  const double l = *in.example_lambda, u = *in.example_uncertainty;
  c.ours = fmt::format("record: {:.2f} +- {:.2f} 1/s = {:.2f} +- {:.2f} bits/s", l, u,
                       l * kBitsPerNat, u * kBitsPerNat);
  if (in.example_wolf) c.ours += fmt::format("; Wolf: {:.2f} 1/s", *in.example_wolf);
  if (in.example_model_lambda) {
    c.ours += fmt::format("; the model's own: {:.2f}", *in.example_model_lambda);
    if (in.example_model_uncertainty)
      c.ours += fmt::format(" +- {:.2f}", *in.example_model_uncertainty);
    c.ours += " 1/s";
  }
  judge(c, positive_exponent(l, u));
  return c;
}

Claim verdict(const ClaimInputs& in) {
  Claim c{"fig7_verdict",
          "Figure 7a exemplifies a velocity response having chaotic behavior (S1 = 2.70 mm2, "
          "S2 = 0.35 mm2). ... These results also support chaotic characteristics of "
          "oscillation.",
          "Section 4.2, Fig. 7",
          "the example's record, judged from its indices together, is chaotic",
          "the regime verdict of the settled record (docs/notes/analysis.md) is chaotic "
          "(margin +1 or "
          "-1)",
          "fig7a_record"};
  if (!in.example_chaotic) return missing(c, "no record");
  c.ours = "verdict: " + in.example_regime;
  judge(c, judged_chaotic(*in.example_chaotic, in.example_regime));
  return c;
}

Claim spectrum(const ClaimInputs& in) {
  Claim c{"fig7_spectrum",
          "Figure 7b shows a power spectrum to the time series of Fig. 7a, and it exhibits wide "
          "and even distribution without dominant peaks.",
          "Section 4.2, Fig. 7b", "no spectral line dominates the record's power",
          "no spectral peak (+-1 bin) holds more than 25 % of the power", "fig7b_indices"};
  if (!in.example_peak_share) return missing(c, "no record");
  c.ours = fmt::format("strongest peak: {:.0f} % of the power", 100 * *in.example_peak_share);
  if (in.example_spectrum_resolution_Hz && in.example_settled_s)
    c.ours += fmt::format(" (bins of {:.2g} Hz, Welch over the {:.1f} s settled record)",
                          *in.example_spectrum_resolution_Hz, *in.example_settled_s);
  judge(c, spectrum_without_dominant_peak(*in.example_peak_share));
  return c;
}

Claim acf(const ClaimInputs& in) {
  Claim c{"fig7_acf", "A value of the auto-correlation function to Fig. 7a converged to zero.",
          "Section 4.2, Fig. 7b", "the record forgets itself: its autocorrelation dies out",
          "|ACF| at most 0.2 at every lag of 1 s or more", "fig7b_indices"};
  if (!in.example_acf_after_1s)
    return missing(c, "no record, or one too short for its autocorrelation to reach 1 s");
  c.ours = fmt::format("largest |ACF| after 1 s: {:.2f}", *in.example_acf_after_1s);
  judge(c, acf_converged(*in.example_acf_after_1s));
  return c;
}

Claim fold(const ClaimInputs& in) {
  Claim c{"fig7_fold_stretch",
          "The trajectory is folded between 180 and 140 and is stretched between 140 and 0.",
          "Section 4.2, Fig. 7c",
          "on the plot's own scale (0 to 180, no unit), the trajectory turns back in the top "
          "22 % of its range and nearby trajectories separate below it",
          "at least half of the velocity maxima in the top 40/180 of the record's range (0.5 "
          "to 99.5 % quantiles), and the local stretching rate below that band positive beyond "
          "3 standard errors",
          "fig7c_trajectory"};
  if (!in.fold_stretch) return missing(c, "no record");
  const FoldStretch& f = *in.fold_stretch;
  c.ours = fmt::format("range {:.0f}-{:.0f} mm/s; {:.0f} % of {} maxima in the fold band; "
                       "stretching {:.1f} +- {:.1f} 1/s below it",
                       1e3 * f.low, 1e3 * f.high, 100 * f.maxima_in_fold_band, f.maxima,
                       f.stretch_rate, f.stretch_se);
  judge(c, folded_and_stretched(f));
  return c;
}

Claim transients(const ClaimInputs& in) {
  Claim c{"fig2_attenuation", kFig2, "Section 3.4, Fig. 2",
          "(a) meter-out, with P1 = Ps as Section 3.2 assumes, settles slowly (a1 ~ B); (b) "
          "meter-in, with the rod side at atmosphere as Section 3.3 assumes, settles fast "
          "(b1 >> B)",
          "every meter-in response decays at least twice as fast as every meter-out one (decay "
          "rate ln 20 / time to stay within 5 % of the final speed, the mean of the record's second half)",
          "fig2_time_responses"};
  if (!in.fig2) return missing(c, "no records");
  std::vector<double> out, min;
  for (const Settling& s : in.fig2->meter_out) out.push_back(s.decay_rate_per_s);
  for (const Settling& s : in.fig2->meter_in) min.push_back(s.decay_rate_per_s);
  c.ours = fmt::format("decay rate [1/s] at S = {} mm^2: meter-out {}, meter-in {}",
                       list(in.fig2->areas_mm2, 1, "{:g}"), list(out, 1, "{:.1f}"),
                       list(min, 1, "{:.1f}"));
  std::size_t unsettled = 0;
  for (const Settling& s : in.fig2->meter_out) unsettled += s.settled ? 0 : 1;
  if (unsettled > 0)
    c.ours += fmt::format(" ({} meter-out responses not settled in their record: bounds)",
                          unsettled);
  judge(c, attenuates_faster(min, out));
  return c;
}

Claim speed(const ClaimInputs& in) {
  Claim c{"fig2_speed_depends_on_area",
          "In addition, the velocity is dependent on the magnitude of the effective sectional "
          "area of restrictors in both cases.",
          "Section 3.4, Fig. 2", "a larger controlling valve gives a faster piston in both circuits",
          "the final speeds rise with the opening in both circuits (margin: the smallest "
          "relative step)",
          "fig2_time_responses"};
  if (!in.fig2) return missing(c, "no records");
  std::vector<double> out, min;
  for (const Settling& s : in.fig2->meter_out) out.push_back(s.final_value);
  for (const Settling& s : in.fig2->meter_in) min.push_back(s.final_value);
  c.ours = fmt::format("final speed [mm/s]: meter-out {}, meter-in {}", list(out, 1e3, "{:.0f}"),
                       list(min, 1e3, "{:.0f}"));
  judge(c, both(rises_with_area(out), rises_with_area(min)));
  return c;
}

Claim slope(const ClaimInputs& in) {
  Claim c{"sec34_negative_slope",
          "Therefore, with low velocity, the frictional coefficient B is negative and its "
          "magnitude varies remarkably.",
          "Section 3.4, Fig. 3", "friction falls as the speed rises from rest",
          "the least-squares line of friction against speed for 0 < v <= a quarter of the "
          "example's top speed falls (margin: its relative drop over that band)",
          "fig3_friction_velocity"};
  if (!in.friction_line) return missing(c, "no record");
  c.ours = fmt::format("{:.0f} N s/m for 0 < v <= {:.1f} mm/s", in.friction_line->slope,
                       1e3 * in.friction_slope_vmax);
  judge(c, negative_low_speed_slope(*in.friction_line, in.friction_slope_vmax));
  return c;
}

Claim loop(const ClaimInputs& in) {
  Claim c{"sec4_loop", kLoop, "Section 4.2, Fig. 3",
          "near the border the friction traces a hysteresis loop and the piston never rests",
          fmt::format("no rest (|v| < 1 mm/s for {:.0f} ms or more) in the example's settled "
                      "record, and in at least half of 10 velocity bins accelerating and "
                      "decelerating friction differ beyond 3 standard errors",
                      1e3 * kRestDuration_s),
          "fig3_friction_velocity"};
  if (!in.friction_loop) return missing(c, "no record");
  const FrictionLoop& l = *in.friction_loop;
  c.ours = fmt::format("{} rests (longest {:.1f} ms); hysteresis in {} of {} velocity bins",
                       l.rests, 1e3 * l.longest_rest_s, l.hysteretic_bins, l.bins);
  judge(c, loops_without_standstill(l));
  return c;
}

Claim sign_rule(const ClaimInputs& in) {
  Claim c{"sec32_sign_rule",
          "(i) if a1 > 0, then the system (7) is stable and velocity responses become damped "
          "oscillation. (ii) if a1 < 0, then the system (7) is unstable and velocity responses "
          "diverge and become self-excited oscillation.",
          "Section 3.2 (and b1, Section 3.3)",
          "where the paper's coefficient is positive the motion settles; where negative it "
          "keeps oscillating",
          "over the Fig. 4 map's coarse lattice (every 4th grid line of each axis and the last: "
          "the points every map runs, adaptive or full), at least 80 % of the decided points "
          "(half of their runs or more with a determined regime) of each sign behave as it "
          "says; undecided points are counted apart",
          "stability_map"};
  if (!in.sign_rule) return missing(c, "no map");
  const SignRuleCounts& s = *in.sign_rule;
  c.ours = fmt::format("damped: {} of {} steady; self-excited: {} of {} oscillating; {} "
                       "lattice points undecided",
                       s.damped_steady, s.damped, s.excited_moving, s.excited, s.undecided);
  judge(c, sign_rule_holds(s));
  return c;
}

Claim meter_in_supply(const ClaimInputs& in) {
  Claim c{"eq11_supply_pressure",
          "Moreover, from Fig. 5 and (11), increased supply pressure improves damping capacity "
          "of the whole system.",
          "Section 4.2, eq. (11)",
          "by eq. (11), in a meter-in circuit a higher Ps raises b1 and damps the motion",
          "the rig in a meter-in circuit (rod side at atmosphere) at each Fig. 2 opening, Ps "
          "0.25 -> 0.30 MPa: b1 rises and the full model's largest real part falls",
          "stability_map"};
  if (in.meter_in_ps.empty()) return missing(c, "no steady motion to linearise");
  std::string s;
  for (const DampingPair& p : in.meter_in_ps)
    s += fmt::format("{}b1 {:.1f} -> {:.1f} N s/m, max Re {:.2f} -> {:.2f} 1/s",
                     s.empty() ? "" : "; ", p.b1_before, p.b1_after, p.max_re_before,
                     p.max_re_after);
  c.ours = s;
  judge(c, damping_improves(in.meter_in_ps));
  return c;
}

Claim load_identity(const ClaimInputs& in) {
  Claim c{"eq9_eq11_load_identity",
          "From Fig. 6, additional loads increase a damping coefficient in (9) and (11) and "
          "prevent chaotic behavior.",
          "Section 4.2, eqs. (9), (11)",
          "a heavier load raises a1 or b1",
          "not scored: at a choked equilibrium the mass multiplies a term that is 0 in eq. (9) "
          "and positive by construction in eq. (11), so no plausible model can fail it; the "
          "map rows test the chaos",
          "stability_map"};
  if (!in.heavier) return missing(c, "no steady motion");
  const LoadCoefficients& h = *in.heavier;
  c.ours = fmt::format("a1 {:.1f} -> {:.1f}, b1 {:.1f} -> {:.1f} N s/m", h.a1_before, h.a1_after,
                       h.b1_before, h.b1_after);
  c.verdict = kIdentity;
  c.why = "an identity at a choked equilibrium";
  return c;
}

}  // namespace

std::vector<Claim> example_claims(const ClaimInputs& in) {
  return {exponent(in),  verdict(in),         spectrum(in),   acf(in),
          fold(in),      transients(in),      speed(in),      slope(in),
          loop(in),      sign_rule(in),       meter_in_supply(in), load_identity(in)};
}

}  // namespace pneumachaos
