#pragma once
// `calibrate`: fits the free scenario keys of a spec (calibration_spec.hpp) with pagmo2's
// CMA-ES or xNES, every evaluation run through the sweep engine and journalled, then
// predicts the spec's out-of-sample conditions at the best point (docs/guide/calibrate.md).

#include <cstddef>
#include <string>
#include <vector>

#include "pneumachaos/calibrate/calibration_spec.hpp"
#include "pneumachaos/claims/claims.hpp"

namespace pneumachaos {

struct CalibrateOptions {
  std::string out_dir;
  std::size_t threads = 0;  ///< the sweeps' threads; 0: all hardware threads
  /// Continue the calibration journalled in out_dir (its evaluations are replayed, not rerun).
  bool resume = false;
  bool progress = true;  ///< one line per evaluation, on a terminal only
  /// Throws Error naming the field (calibrate.out_dir, calibrate.threads).
  void validate() const;
};

/// A claim's result in the calibration: its weight in the objective (0 for a prediction).
struct ScoredClaim {
  Claim claim;
  double weight = 0.0;
};

struct CalibrationResult {
  std::size_t evaluations = 0, best = 0;  ///< evaluations made; index of the best
  double best_objective = 0.0;
  std::vector<double> best_values;      ///< the free keys at the best point (user units)
  std::vector<ScoredClaim> fitted;      ///< the objective's claims at the best point
  std::vector<ScoredClaim> predicted;   ///< [predict]'s claims, judged only there
  std::vector<double> map_errors;       ///< incidence_map: RMS stick-slip and chaos errors
  std::vector<double> record_errors;    ///< records: each record's scaled RMS error (NaN: failed)
  std::vector<Claim> all_claims;        ///< every row at the best point (claims.json)
  bool wrote_files = true;              ///< false on the MPI ranks other than 0
};

/// Runs (or resumes) the calibration into options.out_dir: journal.csv, evaluations.csv,
/// best_scenario.toml, claims.json, calibration.json, summary.md and figures/convergence.*
/// (the last five published together once the run is complete). Throws Error for bad input
/// or a directory holding something else, RunError when a file cannot be written.
CalibrationResult calibrate(const CalibrationSpec& spec, const CalibrateOptions& options);

/// The objective's value for a set of claim margins: the weighted mean of -tanh(margin), a
/// claim not evaluated (NaN) counting as +1, the worst. In [-1, 1]; lower is better.
double claims_objective(const std::vector<double>& margins, const std::vector<double>& weights);

}  // namespace pneumachaos
