#pragma once
// The sweep's result files (private to the module).

#include <string>
#include <vector>

#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos::detail {

/// runs.csv (one row per run), points.csv (incidence per grid point), summary.json.
void write_sweep_outputs(const SweepSpec& spec, const std::vector<RunRecord>& records,
                         const SweepSummary& summary, const std::string& dir);

}  // namespace pneumachaos::detail
