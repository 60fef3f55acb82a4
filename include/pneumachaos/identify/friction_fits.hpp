#pragma once
// Friction models fitted to a friction estimate (docs/friction.md, "Fits"): classic (eq. 4),
// Stribeck with delta fixed or free, LuGre; optionally pressure dependent. Ceres Solver for
// the least squares and the covariance of the parameters.

#include <cstddef>
#include <optional>
#include <string>
#include <vector>

#include "pneumachaos/identify/friction_estimate.hpp"
#include "pneumachaos/model/friction.hpp"
#include "pneumachaos/model/scenario.hpp"

namespace pneumachaos::identify {

enum class FrictionFitModel { kClassic, kStribeck, kStribeckDelta, kLuGre };

/// "classic", "stribeck" (delta fixed), "stribeck_delta" (delta free), "lugre".
const char* fit_model_name(FrictionFitModel m);
/// Throws Error naming `where` for an unknown name.
FrictionFitModel parse_fit_model(const std::string& name, const std::string& where);
std::vector<FrictionFitModel> all_fit_models();

struct FrictionFitOptions {
  std::vector<FrictionFitModel> models = all_fit_models();
  bool pressure_dependent = false;  ///< fit Fc_gain_N_per_MPa and Fs_gain_N_per_MPa too
  double fixed_exponent = 2.0;      ///< delta of "stribeck" (the scenario's, from the CLI)
  /// LuGre start (and the Stribeck levels when no Stribeck fit is available).
  FrictionParams start;
  int max_iterations = 200;
  /// Throws Error naming the field that is out of range.
  void validate() const;
};

/// A parameter as the scenario names it (Fc_N, Fs_N, vs_mm_per_s, B_Ns_per_m, ...), in that
/// key's unit. stderr is NaN when the covariance is not available (rank deficient).
struct FittedParameter {
  std::string name;
  double value = 0.0;
  double stderr_value = 0.0;
  std::string unit;
  bool fixed = false;  ///< held at its value (delta of "stribeck"; LuGre's levels)
};

struct ModelFit {
  FrictionFitModel model = FrictionFitModel::kClassic;
  std::string name;
  bool fitted = false;
  std::string skipped;     ///< why not fitted (too few sliding samples), when !fitted
  bool converged = false;  ///< fitted but not converged: `summary` says why
  std::string summary;     ///< Ceres' one-line report
  std::vector<FittedParameter> params;
  FrictionParams friction;  ///< the fitted law, for curves and the scenario fragment
  double rms_N = 0.0;       ///< residual RMS on the comparison set (sliding + breakaways)
  std::size_t points = 0;   ///< size of the comparison set
  std::size_t free_params = 0;
  double bic = 0.0;
  double aic = 0.0;
  [[nodiscard]] const FittedParameter* param(const std::string& name) const;
};

struct FrictionFits {
  std::vector<ModelFit> fits;
  /// Smallest BIC among the converged fits with Fc <= Fs; "" if none.
  std::string preferred_model;
  std::string criterion = "BIC";
  /// What a reader must know about the fits, one sentence each: a fit that did not converge
  /// (shown, marked, never preferred), a fit whose kinetic level Fc exceeds its static Fs.
  std::vector<std::string> warnings;
  /// The first fit that did not converge, if any.
  [[nodiscard]] const ModelFit* failed() const;
  /// The fit named preferred_model; none when no fit converged with Fc <= Fs.
  [[nodiscard]] const ModelFit* preferred() const;
  /// Whether at least one fit converged.
  [[nodiscard]] bool any_converged() const;
};

FrictionFits fit_friction(const FrictionEstimate& estimate, const FrictionFitOptions& options);

/// The fit options a scenario implies: its seal as the start (and Stribeck exponent for the
/// fixed-delta model), the named models (empty: all; repeats ignored; an unknown name is an
/// Error at `where`), pressure dependence on request.
FrictionFitOptions fit_options_for(const Scenario& scenario, const std::vector<std::string>& models,
                                   bool pressure_dependent, const std::string& where);

/// Throws RunError when fits were made and none converged (naming the first, with Ceres's
/// reason); a fit that did not converge beside one that did is a warning, not a failure: the
/// models that converged are reported.
void require_converged(const FrictionFits& fits);

/// The steady friction of a fitted law at velocity v (gauge sum for pressure dependence).
double steady_friction_N(const FrictionParams& p, double v_m_per_s, double gauge_sum_Pa);

}  // namespace pneumachaos::identify
