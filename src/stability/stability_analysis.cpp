#include "pneumachaos/stability/stability_analysis.hpp"

#include <fmt/format.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <cmath>
#include <numbers>

#include "pneumachaos/core/error.hpp"
#include "stability/linearization.hpp"

namespace pneumachaos {

const char* verdict_name(StabilityVerdict v) {
  switch (v) {
    case StabilityVerdict::kDamped:
      return "damped";
    case StabilityVerdict::kSelfExcited:
      return "self-excited";
    case StabilityVerdict::kNoEquilibrium:
      return "no-equilibrium";
  }
  return "?";
}

PaperCoefficients paper_coefficients(const Plant& plant, const Equilibrium& eq) {
  const double k = plant.polytropic_exponent();
  const double RT = plant.RT_J_per_kg();
  const LoadParams& load = plant.load();
  const double m =
      load.mass_kg + (load.coupling == LoadCoupling::kSpring ? load.piston_mass_kg : 0.0);
  const double V10 = plant.geometry().volume_head_m3(eq.position_m);
  const double V20 = plant.geometry().volume_rod_m3(eq.position_m);
  const double B = eq.slope_Ns_per_m;
  const double v0 = eq.v0_m_per_s;
  PaperCoefficients c;
  c.Cd1_kg_per_sPa = plant.valve1().choked_coefficient();
  c.Cd2_kg_per_sPa = plant.valve2().choked_coefficient();
  // Meter-out, P1 constant, exhaust choked (eqs. 6 and 9).
  c.a = (k * RT * c.Cd2_kg_per_sPa - k * plant.A2() * v0) / V20;
  c.a1 = k * m * RT * c.Cd2_kg_per_sPa / (V20 * eq.P20_Pa) *
             (eq.P20_Pa - eq.P10_Pa + eq.friction_N / plant.A1()) +
         B;
  c.a2 = k * plant.A2() * plant.A2() * eq.P20_Pa / V20 - c.a * B;
  // Meter-in, P2 atmospheric, supply choked (eqs. 10 and 11).
  c.b = k * plant.A1() * v0 / V10;
  c.b1 = k * m * RT * c.Cd1_kg_per_sPa / (V10 * eq.P10_Pa) * plant.supply_pressure_Pa() + B;
  c.b2 = k * plant.A1() * plant.A1() * eq.P10_Pa / V10 + c.b * B;
  const bool meter_out = plant.circuit() == CircuitKind::kMeterOut;
  const double c1 = meter_out ? c.a1 : c.b1;
  const double c2 = meter_out ? c.a2 : c.b2;
  c.zeta = c2 > 0.0 ? c1 / (2.0 * std::sqrt(m * c2)) : std::numeric_limits<double>::quiet_NaN();
  c.verdict = c1 > 0.0 ? StabilityVerdict::kDamped : StabilityVerdict::kSelfExcited;
  return c;
}

StabilityResult analyze_stability(const Plant& plant, const StabilityOptions& options) {
  options.validate();
  StabilityResult r;
  const EquilibriumResult eqs = find_equilibria(plant, options.equilibrium);
  if (!eqs.exists()) {
    r.reason = eqs.reason;
    return r;
  }
  r.equilibrium = eqs.primary();
  r.paper = paper_coefficients(plant, r.equilibrium);
  const Eigen::MatrixXd J = jacobian(plant, r.equilibrium);
  r.state_names = reduced_state(plant, r.equilibrium).names;
  const Eigen::EigenSolver<Eigen::MatrixXd> solver(J, /*computeEigenvectors=*/false);
  for (Eigen::Index i = 0; i < solver.eigenvalues().size(); ++i) {
    r.eigenvalues.push_back(solver.eigenvalues()[i]);
  }
  // Descending real part; of a conjugate pair the member with positive imaginary part first.
  std::sort(r.eigenvalues.begin(), r.eigenvalues.end(), [](auto a, auto b) {
    return a.real() != b.real() ? a.real() > b.real() : a.imag() > b.imag();
  });
  const std::complex<double> dominant = r.eigenvalues.front();
  r.max_real_part_per_s = dominant.real();
  r.dominant_frequency_Hz = std::abs(dominant.imag()) / (2.0 * std::numbers::pi);
  r.dominant_damping_ratio = std::abs(dominant) > 0.0 ? -dominant.real() / std::abs(dominant) : 0.0;
  for (const auto& ev : r.eigenvalues) {
    if (ev.imag() > 0.0) {  // sorted by real part: the first complex one leads
      r.oscillatory_pair = ev;
      r.oscillatory_frequency_Hz = ev.imag() / (2.0 * std::numbers::pi);
      r.oscillatory_damping_ratio = -ev.real() / std::abs(ev);
      break;
    }
  }
  r.verdict_full = dominant.real() < 0.0 ? StabilityVerdict::kDamped : StabilityVerdict::kSelfExcited;
  return r;
}

void set_piston_position(StabilityOptions& options, const Scenario& scenario, double position_mm,
                         const std::string& name) {
  const double stroke_mm = scenario.cylinder.stroke_m * 1e3;
  if (!(position_mm >= 0.0 && position_mm <= stroke_mm)) {
    throw Error(name, fmt::format("{} mm is not a piston position: expected 0 to the stroke, {} mm",
                                  position_mm, stroke_mm));
  }
  options.equilibrium.position_m = position_mm * 1e-3;
}

}  // namespace pneumachaos
