// The supply line (docs/model.md, "Supply line") against closed-form answers: a closed line
// filled through the regulator's restriction (linear while choked, a sine arc on the ISO 6358
// ellipse after), mass conservation between the line and chamber 1 with the piston blocked,
// and the ideal supply it reduces to when off or very large.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "support/stuck_samples.hpp"
#include "support/tight_options.hpp"
#include "support/variant_scenarios.hpp"

namespace pneumachaos {
namespace {

// The simple rig with its piston held at the stop by a seal no pressure here can break.
Scenario blocked_piston_with_line(double volume_m3, double regulator_S_m2, double n) {
  Scenario s = simple_rig_scenario();
  s.friction.curve.coulomb_N = s.friction.curve.static_N = 1.0e5;
  s.supply_line.volume_m3 = volume_m3;
  s.supply_line.regulator_S_m2 = regulator_S_m2;
  s.supply_line.polytropic_exponent = n;
  return s;
}

class ClosedLineFilling : public ::testing::TestWithParam<double> {};

// S1 shut: the line alone fills from ambient. With a = n R T S0 C / V0 (C the choked flux
// factor), dP0/dt = a Ps while P0 <= b Ps (choked: linear in time); above, with
// q = (P0/Ps - b)/(1 - b), the ISO 6358 ellipse gives dq/dt = a sqrt(1 - q^2)/(1 - b), so
// q = sin(a (t - t_b)/(1 - b)), valid until the laminar branch near P0 = Ps.
TEST_P(ClosedLineFilling, RisesLinearlyWhileChokedThenAlongTheEllipse) {
  const double n = GetParam();
  Scenario s = blocked_piston_with_line(40e-6, 0.5e-6, n);
  s.circuit.S1_m2 = 0.0;
  s.supply_gauge_Pa = 0.6e6;
  const Plant plant(s);
  std::vector<double> x0 = plant.initial_state();
  const double Pa = s.ambient_pressure_Pa;
  const double Ps = s.supply_pressure_Pa();
  x0[plant.layout().P0] = Pa;
  const auto r = simulate_from(plant, x0, tight(0.6));
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;

  const double b = s.valve.critical_ratio;
  const double a = n * s.gas.R_J_per_kgK * s.temperature_K * s.supply_line.regulator_S_m2 *
                   choked_flux_factor(s.gas, s.temperature_K) / s.supply_line.volume_m3;
  const double t_b = (b * Ps - Pa) / (a * Ps);
  const auto& P0 = r.series.channel("P0").values;
  std::size_t choked = 0, elliptic = 0;
  for (std::size_t i = 0; i < P0.size(); ++i) {
    const double t = r.series.time_s(i);
    if (t <= t_b) {
      EXPECT_NEAR(P0[i], Pa + a * Ps * t, 1e-6 * Ps) << "t = " << t;
      ++choked;
      continue;
    }
    const double q = std::sin(a * (t - t_b) / (1.0 - b));
    if (Ps * (b + (1.0 - b) * q) > 0.99 * Ps) break;  // the laminar branch takes over
    EXPECT_NEAR(P0[i], Ps * (b + (1.0 - b) * q), 1e-5 * Ps) << "t = " << t;
    ++elliptic;
  }
  EXPECT_GT(choked, 20u);
  EXPECT_GT(elliptic, 20u);
  EXPECT_LE(P0.back(), Ps);
  EXPECT_GT(P0.back(), 0.99 * Ps);
}
INSTANTIATE_TEST_SUITE_P(IsothermalAndAdiabatic, ClosedLineFilling, ::testing::Values(1.0, 1.4));

// Isothermal everywhere, regulator all but shut: the line's air only moves into chamber 1, so
// P0 V0 + P1 V1 stays constant and both settle at the mixed pressure.
TEST(SupplyLine, ConservesMassWithChamberOneWhenThePistonIsBlocked) {
  Scenario s = blocked_piston_with_line(30e-6, 1e-15, 1.0);
  s.polytropic_exponent = 1.0;
  const Plant plant(s);
  const auto r = simulate(plant, tight(0.5));
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  const double V0 = s.supply_line.volume_m3;
  const double V1 = plant.geometry().volume_head_m3(0.0);
  const auto& P0 = r.series.channel("P0").values;
  const auto& P1 = r.series.channel("P1").values;
  const auto& x = r.series.channel("x").values;
  const double total = P0[0] * V0 + P1[0] * V1;
  for (std::size_t i = 0; i < P0.size(); ++i) {
    ASSERT_EQ(x[i], 0.0);
    EXPECT_NEAR((P0[i] * V0 + P1[i] * V1) / total, 1.0, 1e-8) << "sample " << i;
  }
  const double mixed = total / (V0 + V1);
  EXPECT_NEAR(P0.back(), mixed, 1e-4 * mixed);
  EXPECT_NEAR(P1.back(), mixed, 1e-4 * mixed);
  EXPECT_LT(P1.front(), 0.5 * mixed);  // it did fill: chamber 1 started at ambient
}

// The same balance in the derivative itself, at states with flow in either direction and a
// regulator that feeds: d/dt (P0 V0 + P1 V1) = R T W_regulator with the piston stuck.
TEST(SupplyLine, DerivativeMovesMassFromTheLineIntoChamberOne) {
  Scenario s = blocked_piston_with_line(25e-6, 8e-6, 1.0);
  s.polytropic_exponent = 1.0;
  const Plant plant(s);
  const StateLayout& L = plant.layout();
  const double V0 = s.supply_line.volume_m3;
  const double V1 = plant.geometry().volume_head_m3(0.0);
  const double RT = s.gas.R_J_per_kgK * s.temperature_K;
  const Orifice regulator(s.valve, s.gas, s.supply_line.regulator_S_m2, s.temperature_K);
  for (const auto& [P0, P1] : {std::pair{3.0e5, 1.2e5}, {2.2e5, 2.9e5}, {3.4e5, 3.3e5}}) {
    std::vector<double> x = plant.initial_state();
    x[L.P0] = P0;
    x[L.P1] = P1;
    std::vector<double> dx(L.size);
    plant.derivative(plant.initial_mode(x, 0.0), x, dx, 0.0);
    const double W_reg = regulator.mass_flow(s.supply_pressure_Pa(), P0);
    EXPECT_NEAR((dx[L.P0] * V0 + dx[L.P1] * V1) / RT, W_reg, 1e-12 * std::abs(W_reg));
    EXPECT_EQ(dx[L.P0] * V0 < RT * W_reg, P0 > P1) << "the line feeds chamber 1 iff P0 > P1";
  }
}

// The line's pressure keeps evolving while the seal holds the piston: the stiction events
// are located as without the line, v stays exactly 0 and x frozen on every held sample.
TEST(SupplyLine, StictionStillHoldsTheVelocityAtExactlyZero) {
  Scenario s = simple_rig_scenario();
  s.circuit.S2_m2 = 0.05e-6;  // small exhaust: stick-slip on the simple rig
  s.supply_line.volume_m3 = 50e-6;
  s.supply_line.regulator_S_m2 = 2e-6;
  s.valve_opening.kind = ValveOpening::kLag;
  const Plant plant(s);
  const auto r = simulate(plant, s.run);
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  EXPECT_GE(r.summary.events.stick, 3u);
  EXPECT_GE(r.summary.events.slip, 3u);
  const auto& P0 = r.series.channel("P0").values;
  double largest_P0_change = 0.0;
  const std::size_t stuck_samples = for_each_stuck_sample(r.series, [&](std::size_t i) {
    largest_P0_change = std::max(largest_P0_change, std::abs(P0[i] - P0[i - 1]));
  });
  EXPECT_GT(stuck_samples, 100u);
  EXPECT_GT(largest_P0_change, 1.0);  // Pa per ms: the line refills while the piston is held
}

// The simple rig and the compliant-mount rig have the paper's ideal supply; the built-in rig
// carries the calibrated line (scenarios/calibrations/paper.toml), its pressure P0 a state.
TEST(SupplyLine, OffByDefaultAddsNoState) {
  for (const Scenario& s : {simple_rig_scenario(), compliant_mount()}) {
    EXPECT_FALSE(s.supply_line.enabled());
    const Plant plant(s);
    EXPECT_FALSE(plant.layout().has_supply_line());
    for (const auto& e : plant.layout().entries) EXPECT_NE(e.name, "P0");
  }
  const Scenario rig = default_scenario();
  EXPECT_TRUE(rig.supply_line.enabled());
  const Plant plant(rig);
  EXPECT_TRUE(plant.layout().has_supply_line());
  EXPECT_EQ(std::count_if(plant.layout().entries.begin(), plant.layout().entries.end(),
                          [](const auto& e) { return e.name == "P0"; }),
            1);
}

// A line far larger than the chambers, fed through a wide regulator, is the ideal supply.
TEST(SupplyLine, AVeryLargeLineBehavesAsTheIdealSupply) {
  Scenario ideal = simple_rig_scenario();
  ideal.run.duration_s = 2.0;
  Scenario line = ideal;
  line.supply_line.volume_m3 = 1.0;  // a cubic metre: 50000 times chamber 1's dead volume
  line.supply_line.regulator_S_m2 = 1e-3;
  const auto a = simulate(Plant(ideal), ideal.run);
  const auto b = simulate(Plant(line), line.run);
  ASSERT_TRUE(a.summary.ok() && b.summary.ok());
  const auto& xa = a.series.channel("x").values;
  const auto& xb = b.series.channel("x").values;
  ASSERT_EQ(xa.size(), xb.size());
  EXPECT_GT(xa.back(), 0.05);  // the piston did travel
  for (std::size_t i = 0; i < xa.size(); i += 50) EXPECT_NEAR(xb[i], xa[i], 1e-5) << i;
  const auto& P0 = b.series.channel("P0").values;
  for (double p : P0) EXPECT_NEAR(p, line.supply_pressure_Pa(), 10.0);
}

TEST(SupplyLine, KeysCheckTheirRangesAndName) {
  Scenario s = default_scenario();
  apply_setting(s, "supply_line.volume_cm3", 50.0, "");
  apply_setting(s, "supply_line.regulator_S_mm2", 5.0, "");
  EXPECT_DOUBLE_EQ(s.supply_line.volume_m3, 50e-6);
  EXPECT_DOUBLE_EQ(s.supply_line.regulator_S_m2, 5e-6);
  const auto fails_naming = [&](const std::string& key, double v) {
    Scenario t = default_scenario();
    try {
      apply_setting(t, key, v, "");
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
      return;
    }
    ADD_FAILURE() << key << " = " << v << " accepted";
  };
  fails_naming("supply_line.volume_cm3", -1.0);
  fails_naming("supply_line.regulator_S_mm2", 0.0);
  fails_naming("supply_line.polytropic_exponent", 0.9);
  Scenario coded = default_scenario();
  coded.supply_line.volume_m3 = 1e-5;
  coded.supply_line.regulator_S_m2 = 0.0;
  EXPECT_THROW(coded.validate(), Error);
}

}  // namespace
}  // namespace pneumachaos
