#include "simulate/transducer_stages.hpp"

#include <algorithm>
#include <cmath>
#include <cstddef>
#include <numbers>

namespace pneumachaos {

// Over one interval h the input is x(s) = x0 + (x1 - x0) s / h, and the exact solution is
// y1 = a y0 + (1 - c) x1 + (c - a) x0 with a = exp(-h / tau), c = (tau / h)(1 - a): the
// convolution of the step response with the ramp (docs/model.md, "The transducer"). The
// weights sum to 1, so a constant passes unchanged.
std::vector<double> first_order_lag(std::vector<double> x, double rate_Hz, double bandwidth_Hz) {
  if (bandwidth_Hz <= 0.0 || x.empty()) return x;
  const double h = 1.0 / rate_Hz;
  const double tau = 1.0 / (2.0 * std::numbers::pi * bandwidth_Hz);
  const double a = std::exp(-h / tau);
  const double c = tau / h * -std::expm1(-h / tau);  // 1 - a, accurate when h << tau
  double previous_in = x[0];
  for (std::size_t n = 1; n < x.size(); ++n) {
    const double in = x[n];
    x[n] = a * x[n - 1] + (1.0 - c) * in + (c - a) * previous_in;
    previous_in = in;
  }
  return x;
}

void quantise(std::vector<double>& x, int bits, double lo, double hi) {
  if (bits <= 0) {
    for (double& value : x) value = std::clamp(value, lo, hi);
    return;
  }
  const double levels = std::ldexp(1.0, bits);
  const double step = (hi - lo) / levels;
  for (double& value : x) {
    const double k = std::clamp(std::round((value - lo) / step), 0.0, levels - 1.0);
    value = lo + k * step;
  }
}

}  // namespace pneumachaos
