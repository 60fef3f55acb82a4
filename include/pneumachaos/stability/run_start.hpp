#pragma once
// Where a run starts (docs/model.md, "Start and end of a run"): at rest, or on the steady
// sliding motion, so a band where sliding and stick-slip coexist can be mapped from both sides.

#include <vector>

#include "pneumachaos/core/run_params.hpp"
#include "pneumachaos/model/plant.hpp"

namespace pneumachaos {

/// The plant's state at the start of a run: Plant::initial_state for run.start = rest; for
/// sliding, the state of the fastest steady motion (the one `stability` linearises about), at
/// the position it is computed at (where the scenario freezes the volumes, else mid-stroke).
/// Throws Error naming run.start when no steady sliding exists, with the reason.
std::vector<double> run_start_state(const Plant& plant, const RunParams& run);

}  // namespace pneumachaos
