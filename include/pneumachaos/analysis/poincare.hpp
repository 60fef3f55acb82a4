#pragma once
// Poincare sections of a delay-embedded record (the paper's Fig. 7d) and the successive-maxima
// (Lorenz) map.

#include <array>
#include <cstddef>
#include <limits>
#include <span>
#include <vector>

namespace pneumachaos {

/// Crossings of the 3-D delay trajectory (x_t, x_{t+tau}, x_{t+2tau}) through the plane
/// x_t = level in the upward direction; each point holds the other two coordinates,
/// linearly interpolated to the crossing, and the crossing time [s].
struct PoincareSection {
  double level = 0.0;
  std::vector<std::array<double, 2>> points;
  std::vector<double> time_s;
};

/// level: NaN picks the series mean.
PoincareSection poincare_section(std::span<const double> x, std::size_t delay, double rate_Hz,
                                 double level = std::numeric_limits<double>::quiet_NaN());

/// Successive maxima (M_k, M_{k+1}), each maximum refined by a parabola through its three
/// samples; maxima must be separated by a fall of a quarter standard deviation, as in
/// mean_maxima_spacing.
std::vector<std::array<double, 2>> successive_maxima(std::span<const double> x);

}  // namespace pneumachaos
