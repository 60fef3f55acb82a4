// libFuzzer harness: the whole analysis of a short record. The bytes become 16-bit samples
// (as an A/D converter gives them, so repeats, plateaus and steps are common) at 1 kHz;
// Wolf's estimator is included. Only pneumachaos::Error may come out, and an exponent that
// is reported must be a number.
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <vector>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  constexpr std::size_t kMaxSamples = 1024;  // short records: many executions per second
  std::vector<double> x;
  for (std::size_t i = 0; i + 1 < size && x.size() < kMaxSamples; i += 2) {
    const auto raw = static_cast<std::int16_t>(data[i] | (data[i + 1] << 8));
    x.push_back(static_cast<double>(raw) * 1e-3);
  }
  pneumachaos::AnalysisOptions options;
  options.wolf = true;
  try {
    const auto r = pneumachaos::analyze_series(x, 1000.0, options);
    if (r.divergence.found_linear_region && !std::isfinite(r.divergence.lambda_per_s)) std::abort();
    if (r.wolf_run && !std::isfinite(r.wolf.lambda_per_s)) std::abort();
  } catch (const pneumachaos::Error&) {
  }
  return 0;
}
