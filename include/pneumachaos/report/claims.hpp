#pragma once
// The paper's claims against our numbers, each judged "agrees", "disagrees" or "not
// reproduced" by a stated rule from the sweep results and the chaotic example.

#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/report/claim_rules.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {

struct Claim {
  std::string claim;    ///< the paper's statement
  std::string paper;    ///< its figure, as the paper gives it
  std::string ours;     ///< our measured figure
  std::string verdict;  ///< agrees / disagrees / not reproduced
  std::string rule;     ///< how the verdict was decided
  std::string figure;   ///< the report figure that shows it (FigureSpec name), or empty
};

/// Fig. 2's records, reduced: fluctuation (std/|mean| of the settled part) and mean speed,
/// one value per restrictor area, in order of increasing S.
struct CircuitContrast {
  std::vector<double> meter_in_fluctuation, meter_out_fluctuation;
  std::vector<double> meter_in_mean, meter_out_mean;
};

/// A coefficient of the paper's linear analysis before and after a change (Ps or load).
struct DampingChange {
  double a1_before = 0.0, a1_after = 0.0;        ///< eq. (9), meter-out
  double b1_before = 0.0, b1_after = 0.0;        ///< eq. (11), meter-in
  double max_re_before = 0.0, max_re_after = 0.0;  ///< full model's largest real part [1/s]
};

/// The paper's sign rule (a1 / b1 < 0: self-excited) against the simulated runs per point.
struct SignRuleCounts {
  std::size_t damped = 0, damped_steady = 0;  ///< steady in at least half of the runs
  std::size_t excited = 0, excited_moving = 0;  ///< not steady in at least half of the runs
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
  std::optional<double> example_model_uncertainty;  ///< its standard error [1/s]
  std::optional<bool> example_chaotic;         ///< the regime verdict of the settled record
  std::optional<double> example_peak_share;    ///< spectral peak (+-1 bin) / total power
  std::optional<double> example_acf_after_1s;  ///< largest |ACF| at lags >= 1 s
  std::optional<CircuitContrast> fig2;
  std::optional<double> friction_slope;        ///< dF/dv at low speed, chaotic record [N*s/m]
  double friction_slope_vmax = 0.0;            ///< its upper speed [m/s]
  std::optional<FoldStretch> fold_stretch;    ///< Fig. 7c, settled example record
  std::optional<FrictionLoop> friction_loop;  ///< Fig. 3, settled example record
  std::optional<DampingChange> higher_ps, heavier;
  std::optional<SignRuleCounts> sign_rule;
};

/// The claims of the chaotic example, Figs. 2 and 3 and the linear analysis (claims_example.cpp).
std::vector<Claim> example_claims(const ClaimInputs& in);

std::vector<Claim> evaluate_claims(const ClaimInputs& in);

}  // namespace pneumachaos
