// libFuzzer harness: the evidence tests of a short record (fuzz_input.hpp): an IAAFT
// surrogate, the surrogate test (19 surrogates, the fewest a test at 5 % allows, on records
// from 64 samples), the prediction errors and the 0-1 test, with fuzzed embedding, iteration
// and frequency counts. Only pneumachaos::Error may come out; a surrogate holds exactly the
// record's values (IAAFT reorders them), a p-value lies in (0, 1], K is finite.
#include <algorithm>
#include <cmath>
#include <cstddef>
#include <cstdint>
#include <vector>

#include "fuzz_input.hpp"
#include "pneumachaos/analysis/prediction_error.hpp"
#include "pneumachaos/analysis/surrogates.hpp"
#include "pneumachaos/analysis/zero_one_test.hpp"
#include "pneumachaos/core/error.hpp"

namespace {

using pneumachaos::fuzz::require;

void check_surrogate(const std::vector<double>& x, std::uint64_t seed, std::size_t iterations) {
  auto s = pneumachaos::iaaft_surrogate(x, seed, iterations);
  auto sorted = x;
  std::sort(sorted.begin(), sorted.end());
  std::sort(s.begin(), s.end());
  require(s == sorted);
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  pneumachaos::fuzz::FuzzInput in(data, size);
  pneumachaos::PredictionOptions p;
  p.dimension = in.in_range(1, 5);
  p.delay = in.in_range(1, 8);
  p.theiler = in.in_range(0, 10);
  p.horizon = in.in_range(0, 8);
  p.neighbours = in.in_range(1, 6);
  pneumachaos::SurrogateOptions s;
  s.count = pneumachaos::kMinSurrogates;
  s.seed = in.byte();
  s.max_iterations = in.in_range(1, 3);
  s.min_samples = 64;
  pneumachaos::ZeroOneOptions z;
  z.frequencies = in.in_range(1, 12);
  z.min_points = in.in_range(20, 60);
  const std::size_t step = in.in_range(0, 4);
  const auto x = in.samples(96);
  try {
    if (!x.empty()) check_surrogate(x, s.seed, s.max_iterations);
    (void)pneumachaos::prediction_errors(x, p);
    const auto t = pneumachaos::surrogate_test(x, p, s);
    if (t.run) require(t.p_value > 0.0 && t.p_value <= 1.0 && t.surrogate_statistics.size() == s.count);
    const auto k = pneumachaos::zero_one_test(x, step, z);
    if (k.run) require(std::isfinite(k.K));
  } catch (const pneumachaos::Error&) {
  }
  return 0;
}
