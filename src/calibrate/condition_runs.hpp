#pragma once
// Running a set of conditions on one scenario (private to the calibrate module): each map a
// resumable sweep on the sweep engine's threads and MPI ranks (as reproduce runs its maps),
// the example one record; together the inputs the claims module's claims read.

#include <string>

#include "pneumachaos/calibrate/calibration_spec.hpp"
#include "pneumachaos/claims/claims.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos::detail {

struct ConditionRunOptions {
  std::size_t threads = 0;
  std::uint64_t sweep_seed = 1;
};

/// The sweep of one map condition at `scenario` over the spec's grid.
SweepSpec map_sweep_spec(const ObjectiveSpec& o, Scenario scenario, const MapCondition& c);

/// Runs every map of `conditions` into dir/<role> (resumed when there) and the example, and
/// fills the claims' inputs, judged as `o.paper_judge` says. A scenario the model refuses or a
/// run that fails leaves its inputs empty (the claims then are "not reproduced"); only an
/// unusable directory throws.
void run_conditions(const ObjectiveSpec& o, const Scenario& scenario,
                    const ConditionSet& conditions, const std::string& dir,
                    const ConditionRunOptions& settings, ClaimInputs& inputs);

/// Runs the example (Figs. 3 and 7) and adds its inputs; a failed run leaves them empty.
void add_example(const ObjectiveSpec& o, const Scenario& scenario, ClaimInputs& inputs);

/// Runs one sweep quietly into dir (resumed when there).
SweepSummary run_map(const SweepSpec& spec, const std::string& dir, const ConditionRunOptions& settings);

/// Removes the map of `role` from the inputs.
void clear_role(ClaimInputs& inputs, const std::string& role);

/// This process's MPI rank (0 without MPI): only rank 0 writes calibrate's own files.
bool is_writer_rank();

}  // namespace pneumachaos::detail
