#pragma once
// Reading a measured record (docs/friction.md, "Input"): a CSV whose header names the columns
// with their units in brackets, as `simulate` writes them (t[s], v[m/s], P1[Pa], P2[Pa],
// x[m], a[m/s^2]). Every value is converted once, here, to the SI units and absolute
// pressures of MeasuredRecord.

#include <optional>
#include <string>

#include "pneumachaos/identify/measured_record.hpp"
#include "pneumachaos/io/column_units.hpp"
#include "pneumachaos/model/scenario.hpp"

namespace pneumachaos::identify {

/// Header names of the columns (matched exactly, or as the name before "[unit]"). Empty x or
/// a: the column is optional and looked for under its default name only.
struct RecordColumns {
  std::string t = "t";  ///< also found as "time"
  std::string v = "v";
  std::string P1 = "P1";
  std::string P2 = "P2";
  std::string x = "x";  ///< optional
  std::string a = "a";  ///< optional
};

struct RecordReadOptions {
  /// Added to pressures whose unit carries the `gauge` marker, e.g. P1[MPa gauge].
  double ambient_Pa = kStandardAmbientPa;
  /// Cylinder stroke (m): when given, a velocity whose integral travels further than
  /// 1.5 strokes (plus 10 mm) is refused as being in the wrong unit.
  std::optional<double> stroke_m;
  /// Values no rig produces, refused naming the likely mistake (kPa or gauge values under a
  /// [Pa] header, mm/s under [m/s]); the supply is known when a scenario gives it.
  PlausibleRange plausible;
  /// Units of columns whose header has no brackets (`--units`), e.g. {"t", "ms"}.
  UnitOverrides units;
  /// Throws Error naming the field that is out of range.
  void validate() const;
};

/// The reading options a scenario implies: its ambient pressure for gauge columns and its
/// stroke for the travel check (none when the scenario freezes its chamber volumes: a virtual
/// rig's long record may travel beyond the stroke, a real one cannot).
RecordReadOptions read_options_for(const Scenario& scenario);

/// Units as parse_unit() accepts them (time s, ms, us; velocity m/s, mm/s; pressure Pa, kPa,
/// MPa, bar, psi, each optionally gauge, "kPa g"; position m, mm; acceleration m/s^2, mm/s^2),
/// from the header's brackets or options.units; a column without either is taken as SI.
/// Throws Error naming file:line[:column] for: a missing column (naming it and listing the
/// header), an unknown unit, a cell that is not a finite number, a row with the wrong number
/// of fields, a value implausible_value() refuses (an absolute pressure below 50 kPa or above
/// twice the supply, a speed above 10 m/s), non-increasing or non-uniform time, a velocity
/// implausibly large for the stroke, fewer than 100 samples. Path "-" reads standard input.
MeasuredRecord read_measured_record(const std::string& path, const RecordColumns& names,
                                    const RecordReadOptions& options = {});

/// The same from text in memory; `origin` names it in errors.
MeasuredRecord parse_measured_record(const std::string& text, const std::string& origin,
                                     const RecordColumns& names,
                                     const RecordReadOptions& options = {});

}  // namespace pneumachaos::identify
