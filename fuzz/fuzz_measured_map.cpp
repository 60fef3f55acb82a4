// libFuzzer harness: the measured incidence-map reader (calibrate's incidence_map objective) on
// arbitrary text. Only pneumachaos::Error may come out, and a map that reads is a full grid.
#include <cstddef>
#include <cstdint>
#include <cstdlib>
#include <string>

#include "calibrate/measured_map.hpp"
#include "pneumachaos/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const pneumachaos::MeasuredMap m = pneumachaos::parse_measured_map(text, "fuzz.csv");
    const std::size_t n = m.s1.size() * m.s2.size();
    if (n == 0 || m.stick_slip.size() != n || m.chaos.size() != n) std::abort();
    for (std::size_t i = 0; i < n; ++i)
      if (!(m.chaos[i] >= 0.0 && m.chaos[i] <= 1.0)) std::abort();
  } catch (const pneumachaos::Error&) {
  }
  return 0;
}
