#pragma once
// Mass flow of air through a restriction sized by its effective sectional area S
// (JIS B 8390), docs/model.md, "Valves".

#include <cmath>

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
  /// Above this pressure ratio the flow becomes linear in the pressure difference as r -> 1
  /// (laminar), joined to the law in value and slope (a quadratic in 1 - r), so the
  /// integrator never meets the infinite slope at r = 1.
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
/// computed once (the flow law runs in the innermost loop of every simulation). The law is
/// written once on a scalar type T (double, or an automatic-differentiation scalar when the
/// plant's Jacobian is taken).
class Orifice {
 public:
  Orifice(const ValveLaw& valve, const GasConstants& gas, double S_m2, double T_K);
  /// Mass flow [kg/s] from pressure P_a to P_b; negative for reverse flow.
  [[nodiscard]] double mass_flow(double P_a_Pa, double P_b_Pa) const {
    return mass_flow<double>(P_a_Pa, P_b_Pa);
  }
  template <typename T>
  [[nodiscard]] T mass_flow(const T& P_a_Pa, const T& P_b_Pa) const;
  /// psi(r) for 0 <= r <= 1, laminar branch included.
  template <typename T = double>
  [[nodiscard]] T psi(T r) const;
  /// S * choked flux factor: the paper's Cd [kg/(s*Pa)], W_choked = Cd * P_up.
  [[nodiscard]] double choked_coefficient() const { return coefficient_; }

 private:
  template <typename T>
  [[nodiscard]] T raw_psi(const T& r) const;
  ValveLaw valve_;
  double k_;
  double coefficient_;  // S * choked_flux_factor
  double r_crit_;       // b (ISO 6358) or the isentropic critical ratio
  double inv_flux_crit_ = 1.0;
  double lam_a_ = 0.0, lam_c_ = 0.0;  // psi = a x + c x^2, x = 1 - r, above r_lam
};

template <typename T>
T Orifice::raw_psi(const T& r) const {
  using std::pow;
  using std::sqrt;
  if (r <= r_crit_) return T(1.0);
  T radicand;
  if (valve_.law == FlowLaw::kIso6358) {
    const T q = (r - r_crit_) / (1.0 - r_crit_);
    radicand = 1.0 - q * q;
  } else {
    radicand = pow(r, 2.0 / k_) - pow(r, (k_ + 1.0) / k_);
  }
  if (!(0.0 < radicand)) radicand = T(0.0);
  const T root = sqrt(radicand);
  return valve_.law == FlowLaw::kIso6358 ? root : T(root * inv_flux_crit_);
}

template <typename T>
T Orifice::psi(T r) const {
  if (r < 0.0) {
    r = T(0.0);
  } else if (1.0 < r) {
    r = T(1.0);
  }
  const double r_lam = valve_.laminar_ratio;
  if (r <= r_lam) return raw_psi(r);
  // Laminar as r -> 1, joined to the law in value and slope at r_lam: the ellipse's infinite
  // slope at r = 1 would otherwise stall the integrator.
  const T x = 1.0 - r;
  return x * (lam_a_ + lam_c_ * x);
}

template <typename T>
T Orifice::mass_flow(const T& P_a_Pa, const T& P_b_Pa) const {
  if (coefficient_ <= 0.0 || P_a_Pa == P_b_Pa) return T(0.0);
  if (P_a_Pa > P_b_Pa) return coefficient_ * P_a_Pa * psi<T>(P_b_Pa / P_a_Pa);
  return -coefficient_ * P_b_Pa * psi<T>(P_a_Pa / P_b_Pa);
}

/// Dimensionless flow function psi(r) of the law in forward direction (P_up >= P_down),
/// with the laminar branch applied: W = S * P_up * choked_flux_factor * psi(r).
double flow_function(const ValveLaw& valve, const GasConstants& gas, double r);

}  // namespace pneumachaos
