#include "pneumachaos/model/valve_flow.hpp"

#include <algorithm>
#include <cmath>

namespace pneumachaos {
namespace {

// psi without the laminar branch, for 0 <= r <= 1.
double raw_flow_function(const ValveLaw& valve, const GasConstants& gas, double r) {
  if (valve.law == FlowLaw::kIso6358) {
    const double b = valve.critical_ratio;
    if (r <= b) return 1.0;
    const double q = (r - b) / (1.0 - b);
    return std::sqrt(std::max(0.0, 1.0 - q * q));
  }
  // Isentropic nozzle, normalised by its choked value so psi = 1 when choked.
  const double k = gas.heat_capacity_ratio;
  const double r_crit = std::pow(2.0 / (k + 1.0), k / (k - 1.0));
  if (r <= r_crit) return 1.0;
  const double flux = std::sqrt(std::max(0.0, std::pow(r, 2.0 / k) - std::pow(r, (k + 1.0) / k)));
  const double flux_crit =
      std::sqrt(std::pow(r_crit, 2.0 / k) - std::pow(r_crit, (k + 1.0) / k));
  return flux / flux_crit;
}

}  // namespace

double choked_flux_factor(const GasConstants& gas, double T_up_K) {
  const double k = gas.heat_capacity_ratio;
  // The k -> 1 limit of (2/(k+1))^((k+1)/(2(k-1))) is exp(-1/2); guard the removable 0/0.
  const double expo = std::abs(k - 1.0) < 1e-9 ? std::exp(-0.5)
                                                : std::pow(2.0 / (k + 1.0), (k + 1.0) / (2.0 * (k - 1.0)));
  return std::sqrt(k / (gas.R_J_per_kgK * T_up_K)) * expo;
}

double flow_function(const ValveLaw& valve, const GasConstants& gas, double r) {
  r = std::clamp(r, 0.0, 1.0);
  const double r_lam = valve.laminar_ratio;
  if (r <= r_lam) return raw_flow_function(valve, gas, r);
  // Linear in (1 - r) = (P_up - P_down)/P_up, equal to the law at r_lam.
  return raw_flow_function(valve, gas, r_lam) * (1.0 - r) / (1.0 - r_lam);
}

double valve_mass_flow(const ValveLaw& valve, const GasConstants& gas, double S_m2, double P_a_Pa,
                       double T_a_K, double P_b_Pa, double T_b_K) {
  if (S_m2 <= 0.0 || P_a_Pa == P_b_Pa) return 0.0;
  const bool forward = P_a_Pa > P_b_Pa;
  const double P_up = forward ? P_a_Pa : P_b_Pa;
  const double P_down = forward ? P_b_Pa : P_a_Pa;
  const double T_up = forward ? T_a_K : T_b_K;
  const double W = S_m2 * P_up * choked_flux_factor(gas, T_up) *
                   flow_function(valve, gas, P_down / P_up);
  return forward ? W : -W;
}

}  // namespace pneumachaos
