#pragma once
// The simple rig (one rigid mass, the paper's model) with `--set`-style overrides, validated:
// where the stability tests start.
#include <string>
#include <vector>

#include "pneumachaos/model/scenario_toml.hpp"

namespace pneumachaos {

inline Scenario simple_rig_with(const std::vector<std::string>& sets) {
  Scenario s = simple_rig_scenario();
  apply_overrides(s, sets);
  s.validate();
  return s;
}

}  // namespace pneumachaos
