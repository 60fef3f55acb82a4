#include <fmt/format.h>

#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos {

std::string describe(const IntegrationSummary& s) {
  return fmt::format(
      "{} at t = {:.6g} s ({}); {} steps accepted, {} rejected, {} derivative evaluations; "
      "events: {} stick, {} slip, {} reversal, {} stop hit, {} stop release; wall time {:.3g} s",
      termination_name(s.termination), s.t_final_s, s.message, s.steps_accepted, s.steps_rejected,
      s.rhs_evaluations, s.events.stick, s.events.slip, s.events.reversal, s.events.stop_hit,
      s.events.stop_release, s.wall_time_s);
}

}  // namespace pneumachaos
