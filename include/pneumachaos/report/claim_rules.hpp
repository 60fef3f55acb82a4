#pragma once
// The rules behind the claims table as small pure functions of measured numbers, so a unit
// test can show each one failing on a plausible input (docs/report.md).

#include <cstddef>
#include <vector>

#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

/// Largest |r| at lags of at least after_s: the envelope the ACF still has there.
double acf_envelope_after(const std::vector<double>& r, double rate_Hz, double after_s);
/// "converged to zero" (Fig. 7): the envelope after 1 s at most 0.2.
bool acf_converged(double envelope_after_1s);
/// "wide and even distribution without dominant peaks" (Fig. 7): no peak (+-1 bin) holds
/// more than a quarter of the power.
bool spectrum_without_dominant_peak(double peak_share);
/// "converged to a positive value" (Fig. 7): the divergence exponent above 3 times its
/// uncertainty AND the record judged chaotic by the regime rule (docs/analysis.md): a
/// periodic record's divergence curve can rise too, so the exponent alone cannot decide.
bool positive_exponent_of_chaos(double lambda, double uncertainty, bool record_chaotic);

/// Where the chaos of a map lies, weighted by incidence.
struct ChaosLocation {
  double total = 0.0;          ///< summed chaos incidence
  double near_border = 0.0;    ///< share within one S2 step of the stick-slip border
  double map_share = 0.0;      ///< share of the map's points chaotic at least once
};
/// per_point ordered with S2 (n2 values) fastest; stick-slip: incidence >= 0.5.
ChaosLocation chaos_location(const std::vector<PointSummary>& per_point, std::size_t n2);
/// "a limited region ... in the vicinity of the border between the stick-slip and
/// non-stick-slip regions" (Figs. 4-6): >= 75 % near the border, <= 25 % of the map chaotic.
bool chaos_near_border(const ChaosLocation& c);

/// std / |mean| of x from sample `from` on: how much a settled velocity fluctuates.
double relative_fluctuation(const std::vector<double>& x, std::size_t from);
/// Fig. 2: one circuit "fluctuates considerably", the other shows "slight oscillation and
/// high attenuation": every fluctuation of the first at least 3 times every one of the second.
bool fluctuates_much_more(const std::vector<double>& considerable,
                          const std::vector<double>& slight);
/// "the velocity is dependent on the magnitude of the effective sectional area": the mean
/// speeds, in order of increasing S, strictly increase.
bool strictly_increasing(const std::vector<double>& x);

/// Fig. 7c: "the trajectory is folded between 180 and 140 and stretched between 140 and 0"
/// (velocities in mm/s). Read as: the trajectory turns back (its velocity maxima lie) in the
/// fold band, and nearby trajectories separate in the stretch band faster than in the fold band.
struct FoldStretch {
  double maxima_in_fold_band = 0.0;  ///< share of the velocity maxima within 140-180 mm/s
  std::size_t maxima = 0;
  double stretch_rate = 0.0, stretch_se = 0.0;  ///< local stretching, 0-140 mm/s [1/s]
  double fold_rate = 0.0, fold_se = 0.0;        ///< local stretching, 140-180 mm/s [1/s]
};
/// v in m/s; the embedding of the record's analysis (dimension at least 3, as Fig. 7c).
FoldStretch measure_fold_stretch(const std::vector<double>& v, double rate_Hz,
                                 std::size_t dimension, std::size_t delay, std::size_t theiler);
/// At least half of the maxima in the fold band, and the stretch band's rate positive and
/// above the fold band's, each beyond 3 standard errors.
bool folded_and_stretched(const FoldStretch& f);

/// Fig. 3 and Section 4: "the friction force makes a loop ... and greatly fluctuates without
/// a standstill". The loop: at the same velocity the friction differs between accelerating
/// and decelerating motion.
struct FrictionLoop {
  double standstill_share = 0.0;  ///< share of samples with |v| < 1 mm/s
  std::size_t bins = 0;           ///< velocity bins with >= 10 samples on each branch
  std::size_t hysteretic_bins = 0;  ///< ... whose branch means differ beyond 3 standard errors
};
/// Ten equal velocity bins between the 5 % and 95 % quantiles of v (m/s; F in N).
FrictionLoop measure_friction_loop(const std::vector<double>& v, const std::vector<double>& F);
/// Standstill under 1 % of the time, and hysteresis in at least half of at least 4 bins.
bool loops_without_standstill(const FrictionLoop& l);

/// Least-squares slope dF/dv over the samples with 0 < v <= v_max.
double low_speed_slope(const std::vector<double>& v, const std::vector<double>& F, double v_max);

}  // namespace pneumachaos
