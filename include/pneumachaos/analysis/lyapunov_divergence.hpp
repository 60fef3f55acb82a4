#pragma once
// Largest Lyapunov exponent from the average divergence of nearby trajectories (Rosenstein,
// Collins & De Luca 1993, Physica D 65; Kantz 1994, Phys. Lett. A 185), with the linear
// region of the divergence curve found automatically and an uncertainty from a jackknife.
//
// Beyond the references: for oversampled flows each neighbour is aligned with its reference
// in continuous time (cubic interpolation, a Newton step along the local tangent), so the
// along-flow offset between samples, which never grows, does not drag the curve's slope
// down. Without it every divergence-curve tool reads the Rossler exponent 13-18 % low.

#include <cstddef>
#include <span>
#include <vector>

namespace pneumachaos {

struct DivergenceOptions {
  std::size_t dimension = 3;
  std::size_t delay = 1;
  std::size_t theiler = 1;
  std::size_t horizon = 0;  ///< steps followed; 0: min(N/10, 8 periods), at least 20
  /// References are spread over the record; their number is capped so that references x
  /// horizon stays below this (the cost of following them).
  std::size_t max_reference_steps = 1'500'000;
  /// Continuous-time alignment of neighbours: on when delay >= 3 (an oversampled flow);
  /// maps and barely sampled records have no meaningful in-between values.
  enum class Alignment { kAuto, kOn, kOff } alignment = Alignment::kAuto;
  /// Spacing [steps] of the points whose successive slopes define the linear region; 0:
  /// max(1, typical_period / 2) so a modulation at the orbital period averages out.
  std::size_t slope_spacing = 0;
  std::size_t typical_period = 0;  ///< samples per oscillation; 0: mean_maxima_spacing
  double slope_tolerance = 0.2;    ///< relative spread of segment slopes within the region
  std::size_t jackknife_blocks = 10;
  void validate(std::size_t n_samples) const;
};

struct DivergenceResult {
  std::vector<double> curve;  ///< S(k) = <ln d(k)>, k = 0..horizon
  std::size_t fit_first = 0;  ///< linear region [fit_first, fit_last] in steps
  std::size_t fit_last = 0;
  double slope_per_step = 0.0;
  double intercept = 0.0;
  double lambda_per_s = 0.0;       ///< slope * rate
  double uncertainty_per_s = 0.0;  ///< jackknife standard error, with the fit window's sensitivity
  std::size_t references = 0;
  bool aligned = false;
  bool found_linear_region = false;  ///< false: no rising region (not chaotic, or too short)
};

DivergenceResult divergence_exponent(std::span<const double> x, double rate_Hz,
                                     const DivergenceOptions& options);

}  // namespace pneumachaos
