#pragma once
// The supply line between the regulator and the meter-in valve S1 (docs/model.md, "Supply
// line"): a volume V0 at pressure P0, filled from the regulator's constant pressure Ps through
// a restriction of effective area S0 and drained by S1 into chamber 1. Volume 0 (the default)
// is the ideal supply of the paper's model: S1 sees Ps directly and no state is added.

#include "pneumachaos/model/valve_flow.hpp"

namespace pneumachaos {

struct SupplyLineParams {
  /// V0: tube length x bore area plus the valve manifold; 0 = ideal supply (no state P0).
  double volume_m3 = 0.0;
  /// S0 of the regulator and its fittings, the line's source restriction.
  double regulator_S_m2 = 10.0e-6;
  /// n of dP0/dt = n R T / V0 (W_in - W_out): 1 isothermal, 1.4 adiabatic; a 4 mm tube's
  /// air lies between (thermal time constant ~0.1 s, docs/model.md "Supply line").
  double polytropic_exponent = 1.0;
  [[nodiscard]] bool enabled() const { return volume_m3 > 0.0; }
};

/// The line's pressure equation, with the regulator's restriction built once. The flow laws
/// are the chambers' (valve_flow.hpp); the line's air is taken at the supply temperature.
class SupplyLine {
 public:
  SupplyLine(const SupplyLineParams& p, const ValveLaw& valve, const GasConstants& gas,
             double supply_Pa, double T_K);
  /// Mass flow [kg/s] from the regulator into the line at line pressure P0.
  template <typename T>
  [[nodiscard]] T inflow(const T& P0) const {
    return regulator_.mass_flow(T(supply_Pa_), P0);
  }
  /// dP0/dt given the line pressure and the mass flow W_out it delivers through S1.
  template <typename T>
  [[nodiscard]] T pressure_rate(const T& P0, const T& W_out) const {
    return gain_ * (inflow(P0) - W_out);
  }
  [[nodiscard]] double volume_m3() const { return volume_m3_; }

 private:
  Orifice regulator_;
  double supply_Pa_;
  double volume_m3_;
  double gain_;  // n R T / V0 [Pa/kg]
};

}  // namespace pneumachaos
