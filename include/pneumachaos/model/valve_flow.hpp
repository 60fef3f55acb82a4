#pragma once
// Mass flow of air through a restriction sized by its effective sectional area S
// (JIS B 8390), MODEL.md "Valve flow through an effective sectional area S".

namespace pneumachaos {

enum class FlowLaw {
  kIso6358,     ///< choked below b, elliptic subsonic branch above (ISO 6358 with S)
  kIsentropic,  ///< Saint-Venant / isentropic nozzle formula
};

/// Gas constants used by the flow law.
struct GasConstants {
  double R_J_per_kgK = 287.0;         ///< specific gas constant of air
  double heat_capacity_ratio = 1.4;   ///< cp/cv of the flowing gas (used in the nozzle law)
};

struct ValveLaw {
  FlowLaw law = FlowLaw::kIso6358;
  double critical_ratio = 0.528;  ///< b of ISO 6358; ignored by the isentropic law
  /// Above this pressure ratio the flow is made linear in the pressure difference (matched in
  /// value at the junction), so the integrator never meets the infinite slope at r = 1.
  double laminar_ratio = 0.995;
};

/// Choked-flow coefficient per unit area: W_choked = S * P_up * choked_flux_factor.
/// [s/m] = sqrt(k/(R T)) * (2/(k+1))^((k+1)/(2(k-1))).
double choked_flux_factor(const GasConstants& gas, double T_up_K);

/// Mass flow [kg/s] from the node at pressure P_a to the node at pressure P_b through area
/// S_m2; negative when P_b > P_a (reverse flow). T_a_K and T_b_K are the temperatures of the
/// two nodes; the upstream one is used.
double valve_mass_flow(const ValveLaw& valve, const GasConstants& gas, double S_m2, double P_a_Pa,
                       double T_a_K, double P_b_Pa, double T_b_K);

/// Dimensionless flow function psi(r) of the law in forward direction (P_up >= P_down),
/// with the laminar branch applied: W = S * P_up * choked_flux_factor * psi(r).
double flow_function(const ValveLaw& valve, const GasConstants& gas, double r);

}  // namespace pneumachaos
