#pragma once
// Running a sweep into a directory that survives interruption: every finished run is appended
// to a journal and synced to disk; `resume` skips what the journal holds; the result files
// are written from the journal, sorted, so they do not depend on threads, order or resumes.

#include <functional>
#include <string>

#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

struct SweepOptions {
  std::string out_dir;
  bool resume = false;
  std::size_t threads = 0;  ///< 0: all hardware threads
  bool progress = true;     ///< shown only when standard error is a terminal
  /// Called after each finished run with (runs done, runs in the sweep), from the worker
  /// that finished it, one call at a time; for callers that show progress their own way
  /// (a notebook). It must not throw.
  std::function<void(std::size_t, std::size_t)> on_progress;
  /// Called with each run this process simulates, before it is judged, from the worker running
  /// it, concurrently with other runs' calls: for callers that keep what runs.csv does not (the
  /// report keeps each run's record for its page). Not called for runs the journal already
  /// holds (resume) or that other MPI ranks run. It must not throw.
  std::function<void(const SweepRun&)> on_run;
  void validate() const;
};

/// Runs the sweep (or its remainder) and writes runs.csv, points.csv and summary.json into
/// out_dir. Throws Error for a directory that already holds a different sweep, or one that
/// holds this sweep without `resume`.
SweepSummary run_sweep(const SweepSpec& spec, const SweepOptions& options);

/// Whether this build can distribute a sweep over MPI ranks (under mpirun).
bool sweeps_support_mpi();

}  // namespace pneumachaos
