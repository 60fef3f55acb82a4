#pragma once
// Scenarios of scenarios/variants/*.toml, for tests about a mechanism of one particular rig rather
// than about whatever the default is (docs/notes/virtual_rig.md describes each file).
#include <string>
#include <vector>

#include "pneumachaos/model/scenario_toml.hpp"

namespace pneumachaos {

/// scenarios/variants/NAME with the overrides `sets` applied (validated).
inline Scenario variant_scenario(const std::string& name,
                                 const std::vector<std::string>& sets = {}) {
  return build_scenario(std::string(PNEUMACHAOS_VARIANTS_DIR) + "/" + name, sets);
}

/// The frozen light-piston rig: volumes frozen at 420 mm, 0.53 kg piston + rod, LuGre seal,
/// chaotic at the Fig. 7 point (scenarios/variants/frozen_light_piston.toml).
inline Scenario frozen_light_piston(const std::vector<std::string>& sets = {}) {
  return variant_scenario("frozen_light_piston.toml", sets);
}

}  // namespace pneumachaos
