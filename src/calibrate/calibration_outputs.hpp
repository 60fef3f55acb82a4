#pragma once
// The best point's claims and the calibration's files (private to the calibrate module).

#include <string>
#include <vector>

#include "condition_runs.hpp"
#include "evaluation_journal.hpp"
#include "pneumachaos/calibrate/calibrate.hpp"
#include "calibrate/optimizer.hpp"

namespace pneumachaos::detail {

/// The best evaluation's values, and every claim of the objective's and [predict]'s conditions
/// run together at it (into dir; resumed when there).
CalibrationResult best_point_result(const CalibrationSpec& spec, const OptimizerTrace& trace,
                                    const std::vector<JournalEntry>& entries,
                                    const std::string& dir, const ConditionRunOptions& settings);

/// evaluations.csv, best_scenario.toml, claims.json, calibration.json, summary.md (published
/// together, after figures/convergence.*).
void write_calibration_outputs(const CalibrationSpec& spec, const OptimizerTrace& trace,
                               const std::vector<JournalEntry>& entries,
                               const std::vector<std::string>& terms, const CalibrationResult& r,
                               const std::string& out_dir);

}  // namespace pneumachaos::detail
