#pragma once
// The data the report's page reads to make its maps explorable (report_data.js beside
// index.html): every map cell with its runs as runs.csv holds them and the command that
// runs each of them again alone, and the cells each claim read.

#include <string>
#include <vector>

#include "pneumachaos/claims/claims.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

/// One incidence map of the report and where its files are, relative to the report folder.
struct MapData {
  std::string figure;  ///< the FigureSpec name, also the anchor of its figure
  std::string title;
  std::string sweep_dir;      ///< e.g. "sweeps/adaptive_ps025_m15" (holds runs.csv)
  std::string scenario_file;  ///< the map's scenario as its sweep ran it
  /// How `sweep` gets that scenario: a scenario file and/or --set arguments.
  std::string scenario_args;
  SweepSpec spec;
  SweepSummary summary;
};

/// The `--set` arguments that turn the scenario `from` into `to`, one per key whose value
/// differs, each value as the scenario file writes it, except the load's mass, written in
/// full: the report derives it from the total moving mass (1.5 - 1.05 kg is not 0.45 to the
/// last bit) and a run's record depends on every bit.
std::string set_arguments(const Scenario& from, const Scenario& to);

/// One run of a sweep: its grid point and repeat.
struct RunKey {
  std::size_t point = 0, repeat = 0;
};

/// The runs of a map that runs.csv under report_dir holds, in its order.
std::vector<RunKey> map_run_keys(const MapData& map, const std::string& report_dir);

/// The map's run traces for the page, relative to the report folder (runs/FIGURE.js).
std::string runs_file(const MapData& map);

/// `sweep` arguments that name one map's grid, repeats and seed, so that `--replay P:R`
/// added to them runs one of its runs again (docs/sweep.md, "What a run stores").
std::string replay_arguments(const MapData& map);

/// report_data.js: a script that assigns the data to window.PNEUMACHAOS_REPORT. A script
/// rather than a .json file because a page opened from disk (file://) may not fetch a
/// file beside it in Chromium (docs/notes/explorable_report.md). Reads each map's runs.csv
/// under report_dir; throws Error naming a runs.csv that cannot be read.
std::string report_data_js(const std::vector<MapData>& maps, const std::vector<Claim>& claims,
                           const std::string& report_dir);

}  // namespace pneumachaos
