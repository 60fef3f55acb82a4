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

/// [fixed] lines (a calibration spec's) that give the keys where the one-body default and the compliant-mount rig differ, but the Coulomb
/// friction and the coupling, their compliant-mount values: the seal's Fs and pressure gains,
/// the cylinder, the supply line and b. For the calibration tests measured on that rig.
inline const std::string kCompliantMountFixed =
    "friction.Fs_N = 47\nfriction.Fc_gain_N_per_MPa = 0\nfriction.Fs_gain_N_per_MPa = 0\n"
    "cylinder.bore_mm = 40\ncylinder.dead_volume_head_cm3 = 20.000000000000004\n"
    "cylinder.dead_volume_rod_cm3 = 20.000000000000004\n"
    "supply_line.volume_cm3 = 0\nsupply_line.regulator_S_mm2 = 10.000000000000002\n"
    "valve.critical_ratio = 0.528\n";

/// The compliant-mount rig: the load on its own guide
/// behind a compliant mount, the GMS seal, a 40 mm bore, no supply line
/// (scenarios/variants/compliant_mount.toml).
inline Scenario compliant_mount(const std::vector<std::string>& sets = {}) {
  return variant_scenario("compliant_mount.toml", sets);
}

}  // namespace pneumachaos
