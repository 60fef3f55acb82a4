#pragma once
// The steps of estimate_friction (friction_estimate.cpp), shared between the files that hold
// them: the acceleration (friction_acceleration.cpp) and the curve, excursions and Fig. 3
// marks (friction_loops.cpp). Private to the identify module.

#include <cstddef>
#include <utility>
#include <vector>

#include "pneumachaos/identify/friction_estimate.hpp"

namespace pneumachaos::identify::detail {

double median(std::vector<double> v);
/// Centred mean over +-h samples, the window shrinking at the ends.
std::vector<double> moving_mean(const std::vector<double>& y, std::size_t h);
int sign_of(double v);

/// e.a_m_per_s2 and the Savitzky-Golay window statistics (or the record's own acceleration);
/// needs e.stuck and e.velocity_noise_m_per_s.
void estimate_acceleration(const MeasuredRecord& r, const EstimateSpec& s,
                           FrictionEstimate& e);

/// e.curve: the binned steady friction-velocity curve of the sliding samples.
void add_steady_curve(FrictionEstimate& e, std::size_t bins);
/// e.excursions: the runs outside sticks, split at velocity reversals.
void add_excursions(FrictionEstimate& e);
/// The A-D marks of every excursion, on the smoothed force F_smooth.
void add_loop_marks(FrictionEstimate& e, const std::vector<double>& F_smooth);

}  // namespace pneumachaos::identify::detail
