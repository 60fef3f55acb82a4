#pragma once
// (Private to the io module.) The one JSON shape of a number with a unit, {"value": v, "unit": "..."}, shared by every
// command's --json output; a non-finite value is written as null, never as NaN.

#include <cmath>
#include <nlohmann/json.hpp>
#include <string>

namespace pneumachaos {

inline nlohmann::json json_number(double v) {
  return std::isfinite(v) ? nlohmann::json(v) : nlohmann::json(nullptr);
}

inline nlohmann::json json_quantity(double v, const std::string& unit) {
  return {{"value", json_number(v)}, {"unit", unit}};
}

}  // namespace pneumachaos
