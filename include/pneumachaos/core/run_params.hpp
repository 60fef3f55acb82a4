#pragma once
// How one simulation run is carried out: its length, output rate, tolerances and stepper.
// Defined once, here below every module: the Scenario holds it as its [run] table (model),
// `simulate` takes it as its options (simulate), and the CLI maps --duration / --rate to its
// fields (docs/architecture.md, "Run settings").

#include "pneumachaos/core/hybrid_system.hpp"

namespace pneumachaos {

/// Where a run starts (docs/model.md, "Start and end of a run").
enum class RunStart : std::uint8_t {
  kRest,     ///< at rest against the stop, the valve switching at t = 0 (the paper's runs)
  kSliding,  ///< on the steady sliding motion the stability analysis linearises about
};

struct RunParams {
  double duration_s = 10.0;
  double sample_rate_Hz = 1000.0;
  double relative_tolerance = 1e-7;
  double absolute_tolerance = 1e-10;
  double max_step_s = 2e-3;  ///< bounds the step so short event excursions are not stepped over
  StepperKind stepper = StepperKind::kDopri5;
  RunStart start = RunStart::kRest;
};

}  // namespace pneumachaos
