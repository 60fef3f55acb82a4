#pragma once
// Reading one uniformly sampled channel from a record (measured or simulated): comma-separated
// with a header naming the columns (as `simulate` writes), or blank-separated columns with or
// without a header (TISEAN and lab exports); '#' lines are comments.

#include <optional>
#include <string>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/io/column_units.hpp"

namespace pneumachaos {

struct CsvSeriesOptions {
  /// Header name, matched exactly or before a "[unit]" suffix; in a file without a header the
  /// column's number (1 = first; the default "v" then means the first column).
  std::string column = "v";
  /// Sample rate [Hz]; when unset the file needs a time column (t, time, t[s], time_s); when
  /// set and the file has one, the two must agree (within time_jitter) or the read is refused.
  std::optional<double> rate_Hz;
  /// Largest allowed deviation of a time step from the median step, relative to it; A/D
  /// timestamps jitter a little, a missing sample (a step of 2) is refused.
  double time_jitter = 0.01;
  /// Units of columns whose header has no brackets (`--units`), e.g. {"t", "ms"}. The time
  /// column's unit (s, ms, us; s without one) is converted to seconds; the analysed column's
  /// unit labels the series, and a known one (m/s, kPa, ...) is checked for values no rig
  /// produces (parse_unit, implausible_value).
  UnitOverrides units;
  static constexpr ErrorField kRateField{"csv.rate_Hz", "sampling rate"};
  /// Throws Error naming the field that is out of range.
  void validate() const;
};

/// Reads the column as a one-channel TimeSeries named after it (its header name and unit;
/// "column N" with no unit in a file without a header); path "-" reads standard
/// input. A first line whose fields are all numbers is data (no header). Throws Error naming
/// the file, line and column for a missing column, a non-numeric or non-finite cell, a row
/// with the wrong number of fields, non-increasing or non-uniform time, or fewer than 2
/// samples.
TimeSeries read_csv_series(const std::string& path, const CsvSeriesOptions& options);

/// The same from text already in memory; `origin` names it in errors.
TimeSeries parse_csv_series(const std::string& text, const std::string& origin,
                            const CsvSeriesOptions& options);

}  // namespace pneumachaos
