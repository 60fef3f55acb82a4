#include "pneumachaos/io/column_units.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <cctype>
#include <cmath>

#include "pneumachaos/io/csv_text.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

struct KnownUnit {
  const char* name;
  Quantity quantity;
  double scale;
};

constexpr std::array kUnits{
    KnownUnit{"s", Quantity::kTime, 1.0},
    KnownUnit{"ms", Quantity::kTime, 1e-3},
    KnownUnit{"us", Quantity::kTime, 1e-6},
    KnownUnit{"µs", Quantity::kTime, 1e-6},
    KnownUnit{"m/s", Quantity::kVelocity, 1.0},
    KnownUnit{"mm/s", Quantity::kVelocity, 1e-3},
    KnownUnit{"Pa", Quantity::kPressure, 1.0},
    KnownUnit{"kPa", Quantity::kPressure, 1e3},
    KnownUnit{"MPa", Quantity::kPressure, 1e6},
    KnownUnit{"bar", Quantity::kPressure, 1e5},
    KnownUnit{"psi", Quantity::kPressure, 6894.757293168},
    KnownUnit{"m", Quantity::kPosition, 1.0},
    KnownUnit{"mm", Quantity::kPosition, 1e-3},
    KnownUnit{"m/s^2", Quantity::kAcceleration, 1.0},
    KnownUnit{"m/s2", Quantity::kAcceleration, 1.0},
    KnownUnit{"mm/s^2", Quantity::kAcceleration, 1e-3},
    KnownUnit{"mm/s2", Quantity::kAcceleration, 1e-3},
    KnownUnit{"N", Quantity::kForce, 1.0},
    KnownUnit{"kN", Quantity::kForce, 1e3},
};

const char* quantity_name(Quantity q) {
  switch (q) {
    case Quantity::kTime:
      return "a time";
    case Quantity::kVelocity:
      return "a velocity";
    case Quantity::kPressure:
      return "a pressure";
    case Quantity::kPosition:
      return "a position";
    case Quantity::kAcceleration:
      return "an acceleration";
    case Quantity::kForce:
      return "a force";
    case Quantity::kOther:
      break;
  }
  return "a value";
}

// Splits a pressure's gauge or absolute mark off: "MPa gauge", "bar g", "kPa(g)", "psig",
// "Pa abs". Returns the unit without it; `gauge` tells which mark it was.
std::string without_pressure_mark(const std::string& text, bool& marked, bool& gauge) {
  std::string lower;
  for (char c : text) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
  for (const std::string m : {" gauge", "(gauge)", "(g)", " g", " abs", "(abs)", " absolute"}) {
    if (lower.size() > m.size() && lower.ends_with(m)) {
      marked = true;
      gauge = m.find('g') != std::string::npos;
      return trim_field(text.substr(0, text.size() - m.size()));
    }
  }
  if (text == "psig") {
    marked = gauge = true;
    return "psi";
  }
  return text;
}

const KnownUnit* find_unit(const std::string& name) {
  const auto it = std::find_if(kUnits.begin(), kUnits.end(),
                               [&](const KnownUnit& u) { return name == u.name; });
  return it == kUnits.end() ? nullptr : &*it;
}

}  // namespace

std::string accepted_units(Quantity q) {
  std::string out;
  for (const KnownUnit& u : kUnits)
    if (u.quantity == q && std::string(u.name) != "µs")
      out += (out.empty() ? "" : ", ") + std::string(u.name);
  if (q == Quantity::kPressure)
    out += ", each optionally marked gauge (\"kPa g\") or absolute (\"kPa abs\")";
  return out;
}

ColumnUnit parse_unit(const std::string& text, std::optional<Quantity> expected,
                      const std::string& column, const std::string& where) {
  ColumnUnit unit;
  unit.text = trim_field(text);
  bool marked = false;
  const std::string bare = without_pressure_mark(unit.text, marked, unit.gauge);
  if (bare.empty() && !marked) {
    unit.quantity = expected.value_or(Quantity::kOther);  // no unit: SI, or a bare label
    return unit;
  }
  const KnownUnit* known = find_unit(bare.empty() ? "Pa" : bare);
  const bool fits = known && (!expected || known->quantity == *expected) &&
                    (!marked || known->quantity == Quantity::kPressure);
  if (!fits && (expected || marked)) {
    const Quantity q = expected.value_or(Quantity::kPressure);
    throw Error(where, fmt::format("column {}: unit \"{}\" is not {} unit this reader knows; "
                                   "expected {}",
                                   column, unit.text, quantity_name(q), accepted_units(q)));
  }
  if (!known) return unit;  // a label only: the analysed series keeps it as written
  unit.quantity = known->quantity;
  unit.scale = known->scale;
  return unit;
}

std::string unit_with_scale(Quantity q, double scale) {
  for (const KnownUnit& u : kUnits)
    if (u.quantity == q && std::abs(scale / u.scale - 1.0) < 0.01) return u.name;
  return "";
}

UnitOverrides parse_unit_overrides(const std::vector<std::string>& entries,
                                   const std::string& option) {
  UnitOverrides out;
  for (const std::string& e : entries) {
    const auto eq = e.find('=');
    const std::string name = trim_field(e.substr(0, eq));
    if (eq == std::string::npos || name.empty())
      throw Error(option,
                  fmt::format("expected COLUMN=UNIT, e.g. t=ms or \"P1=kPa g\", got \"{}\"", e));
    if (!out.emplace(name, trim_field(e.substr(eq + 1))).second)
      throw Error(option, fmt::format("column {} is given a unit twice", name));
  }
  return out;
}

std::vector<std::string> header_units(const std::vector<std::string>& header,
                                      const UnitOverrides& overrides, const std::string& where) {
  std::vector<std::string> units;
  for (const std::string& h : header) units.push_back(header_unit(h));
  for (const auto& entry : overrides) {
    const std::string& name = entry.first;  // a named copy: clang 15 cannot capture a binding
    const std::string& unit = entry.second;
    const auto it = std::find_if(header.begin(), header.end(),
                                 [&](const std::string& h) { return header_name(h) == name; });
    if (it == header.end())
      throw Error(where,
                  fmt::format("a unit is given for a column \"{}\" that the header lacks", name));
    auto& u = units[static_cast<std::size_t>(it - header.begin())];
    if (!u.empty())
      throw Error(where, fmt::format("column {} states its unit in brackets; the unit {}={} "
                                     "given beside it would contradict or repeat it: drop that "
                                     "entry",
                                     *it, name, unit));
    u = unit;
  }
  return units;
}

std::string implausible_value(double v, const ColumnUnit& unit, const std::string& column,
                              const PlausibleRange& range) {
  // Read as mm/s, a speed up to 1000 times the limit would be one; beyond, the unit is not it.
  if (unit.quantity == Quantity::kVelocity && std::abs(v) > 1e3 * range.max_speed_m_per_s)
    return fmt::format("speed {:.4g} m/s is beyond any pneumatic cylinder, even read as mm/s: "
                       "is the column {} a velocity?",
                       std::abs(v), column);
  if (unit.quantity == Quantity::kVelocity && std::abs(v) > range.max_speed_m_per_s)
    return fmt::format(
        "speed {:.4g} m/s is above {:g} m/s, faster than any pneumatic cylinder: "
        "the velocities look like mm/s; head the column {}[mm/s]",
        std::abs(v), range.max_speed_m_per_s, header_name(column));
  if (unit.quantity != Quantity::kPressure) return "";
  if (v < range.min_pressure_Pa)
    return fmt::format(
        "absolute pressure {1:.4g} Pa is below {2:g} kPa, where no chamber of a "
        "running cylinder falls: the pressures look like gauge values or kPa; "
        "head the column with its unit, e.g. {0}[kPa], {0}[Pa g] or {0}[MPa gauge] "
        "(or give --units \"{0}=Pa g\" for a header without brackets)",
        header_name(column), v, range.min_pressure_Pa * 1e-3);
  if (range.supply_Pa && v > PlausibleRange::kOverSupply * *range.supply_Pa)
    return fmt::format(
        "absolute pressure {:.4g} Pa is more than {:g} x the supply ({:.4g} Pa "
        "absolute): the unit looks wrong (Pa read as kPa?), or the scenario's "
        "supply.pressure_MPa is not the rig's",
        v, PlausibleRange::kOverSupply, *range.supply_Pa);
  if (v > range.max_pressure_Pa)
    return fmt::format(
        "absolute pressure {:.4g} Pa is above {:g} MPa, beyond any pneumatic "
        "rig: the unit looks wrong (Pa read as kPa?)",
        v, range.max_pressure_Pa * 1e-6);
  return "";
}

}  // namespace pneumachaos
