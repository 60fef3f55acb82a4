#pragma once
// Largest Lyapunov exponent from the average divergence of nearby trajectories (Rosenstein,
// Collins & De Luca 1993, Physica D 65; Kantz 1994, Phys. Lett. A 185), with the linear
// region of the divergence curve found automatically and an uncertainty from what varies:
// blocks of references, the fit window, and contiguous segments of the record.
//
// Beyond the references: for oversampled flows each neighbour is aligned with its reference
// in continuous time (cubic interpolation, a Newton step along the local tangent), so the
// along-flow offset between samples, which never grows, does not drag the curve's slope
// down. Without it every divergence-curve tool reads the Rossler exponent 13-18 % low.

#include <cstddef>
#include <span>
#include <vector>

#include "pneumachaos/analysis/slope_spread.hpp"

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
  /// Contiguous segments of the record (groups of jackknife blocks) on which the exponent is
  /// also fitted separately, each with its own linear region; their spread is part of the
  /// uncertainty (docs/notes/analysis.md "Divergence exponent's uncertainty"). 2..jackknife_blocks.
  std::size_t segments = 5;
  void validate(std::size_t n_samples) const;
};

struct DivergenceResult {
  std::vector<double> curve;  ///< S(k) = <ln d(k)>, k = 0..horizon
  std::size_t fit_first = 0;  ///< linear region [fit_first, fit_last] in steps
  std::size_t fit_last = 0;
  double slope_per_step = 0.0;
  double intercept = 0.0;
  double lambda_per_s = 0.0;       ///< slope * rate
  std::size_t slope_spacing = 0;   ///< segment length of the linear region's search, in steps
  /// The value's uncertainty: the slope's (below) and the spread of the segments' exponents,
  /// in quadrature; +-1.96 of it is meant as a 95 % interval (docs/notes/analysis.md "Divergence
  /// exponent's uncertainty").
  double uncertainty_per_s = 0.0;
  /// The chosen window's slope alone: jackknife standard error over blocks of references and
  /// the change when the window is narrowed. Says whether the curve rises (the verdict's
  /// test), not how well the rise measures the exponent.
  double slope_uncertainty_per_s = 0.0;
  /// Slope of each segment's own curve (per step, record order), on its own linear region or,
  /// without one, on the record's.
  std::vector<double> segment_slopes_per_step;
  std::size_t segments_without_region = 0;
  std::size_t references = 0;
  bool aligned = false;
  bool found_linear_region = false;  ///< false: no rising region (not chaotic, or too short)
  /// Without a linear region: the spread of the curve's one-orbit local slopes over its rising
  /// part (per step; rising_slopes). A wide estimate for a curve that rises without one straight
  /// stretch; the verdict does not read it (docs/notes/exponent_validation.md).
  SlopeSpread local_slopes;
};

DivergenceResult divergence_exponent(std::span<const double> x, double rate_Hz,
                                     const DivergenceOptions& options);

}  // namespace pneumachaos
