// The fit's options checked before any work: each out-of-range value is named with its field.
#include <fmt/format.h>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/identify/fit.hpp"

namespace pneumachaos::identify {
namespace {

void check(bool ok, const char* field, double value, const char* range) {
  if (!ok) throw Error(std::string("fit ") + field, fmt::format("{}: must be {}", value, range));
}

}  // namespace

void FitOptions::validate() const {
  check(segment_length_s > 0.0, "segment_length_s", segment_length_s, "> 0");
  for (double s : first_segment_lengths_s)
    check(s > 0.0, "first_segment_lengths_s", s, "> 0 (each)");
  check(pressure_scale_Pa > 0.0, "pressure_scale_Pa", pressure_scale_Pa, "> 0");
  check(velocity_scale_m_per_s > 0.0, "velocity_scale_m_per_s", velocity_scale_m_per_s, "> 0");
  check(start_half_window >= 1, "start_half_window", static_cast<double>(start_half_window),
        ">= 1 (a straight line needs two samples)");
  check(rest_speed_m_per_s >= 0.0, "rest_speed_m_per_s", rest_speed_m_per_s, ">= 0");
  check(x0_m == x0_m, "x0_m", x0_m, "a number");
  check(difference_step > 0.0 && difference_step < 1.0, "difference_step", difference_step,
        "between 0 and 1 (a step in the logarithm of a parameter)");
  check(max_factor > 1.0, "max_factor", max_factor, "> 1 (the bounds must enclose the start)");
  check(max_iterations >= 1, "max_iterations", max_iterations, ">= 1");
  check(function_tolerance > 0.0, "function_tolerance", function_tolerance, "> 0");
  check(parameter_tolerance > 0.0, "parameter_tolerance", parameter_tolerance, "> 0");
  // The integrator's own floor (simulate.cpp's integrator_options): tighter than 1e-12 relative
  // is below double rounding over a segment's steps.
  check(relative_tolerance >= 1e-12 && relative_tolerance < 1.0, "relative_tolerance",
        relative_tolerance, ">= 1e-12 and < 1");
  check(absolute_tolerance > 0.0, "absolute_tolerance", absolute_tolerance, "> 0");
}

}  // namespace pneumachaos::identify
