#pragma once
// The paper's linear analysis (§3.2 meter-out, §3.3 meter-in) beside the eigenvalues of the
// full model's Jacobian at the same steady motion.

#include <complex>
#include <string>
#include <vector>

#include "pneumachaos/model/scenario.hpp"
#include "pneumachaos/stability/equilibrium.hpp"

namespace pneumachaos {

enum class StabilityVerdict { kDamped, kSelfExcited, kNoEquilibrium };
const char* verdict_name(StabilityVerdict v);

/// Kosaki & Sano's coefficients. Meter-out: a1 (eq. 9), a2 and a (eq. 6); meter-in: b1
/// (eq. 11), b2 and b (eq. 10). zeta = c1 / (2 sqrt(m c2)) (eq. 8) for the circuit's pair.
/// Cd = S * choked flux factor [kg/(s*Pa)], B = local friction slope at v0, m = total mass,
/// Fn0 = friction at v0, P1 = P10 of the equilibrium (the paper assumes it equals Ps).
struct PaperCoefficients {
  double Cd1_kg_per_sPa = 0.0, Cd2_kg_per_sPa = 0.0;
  double a1 = 0.0, a2 = 0.0, a = 0.0;  ///< meter-out [N*s/m], [N/m], [1/s]
  double b1 = 0.0, b2 = 0.0, b = 0.0;  ///< meter-in
  double zeta = 0.0;                   ///< damping coefficient of the circuit's pair (eq. 8)
  StabilityVerdict verdict = StabilityVerdict::kDamped;  ///< sign of a1 (meter-out) or b1 (meter-in)
};

/// The plant's circuit (meter-out or meter-in) picks the pair that decides zeta and the verdict.
PaperCoefficients paper_coefficients(const Plant& plant, const Equilibrium& eq);

struct StabilityOptions {
  EquilibriumOptions equilibrium;
  void validate() const { equilibrium.validate(); }
};

struct StabilityResult {
  StabilityVerdict verdict_full = StabilityVerdict::kNoEquilibrium;  ///< from the Jacobian's eigenvalues
  std::string reason;                              ///< when there is no equilibrium
  Equilibrium equilibrium;
  PaperCoefficients paper;
  std::vector<std::complex<double>> eigenvalues;  ///< [1/s], descending real part
  std::vector<std::string> state_names;           ///< states of the linearization
  double max_real_part_per_s = 0.0;
  double dominant_frequency_Hz = 0.0;   ///< of the eigenvalue with the largest real part
  double dominant_damping_ratio = 0.0;  ///< -Re/|lambda| of that eigenvalue
  /// The complex pair with the largest real part (the oscillation the paper's eq. 7
  /// describes); zero frequency when every eigenvalue is real.
  std::complex<double> oscillatory_pair{0.0, 0.0};
  double oscillatory_frequency_Hz = 0.0;
  double oscillatory_damping_ratio = 0.0;
  [[nodiscard]] bool agree() const { return paper.verdict == verdict_full; }
  [[nodiscard]] bool has_equilibrium() const { return verdict_full != StabilityVerdict::kNoEquilibrium; }
};

StabilityResult analyze_stability(const Plant& plant, const StabilityOptions& options = {});

/// Takes the chamber volumes at piston position `position_mm` [mm] instead of the default
/// (the frozen position, else mid-stroke). Throws Error named `name` (the flag or argument the
/// user typed) for a position outside 0 to the scenario's stroke.
void set_piston_position(StabilityOptions& options, const Scenario& scenario, double position_mm,
                         const std::string& name);

}  // namespace pneumachaos
