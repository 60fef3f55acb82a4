#pragma once
// A user's measured incidence map (calibrate's incidence_map objective): per valve setting the
// fraction of runs with stick-slip and with chaos, as the paper's Figs. 4-6 report them.

#include <string>
#include <vector>

namespace pneumachaos {

/// The points of a full S1 x S2 grid, ordered with S2 fastest (the sweep's point order).
struct MeasuredMap {
  std::vector<double> s1, s2;  ///< the grid's axes [mm^2], ascending
  std::vector<double> stick_slip, chaos;  ///< incidence per point, 0..1
};

/// Reads CSV with the columns S1_mm2, S2_mm2, stick_slip, chaos (any order, a "[unit]"
/// suffix allowed, '#' comments). Rows may come in any order but must fill the grid of their
/// S1 and S2 values exactly once. Throws Error naming file:line (and the column) for a missing
/// column, a bad or out-of-range cell (areas > 0, incidences 0..1), a point given twice, a
/// missing point, or more than 100000 points.
MeasuredMap parse_measured_map(const std::string& text, const std::string& origin);
MeasuredMap read_measured_map(const std::string& path);

}  // namespace pneumachaos
