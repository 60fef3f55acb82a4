// The measured record's reading options and the friction fits' options, checked before any
// work: each out-of-range value is named with its field (core/validation.hpp).
#include <cmath>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/identify/friction_fits.hpp"
#include "pneumachaos/identify/measured_record_csv.hpp"

namespace pneumachaos::identify {

void RecordReadOptions::validate() const {
  using namespace validation;
  require(std::isfinite(ambient_Pa) && ambient_Pa > 0.0, field("record.ambient_Pa"), ambient_Pa,
        "a positive pressure [Pa abs]");
  if (stroke_m) require_gt(field("record.stroke_m"), *stroke_m, 0, "when given");
  require_gt(field("record.max_speed_m_per_s"), plausible.max_speed_m_per_s, 0);
}

void FrictionFitOptions::validate() const {
  using namespace validation;
  if (models.empty()) throw Error("friction_fit.models", "expected at least one model to fit");
  require_gt(field("friction_fit.fixed_exponent"), fixed_exponent, 0,
             "the Stribeck curve's exponent");
  require_ge(field("friction_fit.max_iterations"), max_iterations, 1);
  require_gt(field("friction_fit.start.curve.coulomb_N"), start.curve.coulomb_N, 0);
  require_gt(field("friction_fit.start.curve.static_N"), start.curve.static_N, 0);
}

}  // namespace pneumachaos::identify
