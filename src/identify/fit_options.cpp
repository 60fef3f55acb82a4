// The fit's options checked before any work: each out-of-range value is named with its field
// (core/validation.hpp).
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/identify/fit.hpp"

namespace pneumachaos::identify {
namespace {

// The integrator's own floor (simulate.cpp's integrator_options): tighter than this relative
// tolerance is below double rounding over a segment's steps.
constexpr double kTightestRelativeTolerance = 1e-12;

}  // namespace

void FitOptions::validate() const {
  using namespace validation;
  require_gt(field("fit.segment_length_s"), segment_length_s, 0);
  for (double s : first_segment_lengths_s)
    require_gt(field("fit.first_segment_lengths_s"), s, 0, "each");
  require_gt(field("fit.pressure_scale_Pa"), pressure_scale_Pa, 0);
  require_gt(field("fit.velocity_scale_m_per_s"), velocity_scale_m_per_s, 0);
  require_ge(field("fit.start_half_window"), static_cast<double>(start_half_window), 1,
             "a straight line needs two samples");
  require_ge(field("fit.rest_speed_m_per_s"), rest_speed_m_per_s, 0);
  require(x0_m == x0_m, field("fit.x0_m"), x0_m, "a number");
  require_gt_lt(field("fit.difference_step"), difference_step, 0, 1,
                "a step in the logarithm of a parameter");
  require_gt(field("fit.max_factor"), max_factor, 1, "the bounds must enclose the start");
  require_ge(field("fit.max_iterations"), max_iterations, 1);
  require_gt(field("fit.function_tolerance"), function_tolerance, 0);
  require_gt(field("fit.parameter_tolerance"), parameter_tolerance, 0);
  require_ge_lt(field("fit.relative_tolerance"), relative_tolerance, kTightestRelativeTolerance, 1);
  require_gt(field("fit.absolute_tolerance"), absolute_tolerance, 0);
}

}  // namespace pneumachaos::identify
