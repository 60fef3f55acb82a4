#pragma once
// Rests of a velocity record: the runs the stick-slip flag counts (docs/notes/analysis.md
// "Regime verdict" and "Noise floor").

#include <span>

#include "pneumachaos/analysis/regime.hpp"

namespace pneumachaos {

/// Counts the rests of x into e.rest_intervals and e.rest_share. A rest is a run of at least
/// o.min_rest_samples samples inside the band |x| <= level and flat: its spread within
/// o.rest_fraction x max|x| / 2, which a smooth passage through zero exceeds. With white noise
/// of sd s = record_noise_sd (estimate_noise_floor) the band, judged on the running median,
/// widens by o.rest_noise_sigmas x the median's sd and the spread allowance by the band's noisy
/// width, and each run must also be the noise about zero: no trend (its least-squares change
/// within the clean allowance plus o.rest_trend_sigmas standard errors of the noise's) and an
/// RMS about zero within o.rest_max_rms x s. No noise, or noise small enough for the clean
/// rule's spread allowance (s within a twelfth of the clean band), is the clean rule exactly;
/// e.rest_noise_sd says which. Where the widened band exceeds o.max_rest_band x max|x|, no
/// rest is counted and e.rests_above_noise is false.
void rest_statistics(std::span<const double> x, const VerdictOptions& o, double record_noise_sd,
                     RegimeEvidence& e);

}  // namespace pneumachaos
