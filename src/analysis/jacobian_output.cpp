#include "analysis/jacobian_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>

#include "divergence_uncertainty.hpp"
#include "io/json_quantity.hpp"

namespace pneumachaos {
namespace {

using detail::kNormal95;  // +-1.96 standard errors: a two-sided 95 % interval

std::string spectrum_text(const JacobianResult& j) {
  std::string s;
  for (double l : j.exponents_per_s) s += fmt::format("{}{:.3g}", s.empty() ? "" : ", ", l);
  return s;
}

}  // namespace

EstimatorDisagreement estimator_disagreement(const AnalysisResult& r) {
  EstimatorDisagreement d;
  if (!r.jacobian_run || !r.divergence.found_linear_region) return d;
  d.defined = true;
  d.difference_per_s = r.jacobian.lambda_per_s - r.divergence.lambda_per_s;
  const double scale = std::abs(r.divergence.lambda_per_s);
  d.relative = scale > 0.0 ? d.difference_per_s / scale : NAN;
  d.combined_uncertainty_per_s =
      std::hypot(r.divergence.uncertainty_per_s, r.jacobian.uncertainty_per_s);
  d.in_uncertainties = d.combined_uncertainty_per_s > 0.0
                           ? std::abs(d.difference_per_s) / d.combined_uncertainty_per_s
                           : INFINITY;
  d.beyond_95 = d.in_uncertainties > kNormal95;
  return d;
}

CombinedExponent combined_exponent(const AnalysisResult& r) {
  CombinedExponent c;
  const EstimatorDisagreement d = estimator_disagreement(r);
  const double u_d = r.divergence.uncertainty_per_s, u_j = r.jacobian.uncertainty_per_s;
  if (!d.defined || !r.jacobian.reliable || !(u_d > 0.0) || !(u_j > 0.0)) return c;
  const double w_d = 1.0 / (u_d * u_d), w_j = 1.0 / (u_j * u_j);
  c.defined = true;
  c.value_per_s = (w_d * r.divergence.lambda_per_s + w_j * r.jacobian.lambda_per_s) / (w_d + w_j);
  c.scale = std::max(1.0, d.in_uncertainties);
  c.uncertainty_per_s = c.scale / std::sqrt(w_d + w_j);
  return c;
}

std::string jacobian_text(const AnalysisResult& r) {
  if (r.jacobian_status.empty()) return "";
  std::string out;
  if (r.jacobian_run) {
    const JacobianResult& j = r.jacobian;
    out += fmt::format(
        "  local Jacobians (Eckmann & Ruelle 1985): {:.4g} +- {:.2g} 1/s ({:.4g} bits/s; "
        "stretches +- {:.2g}, fit choices +- {:.2g}){}; all {}: {} 1/s, sum {:.3g} ({})\n",
        j.lambda_per_s, j.uncertainty_per_s, j.lambda_per_s / std::numbers::ln2,
        j.statistical_uncertainty_per_s, j.choice_spread_per_s,
        j.reliable ? "" : " UNRELIABLE", j.exponents_per_s.size(), spectrum_text(j), j.sum_per_s,
        !j.reliable ? "no map, no meaning" : j.sum_per_s < 0.0 ? "dissipative" : "not dissipative");
  }
  out += "  local Jacobians: " + r.jacobian_status + "\n";
  const EstimatorDisagreement d = estimator_disagreement(r);
  if (d.defined) {
    out += fmt::format(
        "  the two estimates: Jacobians - divergence = {:+.3g} 1/s ({:+.1f} %), {:.2g} of "
        "their combined uncertainty {:.2g} 1/s: {}\n",
        d.difference_per_s, 100.0 * d.relative, d.in_uncertainties,
        d.combined_uncertainty_per_s,
        d.beyond_95 ? "they disagree beyond their 95 % intervals"
                    : "consistent within their 95 % intervals");
  }
  const CombinedExponent c = combined_exponent(r);
  if (c.defined) {
    out += fmt::format(
        "  the two combined: {:.4g} +- {:.2g} 1/s (inverse-variance weights; the interval "
        "scaled by {:.2g} for their disagreement)\n",
        c.value_per_s, c.uncertainty_per_s, c.scale);
  }
  return out;
}

nlohmann::json jacobian_json(const AnalysisResult& r) {
  if (r.jacobian_status.empty()) return nullptr;
  const JacobianResult& j = r.jacobian;
  const bool run = r.jacobian_run;
  const EstimatorDisagreement d = estimator_disagreement(r);
  nlohmann::json out = {
      {"value", run ? json_number(j.lambda_per_s) : nullptr},
      {"uncertainty", run ? json_number(j.uncertainty_per_s) : nullptr},
      {"statistical_uncertainty", run ? json_number(j.statistical_uncertainty_per_s) : nullptr},
      {"choice_spread", run ? json_number(j.choice_spread_per_s) : nullptr},
      {"unit", "1/s"},
      {"value_bits", run ? json_number(j.lambda_per_s / std::numbers::ln2) : nullptr},
      {"unit_bits", "bits/s"},
      {"exponents", run ? nlohmann::json(j.exponents_per_s) : nlohmann::json(nullptr)},
      {"sum", run ? json_quantity(j.sum_per_s, "1/s") : nlohmann::json(nullptr)},
      {"reliable", run && j.reliable},
      {"unexplained", json_quantity(run ? j.unexplained : NAN, "-")},
      {"maps", j.maps},
      {"skipped", j.skipped},
      {"neighbours", j.neighbours},
      {"evolve_samples", j.evolve},
      {"delay_samples", j.delay},
      {"status", r.jacobian_status},
      {"method", "local linear maps, Householder QR along the trajectory (Eckmann & Ruelle "
                 "1985; Sano & Sawada 1985); uncertainty: batch means, and twice the neighbours or "
                 "the map's span"}};
  out["disagreement"] =
      d.defined ? nlohmann::json{{"difference", json_quantity(d.difference_per_s, "1/s")},
                                 {"relative", json_quantity(d.relative, "-")},
                                 {"combined_uncertainty",
                                  json_quantity(d.combined_uncertainty_per_s, "1/s")},
                                 {"in_uncertainties", json_quantity(d.in_uncertainties, "-")},
                                 {"beyond_95", d.beyond_95}}
                : nlohmann::json(nullptr);
  const CombinedExponent c = combined_exponent(r);
  out["combined"] =
      c.defined ? nlohmann::json{{"value", json_quantity(c.value_per_s, "1/s")},
                                 {"uncertainty", json_quantity(c.uncertainty_per_s, "1/s")},
                                 {"scale", json_quantity(c.scale, "-")}}
                : nlohmann::json(nullptr);
  return out;
}

}  // namespace pneumachaos
