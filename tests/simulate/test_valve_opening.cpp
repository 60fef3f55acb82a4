// The solenoid valve's opening lag (docs/model.md, "Valves"): S1's area grows as
// S1 (1 - exp(-t / tau)) after the switch. Checked against the closed form of a rigid chamber
// filled through the opening valve while choked, and the instant valve it reduces to.
#include <gtest/gtest.h>

#include <cmath>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "support/tight_options.hpp"

namespace pneumachaos {
namespace {

// Piston held at the stop, isothermal chamber 1: it fills at constant volume V1.
Scenario blocked_isothermal(double tau_s) {
  Scenario s = simple_rig_scenario();
  s.friction.curve.coulomb_N = s.friction.curve.static_N = 1.0e5;
  s.polytropic_exponent = 1.0;
  s.supply_gauge_Pa = 0.6e6;
  if (tau_s > 0.0) {
    s.valve_opening.kind = ValveOpening::kLag;
    s.valve_opening.time_constant_s = tau_s;
  }
  return s;
}

// While choked, dP1/dt = c a(t) with c = R T S1 C Ps / V1 and a = 1 - exp(-t/tau), so
// P1 = Pa + c (t - tau (1 - exp(-t/tau))): the instant valve's ramp, delayed by tau at length.
TEST(ValveOpening, ChokedFillingFollowsTheLaggedAreaInClosedForm) {
  for (const double tau : {0.0, 0.005, 0.030}) {
    const Scenario s = blocked_isothermal(tau);
    const Plant plant(s);
    const auto r = simulate(plant, tight(0.2));
    ASSERT_TRUE(r.summary.ok()) << r.summary.message;
    const double Pa = s.ambient_pressure_Pa;
    const double Ps = s.supply_pressure_Pa();
    const double c = s.gas.R_J_per_kgK * s.temperature_K * s.circuit.S1() *
                     choked_flux_factor(s.gas, s.temperature_K) * Ps /
                     plant.geometry().volume_head_m3(0.0);
    const auto& P1 = r.series.channel("P1").values;
    std::size_t checked = 0;
    for (std::size_t i = 0; i < P1.size() && P1[i] <= s.valve.critical_ratio * Ps; ++i) {
      const double t = r.series.time_s(i);
      const double delay = tau > 0.0 ? tau * (1.0 - std::exp(-t / tau)) : 0.0;
      EXPECT_NEAR(P1[i], Pa + c * (t - delay), 1e-6 * Ps) << "tau " << tau << ", t " << t;
      ++checked;
    }
    EXPECT_GT(checked, 10u) << "tau " << tau;
    if (tau > 0.0) {
      const auto& a = r.series.channel("S1_open").values;
      for (std::size_t i = 0; i < a.size(); i += 7)
        EXPECT_NEAR(a[i], 1.0 - std::exp(-r.series.time_s(i) / tau), 1e-7);
    }
  }
}

TEST(ValveOpening, InstantByDefaultAndTheTimeConstantIsChecked) {
  for (const Scenario& s : {simple_rig_scenario(), default_scenario()}) {
    EXPECT_FALSE(s.valve_opening.lagged());
    EXPECT_FALSE(Plant(s).layout().has_valve_opening());
  }
  Scenario s = default_scenario();
  apply_setting(s, "valve.S1_opening", std::string("lag"), "");
  apply_setting(s, "valve.S1_opening_time_ms", 15.0, "");
  EXPECT_TRUE(Plant(s).layout().has_valve_opening());
  EXPECT_DOUBLE_EQ(s.valve_opening.time_constant_s, 0.015);
  try {
    apply_setting(s, "valve.S1_opening_time_ms", 0.0, "");
    ADD_FAILURE() << "a zero time constant was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("valve.S1_opening_time_ms"), std::string::npos);
  }
}

}  // namespace
}  // namespace pneumachaos
