#pragma once
// Simulation options for tests that compare with closed forms: tolerances far below the
// documented defaults, so the integration error is negligible against the checked bounds.
#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos {

inline RunParams tight(double duration) {
  RunParams o;
  o.duration_s = duration;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-12;
  return o;
}

}  // namespace pneumachaos
