// libFuzzer harness: the scenario reader (TOML text onto the defaults, then the cross-key
// checks) on arbitrary text. Only pneumachaos::Error may come out.
#include <cstddef>
#include <cstdint>
#include <string>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/model/scenario_toml.hpp"

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  const std::string text(reinterpret_cast<const char*>(data), size);
  try {
    pneumachaos::Scenario s = pneumachaos::default_scenario();
    pneumachaos::apply_toml(s, text, "fuzz.toml");
    s.validate();
    // A scenario that validates must also print and read back.
    pneumachaos::Scenario again = pneumachaos::default_scenario();
    pneumachaos::apply_toml(again, pneumachaos::scenario_to_toml(s), "printed.toml");
  } catch (const pneumachaos::Error&) {
  }
  return 0;
}
