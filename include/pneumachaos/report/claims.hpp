#pragma once
// The paper's claims against our numbers, each judged "agrees", "disagrees" or "not
// reproduced" by a stated rule from the sweep results and the chaotic example.

#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

struct Claim {
  std::string claim;    ///< the paper's statement
  std::string paper;    ///< its figure, as the paper gives it
  std::string ours;     ///< our measured figure
  std::string verdict;  ///< agrees / disagrees / not reproduced
  std::string rule;     ///< how the verdict was decided
};

struct ClaimInputs {
  SweepSpec spec;                        ///< the grid of the maps (S1, S2 axes first and second)
  std::optional<SweepSummary> base;      ///< Ps 0.25 MPa, m 1.5 kg
  std::optional<SweepSummary> high_ps;   ///< Ps 0.30 MPa
  std::optional<SweepSummary> double_m;  ///< m 3.0 kg
  std::optional<SweepSummary> triple_m;  ///< m 4.5 kg
  std::optional<double> example_lambda;  ///< divergence exponent of the Fig. 7 record [1/s]
  std::optional<double> example_uncertainty;
  std::optional<double> example_model_lambda;  ///< the model's own exponent there [1/s]
};

std::vector<Claim> evaluate_claims(const ClaimInputs& in);

}  // namespace pneumachaos
