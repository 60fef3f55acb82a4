#pragma once
// The rules behind the claims table as small pure functions of measured numbers, so a unit
// test can show each one agreeing and failing on plausible inputs (docs/report.md). Every rule
// returns a RuleResult: a signed, dimensionless margin (>= 0 passes; how far from the rule's
// boundary in units of its own scale) and, when it fails, one sentence saying why.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/analysis/paper_judge.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

struct RuleResult {
  double margin = kNaN;  ///< >= 0 passes; NaN: the rule could not be evaluated
  std::string why;       ///< one sentence when it fails (or cannot be evaluated)
  [[nodiscard]] bool passes() const { return margin >= 0.0; }
  [[nodiscard]] bool evaluated() const { return margin == margin; }
};

/// A rule's result from its margin; `why` is kept only when the margin fails.
RuleResult rule_result(double margin, std::string why);
/// The smaller of two margins, with the failing one's reason (the rule is an AND).
RuleResult both(const RuleResult& a, const RuleResult& b);

// ---- Fig. 7b: the chaotic example's indices -------------------------------------------------

// The thresholds and acf_envelope_after: the paper's judge (pneumachaos/analysis/paper_judge.hpp).
/// "converged to zero": the envelope after 1 s at most 0.2.
RuleResult acf_converged(double envelope_after_1s);
/// "wide and even distribution without dominant peaks": no peak (+-1 bin) holds more than a
/// quarter of the power.
RuleResult spectrum_without_dominant_peak(double peak_share);
/// "converged to a positive value": the exponent above 3 times its uncertainty.
RuleResult positive_exponent(double lambda_per_s, double uncertainty_per_s);
/// "exemplifies a velocity response having chaotic behavior": the regime verdict (+-1).
RuleResult judged_chaotic(bool chaotic, const std::string& regime);

// ---- Fig. 2: the two circuits' transients ---------------------------------------------------

/// How fast a step response settles: ln(20) / (time from the start of motion until the
/// velocity stays within 5 % of its final value), the decay rate of an exponential envelope
/// [1/s]. The final value is the mean of the record's second half (a stick-slip response
/// averages over several of its cycles there); a response still outside the band in that half
/// has not settled: its rate is ln(20) / (the record's length after the start), a bound from
/// above, and `settled` is false.
struct Settling {
  double final_value = 0.0;
  double start_s = 0.0, settle_s = 0.0;
  double decay_rate_per_s = 0.0;
  bool settled = false;
};
Settling settling(const std::vector<double>& v, double rate_Hz);
/// "(a) fluctuates considerably ... (b) slight oscillation and high attenuation": every
/// response of (b) decays at least twice as fast as every response of (a).
RuleResult attenuates_faster(const std::vector<double>& fast_decay,
                             const std::vector<double>& slow_decay);
/// "the velocity is dependent on the magnitude of the effective sectional area": the final
/// speeds, in order of increasing S, rise (margin: the smallest relative step).
RuleResult rises_with_area(const std::vector<double>& speeds);

// ---- Section 3.4, eq. (11): damping against a change -----------------------------------------

/// b1 (eq. 11) and the full model's largest real part before and after a change.
struct DampingPair {
  double b1_before = 0.0, b1_after = 0.0;          ///< [N s/m]
  double max_re_before = 0.0, max_re_after = 0.0;  ///< [1/s]
};
/// "improves damping": at every point b1 rises and the full model's largest real part falls.
RuleResult damping_improves(const std::vector<DampingPair>& points);

// ---- Section 3.4 and Fig. 3: friction ---------------------------------------------------------

/// Least-squares line F = intercept + slope v over the samples with 0 < v <= v_max.
struct LineFit {
  double slope = kNaN, intercept = kNaN;
  std::size_t n = 0;
};
LineFit low_speed_line(const std::vector<double>& v, const std::vector<double>& F, double v_max);
/// "with low velocity, the frictional coefficient B is negative": the line falls; margin:
/// the relative drop of friction over the band, -slope v_max / intercept.
RuleResult negative_low_speed_slope(const LineFit& line, double v_max);

/// Fig. 3 and Section 4: "the friction force makes a loop ... and greatly fluctuates without a
/// standstill". A standstill is a rest: |v| below kRestSpeed for at least kRestDuration in a
/// row (a reversal passes zero within a millisecond or two; a stick lasts). The loop: at the
/// same velocity the friction differs between accelerating and decelerating motion.
constexpr double kRestSpeed_m_per_s = 1e-3;
constexpr double kRestDuration_s = 0.010;  ///< ten samples of the paper's 1 kHz record
struct FrictionLoop {
  std::size_t rests = 0;           ///< rest episodes
  double longest_rest_s = 0.0;     ///< the longest run of |v| < kRestSpeed [s]
  std::size_t bins = 0;            ///< velocity bins with >= 10 samples on each branch
  std::size_t hysteretic_bins = 0;  ///< ... whose branch means differ beyond 3 standard errors
};
/// Ten equal velocity bins between the 5 % and 95 % quantiles of v (m/s; F in N).
FrictionLoop measure_friction_loop(const std::vector<double>& v, const std::vector<double>& F,
                                   double rate_Hz);
/// No rest episode, and hysteresis in at least half of at least 4 bins.
RuleResult loops_without_standstill(const FrictionLoop& l);

// ---- Fig. 7c: fold and stretch ----------------------------------------------------------------

/// "The trajectory is folded between 180 and 140 and is stretched between 140 and 0", read on
/// the scale of the record: the paper's plot spans 0 to 180, so the fold band is the top
/// 40/180 of the record's velocity range and the stretch band the rest.
constexpr double kFoldBandStart = 140.0 / 180.0;
struct FoldStretch {
  double low = 0.0, high = 0.0;      ///< the record's range (0.5 % and 99.5 % quantiles) [m/s]
  double maxima_in_fold_band = 0.0;  ///< share of the velocity maxima in the fold band
  std::size_t maxima = 0;
  double stretch_rate = 0.0, stretch_se = 0.0;  ///< local stretching in the stretch band [1/s]
};
/// v in m/s; the embedding of the record's analysis (dimension at least 3, as Fig. 7c).
FoldStretch measure_fold_stretch(const std::vector<double>& v, double rate_Hz,
                                 std::size_t dimension, std::size_t delay, std::size_t theiler);
/// At least half of the maxima (where the trajectory turns back) in the fold band, and nearby
/// trajectories separating in the stretch band (rate beyond 3 standard errors).
RuleResult folded_and_stretched(const FoldStretch& f);

// ---- Figs. 4-6: maps --------------------------------------------------------------------------

/// The map's grid: per_point ordered with the second axis (S2, n2 values) fastest.
struct MapGrid {
  std::vector<double> s1, s2;  ///< axis values [mm^2]
};

/// "the rate is highest ... in the neighborhood of the boundary between the stick-slip region
/// and the non-stick-slip region": the mean chaos incidence of the points within one grid step
/// of the border (a point whose stick-slip class differs from one of its four neighbours) is
/// above that of the other points. Margin: (near - far) / (near + far).
RuleResult chaos_highest_near_border(const std::vector<PointSummary>& pts, const MapGrid& g);
/// The points that rule reads as near the border, in grid order (the report marks them).
std::vector<std::size_t> stick_slip_border_points(const std::vector<PointSummary>& pts,
                                                  const MapGrid& g);
/// The points of a map that `keep` accepts, in grid order (the cells a count rule counted).
std::vector<std::size_t> points_where(const SweepSummary& s, bool (*keep)(const PointSummary&));
/// "the rate is highest in the range of S1 > S2": mean incidence where S1 > S2 above that
/// where S1 <= S2 (not evaluated when the grid has no point on one side).
RuleResult chaos_highest_where_s1_above_s2(const std::vector<PointSummary>& pts,
                                           const MapGrid& g);
/// "chaotic oscillation occurs in the limited region in which S1 and S2 are relatively small":
/// the incidence-weighted mean S1 and mean S2 each below the middle of the grid's range, and
/// fewer than half of the points ever chaotic.
RuleResult chaos_where_s1_and_s2_small(const std::vector<PointSummary>& pts, const MapGrid& g);

/// Smallest region (points) in which a change by `fraction` of it exceeds twice the counting
/// noise of the difference (Poisson): b f >= 2 sqrt(b (2 - f)), i.e. b >= 4 (2 - f) / f^2.
/// Below it a change by that fraction is noise, and the claim is "not reproduced".
std::size_t min_region_for_change(double fraction);
/// "decreases" / "reduces": the region loses at least one point (margin (b - 1 - a) / b).
RuleResult region_shrinks(std::size_t before, std::size_t after);
/// "grows" / "promotes": the region gains at least one point.
RuleResult region_grows(std::size_t before, std::size_t after);
/// "contracts by more than half": after < before / 2, on a base of at least
/// min_region_for_change(0.5) points (else not evaluated).
RuleResult region_more_than_halved(std::size_t before, std::size_t after);
/// "a few points where chaotic oscillation always happens": 1 to max(3, 1.3 % of the points)
/// (10 of the paper's 780).
RuleResult a_few_points(std::size_t always_chaotic, std::size_t points);

/// The verdict's false-positive rate per judged run: of the default rig's validation runs
/// that the model's own exponent calls non-chaotic, 197 got a verdict other than steady or
/// undetermined (neither can be a false positive) and 14 of those were called chaotic
/// (bench/verdict_vs_model_sweeps.sh; docs/report.md, "The claims table").
constexpr double kVerdictFalsePositiveRate = 14.0 / 197.0;
/// The most chaotic runs that the false-positive rate alone gives in `judged` runs (the
/// binomial distribution's 95 % quantile).
std::size_t false_positive_allowance(std::size_t judged,
                                     double rate = kVerdictFalsePositiveRate);
/// "completely prevents chaotic behavior": no more chaotic runs than the allowance.
RuleResult no_chaos_beyond_false_positives(std::size_t chaotic_runs, std::size_t judged);
/// Runs of a map whose verdict is neither steady nor undetermined: the runs that could be
/// false positives.
std::size_t judged_runs(const SweepSummary& s);
/// The map has chaos beyond what false positives give: only then can its place or its change
/// be read.
bool chaos_beyond_false_positives(const SweepSummary& s);

/// Chaotic runs of a map (incidence times successful runs, summed; a point an adaptive map
/// inferred counts as many runs as an evaluated one).
std::size_t chaotic_runs(const SweepSummary& s);
/// Points of the coarse lattice (PointSummary::on_lattice: run by full and adaptive maps
/// alike, an even sample of the grid) whose determined runs mostly oscillate (not steady);
/// undetermined runs left out. Off the lattice an adaptive map's motion is inferred from a
/// cell uniform in other classes, so it is not counted.
std::size_t oscillating_points(const SweepSummary& s);
/// The points oscillating_points() reads.
std::size_t lattice_points(const SweepSummary& s);

/// The paper's sign rule (a1 / b1 < 0: self-excited) against the simulated runs per point.
/// A point is decided when at least half of its runs got a determined regime; it is steady
/// when most of its determined runs are steady.
struct SignRuleCounts {
  std::size_t damped = 0, damped_steady = 0;    ///< decided points the rule calls damped
  std::size_t excited = 0, excited_moving = 0;  ///< decided points it calls self-excited
  std::size_t undecided = 0;                    ///< points counted apart (mostly undetermined)
};
/// The counts over a map's coarse lattice (as oscillating_points()): damped[i] is the sign
/// rule's call at point i (empty: no steady motion there, not counted), in the sweep's point
/// order.
SignRuleCounts count_sign_rule(const std::vector<std::optional<bool>>& damped,
                               const SweepSummary& sweep);
/// (i) and (ii): at least 80 % of the decided points of each class behave as the sign says.
RuleResult sign_rule_holds(const SignRuleCounts& s);

}  // namespace pneumachaos
