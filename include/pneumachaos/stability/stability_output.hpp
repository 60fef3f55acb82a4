#pragma once
// Stability results for people (a table), for programs (JSON with a unit on every number)
// and for plotting (the map as CSV).

#include <ostream>
#include <string>

#include "pneumachaos/stability/stability_map.hpp"

namespace pneumachaos {

/// `scenario` is the one the result was computed for (its circuit, valves, supply and mass
/// head the output).
std::string stability_table(const Scenario& scenario, const StabilityResult& result);
std::string stability_json(const Scenario& scenario, const StabilityResult& result);

/// Columns: one per axis key, then v0_mm_per_s, P10_MPa_gauge, P20_MPa_gauge,
/// B_Ns_per_m, a1_Ns_per_m, b1_Ns_per_m, zeta_paper, verdict_paper, max_real_part_per_s,
/// osc_frequency_Hz, osc_damping_ratio, verdict_full, agree, error.
void write_stability_map_csv(std::ostream& out, const StabilityMap& map, double ambient_Pa);

}  // namespace pneumachaos
