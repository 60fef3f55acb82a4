// libFuzzer harness: the divergence (Rosenstein/Kantz) exponent of a short record
// (fuzz_input.hpp) with fuzzed dimension, delay, Theiler window, horizon, alignment and
// jackknife settings. Only pneumachaos::Error may come out; a linear region that is found
// lies inside the curve and gives a finite exponent and uncertainty.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_input.hpp"
#include "pneumachaos/analysis/lyapunov_divergence.hpp"
#include "pneumachaos/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using pneumachaos::fuzz::require;
  pneumachaos::fuzz::FuzzInput in(data, size);
  pneumachaos::DivergenceOptions o;
  o.dimension = in.in_range(1, 6);
  o.delay = in.in_range(1, 12);
  o.theiler = in.in_range(0, 20);
  o.horizon = in.in_range(0, 60);
  o.alignment = static_cast<pneumachaos::DivergenceOptions::Alignment>(in.in_range(0, 2));
  o.typical_period = in.in_range(0, 40);
  o.slope_spacing = in.in_range(0, 10);
  o.jackknife_blocks = in.in_range(1, 12);
  o.segments = in.in_range(1, 12);
  const auto x = in.samples(200);
  try {
    const auto r = pneumachaos::divergence_exponent(x, 1000.0, o);
    if (r.found_linear_region) {
      require(r.fit_first <= r.fit_last && r.fit_last < r.curve.size());
      require(std::isfinite(r.lambda_per_s) && std::isfinite(r.uncertainty_per_s));
    }
  } catch (const pneumachaos::Error&) {
  }
  return 0;
}
