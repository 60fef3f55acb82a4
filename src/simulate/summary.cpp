#include <fmt/format.h>

#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos {

std::string describe(const IntegrationSummary& s, bool smooth_seal) {
  // The counts are mode switches of a stiction model; a smooth seal model (gms, lugre) sticks
  // without any, which the record's velocity shows, so only then is that said.
  std::string sticking = fmt::format("{} stick, {} slip", s.events.stick, s.events.slip);
  if (s.events.stick == 0 && s.events.slip == 0)
    sticking = smooth_seal ? "no stick/slip mode switch (a smooth seal model, gms or lugre, "
                             "sticks without one: the record's v shows it)"
                           : "0 stick, 0 slip (the seal did not stick)";
  return fmt::format(
      "{} at t = {:.6g} s ({}); {} steps accepted, {} rejected, {} derivative evaluations; "
      "events: {}, {} reversal, {} stop hit, {} stop release; wall time {:.3g} s",
      termination_name(s.termination), s.t_final_s, s.message, s.steps_accepted, s.steps_rejected,
      s.rhs_evaluations, sticking, s.events.reversal, s.events.stop_hit, s.events.stop_release,
      s.wall_time_s);
}

}  // namespace pneumachaos
