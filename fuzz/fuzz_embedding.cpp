// libFuzzer harness: the embedding parameters of a short record (fuzz_input.hpp): the delay
// from the mutual information (with a fuzzed bin count) and the dimension by Cao's method
// (with a fuzzed delay and Theiler window). Only pneumachaos::Error may come out; a delay is
// at least 1, a dimension lies within 1..max_dimension.
#include <cstddef>
#include <cstdint>

#include "fuzz_input.hpp"
#include "pneumachaos/analysis/embedding_parameters.hpp"
#include "pneumachaos/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  using pneumachaos::fuzz::require;
  pneumachaos::fuzz::FuzzInput in(data, size);
  const std::size_t bins = in.in_range(0, 70);
  const std::size_t delay = in.in_range(1, 20);
  const std::size_t theiler = in.in_range(0, 30);
  const std::size_t max_dimension = in.in_range(1, 6);
  const auto x = in.samples(128);
  try {
    const auto ami = pneumachaos::mutual_information(x, x.size() / 10, bins);
    for (double v : ami) require(!std::isnan(v));
    const auto chosen = pneumachaos::choose_delay(x);
    require(chosen.delay >= 1);
  } catch (const pneumachaos::Error&) {
  }
  try {
    const auto d = pneumachaos::choose_dimension(x, delay, theiler, max_dimension);
    require(d.dimension >= 1 && d.dimension <= max_dimension);
  } catch (const pneumachaos::Error&) {
  }
  return 0;
}
