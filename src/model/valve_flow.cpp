#include "pneumachaos/model/valve_flow.hpp"

#include <algorithm>
#include <cmath>

namespace pneumachaos {

double choked_flux_factor(const GasConstants& gas, double T_up_K) {
  const double k = gas.heat_capacity_ratio;
  // The k -> 1 limit of (2/(k+1))^((k+1)/(2(k-1))) is exp(-1/2); guard the removable 0/0.
  const double expo = std::abs(k - 1.0) < 1e-9
                          ? std::exp(-0.5)
                          : std::pow(2.0 / (k + 1.0), (k + 1.0) / (2.0 * (k - 1.0)));
  return std::sqrt(k / (gas.R_J_per_kgK * T_up_K)) * expo;
}

Orifice::Orifice(const ValveLaw& valve, const GasConstants& gas, double S_m2, double T_K)
    : valve_(valve),
      k_(gas.heat_capacity_ratio),
      coefficient_(S_m2 * choked_flux_factor(gas, T_K)),
      r_crit_(valve.law == FlowLaw::kIso6358 ? valve.critical_ratio
                                             : std::pow(2.0 / (k_ + 1.0), k_ / (k_ - 1.0))) {
  if (valve_.law == FlowLaw::kIsentropic) {
    // Normalise the nozzle's flux by its choked value so that psi = 1 when choked.
    inv_flux_crit_ =
        1.0 / std::sqrt(std::pow(r_crit_, 2.0 / k_) - std::pow(r_crit_, (k_ + 1.0) / k_));
  }
  // Near r = 1 the law's flow goes as sqrt(1 - r) (a turbulent orifice), with an infinite
  // slope at r = 1. Above r_lam it is replaced by a x + c x^2 in x = 1 - r: linear at small
  // pressure differences (laminar), and matched to the law in value AND slope at r_lam, so the
  // flow's derivative is continuous there and the junction's place does not act as a kink
  // (docs/model.md, "Valves").
  const double r_lam = valve_.laminar_ratio, x_lam = 1.0 - r_lam, h = 1e-4 * x_lam;
  const double psi_lam = raw_psi(r_lam);
  const double slope = (raw_psi(r_lam - h) - raw_psi(r_lam + h)) / (2.0 * h);  // d psi / dx
  lam_c_ = (slope * x_lam - psi_lam) / (x_lam * x_lam);
  lam_a_ = slope - 2.0 * lam_c_ * x_lam;
}

double flow_function(const ValveLaw& valve, const GasConstants& gas, double r) {
  return Orifice(valve, gas, 0.0, 293.15).psi(r);
}

double valve_mass_flow(const ValveLaw& valve, const GasConstants& gas, double S_m2, double P_a_Pa,
                       double T_a_K, double P_b_Pa, double T_b_K) {
  // Reverse flow carries the other node's temperature.
  return P_a_Pa >= P_b_Pa ? Orifice(valve, gas, S_m2, T_a_K).mass_flow(P_a_Pa, P_b_Pa)
                          : Orifice(valve, gas, S_m2, T_b_K).mass_flow(P_a_Pa, P_b_Pa);
}

}  // namespace pneumachaos
