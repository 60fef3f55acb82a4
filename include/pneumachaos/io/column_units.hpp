#pragma once
// The unit of a record's column, read once from its header's brackets ("t[ms]", "P1[kPa g]")
// or from a `--units NAME=UNIT` entry for a header without brackets, with the factor that
// takes its values to SI units and the physical plausibility of a value once converted. Every
// record reader (the analysed series, the measured rig records) goes through these functions.

#include <map>
#include <optional>
#include <string>
#include <vector>

namespace pneumachaos {

/// Standard atmosphere [Pa]: the ambient pressure added to gauge readings when no scenario
/// gives one (the scenario key ambient.pressure_kPa does).
inline constexpr double kStandardAmbientPa = 101325.0;

/// What a unit measures; kOther: a unit this reader does not know (a label only).
enum class Quantity { kTime, kVelocity, kPressure, kPosition, kAcceleration, kForce, kOther };

struct ColumnUnit {
  Quantity quantity = Quantity::kOther;
  double scale = 1.0;  ///< value_SI = value * scale
  bool gauge = false;  ///< a pressure above ambient: absolute = value * scale + ambient
  std::string text;    ///< as written, e.g. "kPa g"; "" when the header states none
};

/// The units every reader accepts, for one quantity, as a user reads them in an error.
std::string accepted_units(Quantity q);

/// Parses a unit as written: time s, ms, us; velocity m/s, mm/s; pressure Pa, kPa, MPa, bar,
/// psi, each optionally marked gauge ("kPa g", "MPa gauge", "bar(g)", "psig") or absolute
/// ("Pa abs"); position m, mm; acceleration m/s^2, mm/s^2; force N, kN. An empty text is the
/// SI unit of `expected`. Throws Error(where) naming `column` when the text is not a unit of
/// `expected` (or, with no expected quantity, when a gauge mark follows no pressure unit);
/// with no expected quantity an unknown unit is kOther, scale 1.
ColumnUnit parse_unit(const std::string& text, std::optional<Quantity> expected,
                      const std::string& column, const std::string& where);

/// The unit of quantity `q` whose factor to SI is `scale` (within 1 %), e.g. "ms" for a time
/// and 1e-3; "" when none is.
std::string unit_with_scale(Quantity q, double scale);

/// `--units` entries NAME=UNIT (e.g. "t=ms", "P1=kPa g") by column name.
using UnitOverrides = std::map<std::string, std::string>;

/// Parses `--units` entries; throws Error(option) for an entry without "=" or a name given
/// twice.
UnitOverrides parse_unit_overrides(const std::vector<std::string>& entries,
                                   const std::string& option);

/// The unit text of each header: its brackets, or its entry in `overrides` (`--units`, a
/// calibration record's `units`). Throws Error(where) for an entry that names no column of the
/// header or one whose brackets already state a unit.
std::vector<std::string> header_units(const std::vector<std::string>& header,
                                      const UnitOverrides& overrides, const std::string& where);

/// What a value converted to SI (absolute for pressures) must respect to be physical.
struct PlausibleRange {
  /// Absolute chamber pressures below this [Pa] are refused: a pneumatic chamber vented to the
  /// atmosphere holds ~100 kPa; kPa or gauge values under a [Pa] header read far lower.
  double min_pressure_Pa = 50e3;
  /// The supply's absolute pressure [Pa] when known; a chamber above kOverSupply x this
  /// is refused.
  std::optional<double> supply_Pa;
  /// Largest absolute pressure with no supply known [Pa]: above any pneumatic rig.
  double max_pressure_Pa = 10.0e6;
  /// Speeds above this [m/s] are refused: no pneumatic cylinder moves at 10 m/s.
  double max_speed_m_per_s = 10.0;
  /// A rod-side chamber of a meter-out circuit compresses beyond the supply by up to the
  /// ratio of the piston areas (~1.3 on a standard rod); twice the supply is the limit.
  static constexpr double kOverSupply = 2.0;
};

/// Why a value in SI units (absolute for pressures) cannot be what the column says, naming the
/// likely mistake; "" when it can. `column` is the header as written.
std::string implausible_value(double value_si, const ColumnUnit& unit, const std::string& column,
                              const PlausibleRange& range);

}  // namespace pneumachaos
