// libFuzzer harness: the calibration spec reader (docs/guide/calibrate.md) on arbitrary text,
// with the spec's cross-checks, scenarios and fingerprint. Only pneumachaos::Error may come out.
#include <cstddef>
#include <cstdint>
#include <string>
#include <vector>

#include "pneumachaos/calibrate/calibration_spec.hpp"
#include "pneumachaos/core/error.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    const pneumachaos::CalibrationSpec s = pneumachaos::parse_calibration_spec(text, "fuzz.toml");
    // A spec that reads has a scenario at both corners of its box and a fingerprint.
    (void)s.fingerprint();
    (void)s.scenario_at(std::vector<double>(s.free.size(), 0.0));
    (void)s.scenario_at(std::vector<double>(s.free.size(), 1.0));
  } catch (const pneumachaos::Error&) {
  }
  return 0;
}
