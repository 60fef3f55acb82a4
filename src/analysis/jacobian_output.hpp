#pragma once
// (Internal to the analysis module.) The local-Jacobian estimate in `analyze`'s text and JSON,
// beside the divergence estimate and compared with it (docs/reference/outputs.md).

#include <nlohmann/json.hpp>
#include <string>

#include "pneumachaos/analysis/analyze.hpp"

namespace pneumachaos {

/// How far the local-Jacobian exponent lies from the divergence exponent, in 1/s and in units
/// of their combined uncertainty (the two uncertainties in quadrature).
struct EstimatorDisagreement {
  bool defined = false;  ///< both estimates exist
  double difference_per_s = 0.0;  ///< Jacobian minus divergence
  double relative = 0.0;          ///< difference / |divergence value|
  double combined_uncertainty_per_s = 0.0;
  double in_uncertainties = 0.0;  ///< |difference| / combined uncertainty
  bool beyond_95 = false;         ///< in_uncertainties > 1.96: the 95 % intervals disagree
};

EstimatorDisagreement estimator_disagreement(const AnalysisResult& r);

/// The two estimates of the largest exponent as one, by a rule fixed before it was measured:
/// the inverse-variance weighted mean, its standard error sqrt(1 / sum w) multiplied by the
/// Particle Data Group's scale factor S = max(1, sqrt(chi2 / (N - 1))) (Review of Particle
/// Physics, "Introduction: averaging"), which for two estimates is max(1, their difference in
/// combined uncertainties): where they disagree the interval widens in proportion.
/// Defined where both are (a linear region, a reliable Jacobian estimate).
struct CombinedExponent {
  bool defined = false;
  double value_per_s = 0.0;
  double uncertainty_per_s = 0.0;  ///< one standard error, scaled by `scale`
  double scale = 1.0;              ///< S >= 1
};

CombinedExponent combined_exponent(const AnalysisResult& r);

/// The text lines (empty when not requested).
std::string jacobian_text(const AnalysisResult& r);

/// lyapunov.jacobian of the JSON (null when not requested).
nlohmann::json jacobian_json(const AnalysisResult& r);

}  // namespace pneumachaos
