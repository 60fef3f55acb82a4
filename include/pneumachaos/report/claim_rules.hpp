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

/// Least-squares slope dF/dv over the samples with 0 < v <= v_max.
double low_speed_slope(const std::vector<double>& v, const std::vector<double>& F, double v_max);

}  // namespace pneumachaos
