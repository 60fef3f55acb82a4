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
  psi_lam_ = raw_psi(valve_.laminar_ratio);
}

double Orifice::raw_psi(double r) const {
  if (r <= r_crit_) return 1.0;
  if (valve_.law == FlowLaw::kIso6358) {
    const double q = (r - r_crit_) / (1.0 - r_crit_);
    return std::sqrt(std::max(0.0, 1.0 - q * q));
  }
  const double flux = std::pow(r, 2.0 / k_) - std::pow(r, (k_ + 1.0) / k_);
  return std::sqrt(std::max(0.0, flux)) * inv_flux_crit_;
}

double Orifice::psi(double r) const {
  r = std::clamp(r, 0.0, 1.0);
  const double r_lam = valve_.laminar_ratio;
  if (r <= r_lam) return raw_psi(r);
  // Linear in (1 - r) = (P_up - P_down)/P_up, equal to the law at r_lam: the ellipse's
  // infinite slope at r = 1 would otherwise stall the integrator.
  return psi_lam_ * (1.0 - r) / (1.0 - r_lam);
}

double Orifice::dpsi_dr(double r) const {
  r = std::clamp(r, 0.0, 1.0);
  if (r > valve_.laminar_ratio) return -psi_lam_ / (1.0 - valve_.laminar_ratio);
  if (r <= r_crit_) return 0.0;
  if (valve_.law == FlowLaw::kIso6358) {
    const double q = (r - r_crit_) / (1.0 - r_crit_);
    return -q / (std::sqrt(1.0 - q * q) * (1.0 - r_crit_));
  }
  const double flux = std::pow(r, 2.0 / k_) - std::pow(r, (k_ + 1.0) / k_);
  const double dflux =
      2.0 / k_ * std::pow(r, 2.0 / k_ - 1.0) - (k_ + 1.0) / k_ * std::pow(r, 1.0 / k_);
  return inv_flux_crit_ * dflux / (2.0 * std::sqrt(flux));
}

Orifice::Partials Orifice::mass_flow_partials(double P_a_Pa, double P_b_Pa) const {
  Partials d;
  if (coefficient_ <= 0.0) return d;
  const bool forward = P_a_Pa >= P_b_Pa;
  const double P_up = forward ? P_a_Pa : P_b_Pa;
  const double r = (forward ? P_b_Pa : P_a_Pa) / P_up;
  const double s = forward ? 1.0 : -1.0;
  // W = s c P_up psi(P_down / P_up).
  d.W = s * coefficient_ * P_up * psi(r);
  const double d_up = s * coefficient_ * (psi(r) - r * dpsi_dr(r));
  const double d_down = s * coefficient_ * dpsi_dr(r);
  d.dW_dPa = forward ? d_up : d_down;
  d.dW_dPb = forward ? d_down : d_up;
  return d;
}

double Orifice::mass_flow(double P_a_Pa, double P_b_Pa) const {
  if (coefficient_ <= 0.0 || P_a_Pa == P_b_Pa) return 0.0;
  if (P_a_Pa > P_b_Pa) return coefficient_ * P_a_Pa * psi(P_b_Pa / P_a_Pa);
  return -coefficient_ * P_b_Pa * psi(P_a_Pa / P_b_Pa);
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
