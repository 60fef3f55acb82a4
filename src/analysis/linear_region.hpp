#pragma once
// The linear region of a curve (e.g. a divergence curve), found without hand tuning.

#include <cstddef>
#include <vector>

#include "pneumachaos/analysis/slope_spread.hpp"

namespace pneumachaos {

struct LineFit {
  double slope = 0.0;
  double intercept = 0.0;
};

/// Least-squares line through y[first..last] against the index.
LineFit fit_line(const std::vector<double>& y, std::size_t first, std::size_t last);

struct LinearRegion {
  bool found = false;
  std::size_t first = 0, last = 0;
  double slope = 0.0, intercept = 0.0;
};

/// Samples the curve every `spacing` points and splits it into runs whose successive segment
/// slopes stay within `tolerance` (relative) of the run's mean slope: every rising run of at
/// least three segments that no other contains, in the order of their start, each with the
/// line fitted to all points it covers. This follows the idea of ChaosTools.jl's linear_region.
std::vector<LinearRegion> agreeing_runs(const std::vector<double>& y, std::size_t spacing,
                                        double tolerance);

/// The longest of agreeing_runs that start before the curve first covers 90 % of its rise from
/// y[0] to its maximum (ties: the earlier one): the curve's linear region. Past that point the
/// curve is at its saturated top, where a rise is the top's wobble (a noisy cycle's mean
/// distance modulated at its period), not divergence. The uncertainty still reads every run
/// (exponent_spread's window choice): a bound on the window, not a second value.
LinearRegion find_linear_region(const std::vector<double>& y, std::size_t spacing,
                                double tolerance);

/// The spread of a curve's local slopes over its rising part, for a curve without a linear
/// region (docs/notes/exponent_validation.md): slopes (y[k + w] - y[k]) / w for every k whose
/// window ends before the curve first covers 90 % of its rise from y[0] to its maximum. With w
/// one orbit, a modulation at the orbital period averages out of each slope. found: at least
/// three slopes.
SlopeSpread rising_slopes(const std::vector<double>& y, std::size_t w);

}  // namespace pneumachaos
