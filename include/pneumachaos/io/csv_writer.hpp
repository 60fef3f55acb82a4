#pragma once
// CSV output of a TimeSeries: a header "t[s],name[unit],..." and one row per sample.

#include <ostream>

#include "pneumachaos/core/time_series.hpp"

namespace pneumachaos {

/// Writes the series with a leading time column. Numbers use the shortest text that reads
/// back to the same double, so a written file round-trips exactly.
void write_csv(std::ostream& out, const TimeSeries& series);

}  // namespace pneumachaos
