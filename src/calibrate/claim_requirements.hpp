#pragma once
// Which conditions each claim (the claims module) needs (private to the calibrate module): a spec
// that asks for a claim its conditions cannot score is refused before any run.

#include <string>
#include <vector>

#include "pneumachaos/calibrate/calibration_spec.hpp"

namespace pneumachaos::detail {

/// The roles a map condition can take (the claims' ClaimInputs fields).
bool is_map_role(const std::string& role);

/// What `conditions` lack to score claim `id` ("" when nothing): a map role, the example, or
/// an input calibrate does not compute (Fig. 2, the stability map, the linearized trends).
std::string missing_for_claim(const std::string& id, const ConditionSet& conditions);

/// What the maps' grid lacks to score claim `id` ("" when nothing): fig4_s1_above_s2 compares
/// points with S1 > S2 against points with S1 <= S2, so the grid needs both.
std::string grid_problem_for_claim(const std::string& id, const std::vector<GridAxis>& axes);

/// FNV-1a of the text as 16 hex digits (a fingerprint stable across builds).
std::string stable_hash(const std::string& text);

}  // namespace pneumachaos::detail

namespace pneumachaos {
using detail::is_map_role;
}
