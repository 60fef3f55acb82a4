// libFuzzer harness: Wolf's exponent of a short record (fuzz_input.hpp) with fuzzed
// dimension, delay, Theiler window, evolution time, scales, settling and chains. Only
// pneumachaos::Error may come out; the exponent, its uncertainty and the measured time are
// finite, and the running estimate has a time for each value.
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_input.hpp"
#include "pneumachaos/analysis/lyapunov_wolf.hpp"
#include "pneumachaos/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using pneumachaos::fuzz::require;
  pneumachaos::fuzz::FuzzInput in(data, size);
  pneumachaos::WolfOptions o;
  o.dimension = in.in_range(1, 6);
  o.delay = in.in_range(1, 12);
  o.theiler = in.in_range(0, 20);
  o.evolve = in.in_range(0, 10);
  o.typical_period = in.in_range(0, 40);
  o.scale_factor = in.in_range(0, 10);  // 0 is refused by validate()
  o.settle = in.in_range(0, 20);
  o.align = (in.byte() & 1) != 0;
  o.chains = in.in_range(1, 8);
  const auto x = in.samples(200);
  try {
    const auto r = pneumachaos::wolf_exponent(x, 1000.0, o);
    require(std::isfinite(r.lambda_per_s) && std::isfinite(r.uncertainty_per_s));
    require(std::isfinite(r.measured_s) && r.measured_s >= 0.0);
    require(r.running_time_s.size() == r.running_per_s.size());
  } catch (const pneumachaos::Error&) {
  }
  return 0;
}
