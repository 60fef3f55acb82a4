#pragma once
// Grids over scenario keys, written KEY=FROM:TO:STEP in the key's own unit
// (e.g. circuit.S1_mm2=2.45:3.70:0.05), as the paper's S1 x S2 maps.

#include <string>
#include <vector>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario.hpp"

namespace pneumachaos {

struct GridAxis {
  std::string key;             ///< a numeric scenario key
  std::vector<double> values;  ///< in the key's unit, ascending
};

/// The grid as a whole (no axis, too many runs) and one axis's text, in errors.
inline constexpr ErrorField kGridField{"grid", "grid"};
inline constexpr ErrorField kGridAxisField{"grid.axis", "grid axis"};

/// Parses KEY=FROM:TO:STEP; TO is included when it lies on the grid (to a millionth of a
/// step). Throws Error about kGridAxisField, naming the text, for an unknown or non-numeric
/// key, FROM > TO, STEP <= 0, or more than 100000 values.
GridAxis parse_grid_axis(const std::string& text);

/// The paper's grid (§4.1): S1 2.45..3.70 by 0.05 mm^2 (26 values) and S2 0.05..4.40 by
/// 0.15 mm^2 (30 values).
std::vector<GridAxis> paper_valve_grid();

/// Checks a set of axes: at least one, no key twice. Throws Error.
void validate_grid(const std::vector<GridAxis>& axes);

/// Scenario at one grid point: `base` with axis i set to values[index[i]].
Scenario scenario_at(const Scenario& base, const std::vector<GridAxis>& axes,
                     const std::vector<std::size_t>& index);

/// Number of points of the full product grid.
std::size_t grid_size(const std::vector<GridAxis>& axes);
/// Index vector of point `flat` (last axis fastest).
std::vector<std::size_t> grid_index(const std::vector<GridAxis>& axes, std::size_t flat);

}  // namespace pneumachaos
