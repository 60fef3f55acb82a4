#pragma once
// The chaotic example (the paper's Figs. 3 and 7) as a measurement of any scenario: its record,
// the analysis of the settled part and the model's own exponent, and the claim inputs they give.
// `reproduce` draws its figures from it; `calibrate` scores scenarios with it.

#include <cstddef>
#include <vector>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/claims/claims.hpp"
#include "pneumachaos/simulate/model_lyapunov.hpp"
#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos {

/// The example starts at rest; its analysis and Fig. 7 skip the start-up.
constexpr double kExampleSettle_s = 2.0;

struct ExampleRun {
  SimulationResult sim;          ///< the whole record
  std::size_t settle = 0;        ///< first sample of the settled part
  std::vector<double> v;         ///< the settled velocity [m/s], as its transducer records it
  AnalysisResult analysis;       ///< of v
  ModelLyapunovResult model;     ///< the model's own exponent (ok = false when not asked)
};

/// Simulates `s` for record_s (or up to its stroke end) and analyses the settled record; with
/// `model_exponent` also the model's exponent after 1 s of start-up over the rest. Throws Error
/// when the simulation fails.
ExampleRun run_example(const Scenario& s, double record_s, bool model_exponent);

/// The Fig. 7 and Fig. 3 numbers of the claims from the example.
void add_example_inputs(ClaimInputs& ci, const ExampleRun& run);

}  // namespace pneumachaos
