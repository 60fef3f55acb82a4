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
  double R_J_per_kgK = 287.0;        ///< specific gas constant of air
  double heat_capacity_ratio = 1.4;  ///< cp/cv of the flowing gas (used in the nozzle law)
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

/// A restriction of fixed area, law and upstream temperatures, with the law's constants
/// computed once (the flow law runs in the innermost loop of every simulation).
class Orifice {
 public:
  Orifice(const ValveLaw& valve, const GasConstants& gas, double S_m2, double T_K);
  /// Mass flow [kg/s] from pressure P_a to P_b; negative for reverse flow.
  [[nodiscard]] double mass_flow(double P_a_Pa, double P_b_Pa) const;
  /// psi(r) for 0 <= r <= 1, laminar branch included.
  [[nodiscard]] double psi(double r) const;
  /// d psi / d r, analytic (used by the linearization).
  [[nodiscard]] double dpsi_dr(double r) const;

  struct Partials {
    double W = 0.0;       ///< mass flow from a to b [kg/s]
    double dW_dPa = 0.0;  ///< [kg/(s*Pa)]
    double dW_dPb = 0.0;
  };
  [[nodiscard]] Partials mass_flow_partials(double P_a_Pa, double P_b_Pa) const;
  /// S * choked flux factor: the paper's Cd [kg/(s*Pa)], W_choked = Cd * P_up.
  [[nodiscard]] double choked_coefficient() const { return coefficient_; }

 private:
  [[nodiscard]] double raw_psi(double r) const;
  ValveLaw valve_;
  double k_;
  double coefficient_;  // S * choked_flux_factor
  double r_crit_;       // b (ISO 6358) or the isentropic critical ratio
  double inv_flux_crit_ = 1.0;
  double psi_lam_ = 0.0;
};

/// Dimensionless flow function psi(r) of the law in forward direction (P_up >= P_down),
/// with the laminar branch applied: W = S * P_up * choked_flux_factor * psi(r).
double flow_function(const ValveLaw& valve, const GasConstants& gas, double r);

}  // namespace pneumachaos
