#include "pneumachaos/simulate/lyapunov_output.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <numbers>

#include "io/json_quantity.hpp"

namespace pneumachaos {

std::string lyapunov_summary(const ModelLyapunovResult& r, const ModelLyapunovOptions& o) {
  std::string out = fmt::format(
      "largest Lyapunov exponent of the model: {:.4g} +- {:.2g} 1/s ({:.4g} bits/s)\n",
      r.lambda_per_s, r.uncertainty_per_s, r.lambda_per_s / std::numbers::ln2);
  // A stroke end may have cut the measurement short (until_terminal_event): say so.
  const bool cut = r.measured_s > 0.0 && r.measured_s < o.measure_s - 0.5 * o.renormalize_s;
  out += fmt::format(
      "{} renormalisations every {} s over {:.6g} s after {} s of transient ({} postponed "
      "while the two trajectories were in different stick/slip modes){}\n",
      r.renormalizations, o.renormalize_s, cut ? r.measured_s : o.measure_s, o.transient_s,
      r.postponed, cut ? "; the run reached its stroke end" : "");
  out += "convergence (running estimate, 1/s):";
  const std::size_t n = r.running_per_s.size();
  for (std::size_t k = 1; k <= 8 && n > 0; ++k) {
    const std::size_t i = std::min(n - 1, std::max<std::size_t>(1, k * n / 8) - 1);
    out += fmt::format(" t={:.3g}s:{:.4g}", r.running_time_s[i], r.running_per_s[i]);
  }
  return out + "\n";
}

std::string lyapunov_json(const ModelLyapunovResult& r, const ModelLyapunovOptions& o) {
  nlohmann::json running = {{"t", {{"values", r.running_time_s}, {"unit", "s"}}},
                            {"lambda", {{"values", r.running_per_s}, {"unit", "1/s"}}}};
  const nlohmann::json j = {
      {"lyapunov",
       {{"lambda", json_quantity(r.lambda_per_s, "1/s")},
        {"uncertainty", json_quantity(r.uncertainty_per_s, "1/s")},
        {"bits", json_quantity(r.lambda_per_s / std::numbers::ln2, "bit/s")},
        {"renormalizations", r.renormalizations},
        {"postponed", r.postponed},
        {"measured", json_quantity(r.measured_s, "s")},
        {"running", running}}},
      {"settings",
       {{"transient", json_quantity(o.transient_s, "s")},
        {"measure", json_quantity(o.measure_s, "s")},
        {"renormalize", json_quantity(o.renormalize_s, "s")},
        {"separation", json_quantity(o.separation, "-")}}}};
  return j.dump(2);
}

}  // namespace pneumachaos
