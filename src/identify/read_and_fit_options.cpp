// The measured record's reading options and the friction fits' options, checked before any
// work: each out-of-range value is named with its field.
#include <fmt/format.h>

#include <cmath>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/identify/friction_fits.hpp"
#include "pneumachaos/identify/measured_record_csv.hpp"

namespace pneumachaos::identify {
namespace {

void check(bool ok, const std::string& field, double value, const char* range) {
  if (!ok) throw Error(field, fmt::format("{}: must be {}", value, range));
}

}  // namespace

void RecordReadOptions::validate() const {
  check(std::isfinite(ambient_Pa) && ambient_Pa > 0.0, "record ambient_Pa", ambient_Pa,
        "a positive pressure [Pa abs]");
  if (stroke_m) check(*stroke_m > 0.0, "record stroke_m", *stroke_m, "> 0 when given");
  check(plausible.max_speed_m_per_s > 0.0, "record max_speed_m_per_s", plausible.max_speed_m_per_s,
        "> 0");
}

void FrictionFitOptions::validate() const {
  if (models.empty()) throw Error("friction fit models", "expected at least one model to fit");
  check(fixed_exponent > 0.0, "friction fit fixed_exponent", fixed_exponent,
        "> 0 (the Stribeck curve's exponent)");
  check(max_iterations >= 1, "friction fit max_iterations", max_iterations, ">= 1");
  check(start.curve.coulomb_N > 0.0, "friction fit start.curve.coulomb_N", start.curve.coulomb_N,
        "> 0");
  check(start.curve.static_N > 0.0, "friction fit start.curve.static_N", start.curve.static_N,
        "> 0");
}

}  // namespace pneumachaos::identify
