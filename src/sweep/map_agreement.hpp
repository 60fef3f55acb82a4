#pragma once
// How far an adaptive map is from the full grid's map of the same sweep (its
// validation): the shares of points whose classes agree, each region's area error against its
// border's length, and the runs saved.

#include <cstddef>
#include <string>
#include <vector>

#include "pneumachaos/sweep/sweep.hpp"
#include "pneumachaos/sweep/sweep_runner.hpp"

namespace pneumachaos {

struct RegionAgreement {
  std::string region;               ///< "stick-slip", "chaos in every run", "chaos in some run"
  std::size_t full_points = 0;      ///< the region's area on the full grid [points]
  std::size_t adaptive_points = 0;  ///< and on the adaptive map
  /// Neighbouring point pairs (along either axis) of the full map on opposite sides of the
  /// region's border: its length in grid steps, the bound of the goal "within one grid cell
  /// per border crossing".
  std::size_t border_steps = 0;
  [[nodiscard]] std::size_t area_error() const;
};

struct MapAgreement {
  std::size_t points = 0, inferred_points = 0;
  std::size_t full_runs = 0, adaptive_runs = 0;
  double stick_slip_agreement = 0.0;  ///< share of points in the same stick-slip class
  double chaos_agreement = 0.0;       ///< share of points in the same chaos class (none/some/all)
  /// Share of points with the same most frequent regime (sweep_regime_names(), e.g. steady or
  /// periodic): not what the refinement follows, so an inferred point's may be wrong.
  double regime_agreement = 0.0;
  std::vector<RegionAgreement> regions;
  /// Full runs per adaptive run.
  [[nodiscard]] double runs_ratio() const;
  /// Every region's area error within its border's length.
  [[nodiscard]] bool areas_within_borders() const;
  /// One line per figure, for logs and the validation table.
  [[nodiscard]] std::string describe() const;
};

/// Compares two summaries of one two-axis sweep (per_point in grid order, the second axis
/// fastest): `full` evaluated everywhere, `adaptive` with inferred points. Throws Error when
/// they differ in their points.
MapAgreement compare_maps(const SweepSpec& spec, const SweepSummary& full,
                          const SweepSummary& adaptive);

struct AdaptiveValidation {
  SweepSummary full, adaptive;
  MapAgreement agreement;
  double full_wall_s = 0.0, adaptive_wall_s = 0.0;  ///< each sweep's wall time, this process
};

/// Runs `spec` (two axes; its `adaptive` settings, enabled or not, give the coarse step) over
/// its full grid into options.out_dir/full and adaptively into options.out_dir/adaptive, one
/// after the other in this process, and compares the maps. With options.resume a finished
/// pair is re-read (then the wall times say nothing).
AdaptiveValidation validate_adaptive(SweepSpec spec, const SweepOptions& options);

}  // namespace pneumachaos
