// The chamber energy equation (docs/model.md, "Chamber temperatures") against closed-form
// answers: adiabatic compression, relaxation to the wall, the isothermal limit and the
// adiabatic filling of a rigid chamber.
#include <gtest/gtest.h>

#include <cmath>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "support/tight_options.hpp"
#include "support/stuck_samples.hpp"

namespace pneumachaos {
namespace {

Scenario energy_rig(double h_W_per_m2K) {
  Scenario s = simple_rig_scenario();
  s.thermal.chamber_model = ChamberModel::kEnergy;
  s.thermal.heat_transfer_W_per_m2K = h_W_per_m2K;
  return s;
}

// Both valves shut and no friction: two closed chambers, a gas spring.
Scenario closed_gas_spring(double h_W_per_m2K) {
  Scenario s = energy_rig(h_W_per_m2K);
  s.circuit.S1_m2 = 0.0;
  s.circuit.S2_m2 = 0.0;
  s.friction.kind = FrictionKind::kClassic;
  s.friction.curve.coulomb_N = s.friction.curve.static_N = s.friction.curve.viscous_Ns_per_m = 0.0;
  return s;
}

SimulationResult run_gas_spring(const Plant& plant, double duration) {
  std::vector<double> x0 = plant.initial_state();
  x0[plant.layout().x] = 0.2;
  x0[plant.layout().P1] = 3.0e5;
  x0[plant.layout().P2] = 1.5e5;
  return simulate_from(plant, x0, tight(duration));
}

// Largest |P V^n / (P V^n)_0 - 1| of chamber 2 over the record.
double rod_side_drift(const Plant& plant, const SimulationResult& r, double n) {
  const auto& x = r.series.channel("x").values;
  const auto& P2 = r.series.channel("P2").values;
  const auto& geo = plant.geometry();
  const double c = P2[0] * std::pow(geo.volume_rod_m3(x[0]), n);
  double worst = 0.0;
  for (std::size_t i = 0; i < x.size(); ++i)
    worst = std::max(worst, std::abs(P2[i] * std::pow(geo.volume_rod_m3(x[i]), n) / c - 1.0));
  return worst;
}

TEST(ChamberEnergy, ClosedAdiabaticChamberKeepsPVkappaAndTVkappaMinusOne) {
  const Scenario s = closed_gas_spring(0.0);
  const Plant plant(s);
  const auto r = run_gas_spring(plant, 1.0);
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  const double kappa = s.gas.heat_capacity_ratio;
  const auto& x = r.series.channel("x").values;
  const auto& P1 = r.series.channel("P1").values;
  const auto& T1 = r.series.channel("T1").values;
  const auto& geo = plant.geometry();
  const double c = P1[0] * std::pow(geo.volume_head_m3(x[0]), kappa);
  const double d = T1[0] * std::pow(geo.volume_head_m3(x[0]), kappa - 1.0);
  double x_min = x[0], x_max = x[0];
  for (std::size_t i = 0; i < x.size(); ++i) {
    // Relative drift bounded by the integration tolerance times the number of steps.
    EXPECT_NEAR(P1[i] * std::pow(geo.volume_head_m3(x[i]), kappa) / c, 1.0, 1e-7);
    EXPECT_NEAR(T1[i] * std::pow(geo.volume_head_m3(x[i]), kappa - 1.0) / d, 1.0, 1e-7);
    x_min = std::min(x_min, x[i]);
    x_max = std::max(x_max, x[i]);
  }
  EXPECT_GT(x_max - x_min, 0.01);  // the piston really moved
  EXPECT_LT(rod_side_drift(plant, r, kappa), 1e-7);
}

TEST(ChamberEnergy, ClosedChamberRelaxesToTheWallWithTimeConstantMcvOverHA) {
  Scenario s = closed_gas_spring(20.0);
  s.thermal.wall_temperature_K = 313.15;  // a wall 20 K warmer than the air
  const Plant plant(s);
  // Chamber 2 at supply pressure holds the piston at the stop: both volumes stay fixed.
  const auto r = simulate(plant, tight(1.0));
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  const auto& geo = plant.geometry();
  const double V1 = geo.volume_head_m3(0.0);
  const double R = s.gas.R_J_per_kgK;
  const double cv = R / (s.gas.heat_capacity_ratio - 1.0);
  const double mass = s.ambient_pressure_Pa * V1 / (R * s.temperature_K);
  const double tau = mass * cv / (20.0 * geo.wall_area_head_m2(V1));
  ASSERT_GT(tau, 0.05);  // the 1 s record spans several time constants
  ASSERT_LT(tau, 0.5);
  const auto& T1 = r.series.channel("T1").values;
  const auto& x = r.series.channel("x").values;
  const double Tw = s.thermal.wall_temperature_K;
  for (std::size_t i = 0; i < T1.size(); i += 10) {
    const double t = r.series.time_s(i);
    const double expected = Tw - (Tw - s.temperature_K) * std::exp(-t / tau);
    EXPECT_NEAR(T1[i], expected, 1e-6);  // K; the tolerance of a 1e-10 relative integration
    EXPECT_EQ(x[i], 0.0);
  }
}

TEST(ChamberEnergy, LargeHeatTransferGivesTheIsothermalGasSpring) {
  // tau = m cv / (h A) ~ 2e-5 s at h = 1e6, far below the ~10 Hz spring's period: the
  // chamber follows the wall, P V = const to about (kappa - 1) omega tau ~ 1e-4.
  const Plant isothermal(closed_gas_spring(1.0e6));
  const auto r = run_gas_spring(isothermal, 0.5);
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  constexpr double kIsothermalTolerance = 2e-3;
  EXPECT_LT(rod_side_drift(isothermal, r, 1.0), kIsothermalTolerance);
  // The same spring without heat transfer is far from isothermal: the check can fail.
  const Plant adiabatic(closed_gas_spring(0.0));
  const auto a = run_gas_spring(adiabatic, 0.5);
  EXPECT_GT(rod_side_drift(adiabatic, a, 1.0), 10.0 * kIsothermalTolerance);
}

TEST(ChamberEnergy, AdiabaticFillingOfARigidChamberMatchesTheFirstLaw) {
  // Charging a rigid, insulated vessel from a reservoir at Ts: U - U0 = cp Ts (m - m0), so
  // m = m0 + V (P - P0) / (kappa R Ts) and T = P V / (R m); from vacuum T -> kappa Ts.
  Scenario s = energy_rig(0.0);
  s.circuit.S2_m2 = 0.0;
  s.friction.kind = FrictionKind::kClassic;
  s.friction.curve.coulomb_N = s.friction.curve.static_N =
      1.0e5;  // the piston never leaves the stop
  const Plant plant(s);
  const auto r = simulate(plant, tight(1.0));
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  const double V = plant.geometry().volume_head_m3(0.0);
  const double R = s.gas.R_J_per_kgK;
  const double kappa = s.gas.heat_capacity_ratio;
  const double Ts = s.temperature_K;
  const double P0 = s.ambient_pressure_Pa;
  const double m0 = P0 * V / (R * Ts);
  const auto& P1 = r.series.channel("P1").values;
  const auto& T1 = r.series.channel("T1").values;
  for (std::size_t i = 0; i < P1.size(); i += 10) {
    const double m = m0 + V * (P1[i] - P0) / (kappa * R * Ts);
    EXPECT_NEAR(T1[i] / (P1[i] * V / (R * m)), 1.0, 1e-7);
  }
  EXPECT_GT(P1.back(), 0.95 * s.supply_pressure_Pa());  // filled
  EXPECT_GT(T1.back(), Ts + 60.0);  // 3.5 bar from 1 bar: about 1.26 Ts
}

TEST(ChamberEnergy, StictionStillHoldsTheVelocityAtExactlyZero) {
  Scenario s = energy_rig(20.0);
  s.circuit.S2_m2 = 0.05e-6;  // small exhaust: stick-slip on the simple rig
  const Plant plant(s);
  const auto r = simulate(plant, s.run);
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  EXPECT_GE(r.summary.events.stick, 3u);
  const auto& T2 = r.series.channel("T2").values;
  double largest_T2_change = 0.0;
  const std::size_t stuck_samples = for_each_stuck_sample(r.series, [&](std::size_t i) {
    largest_T2_change = std::max(largest_T2_change, std::abs(T2[i] - T2[i - 1]));
  });
  EXPECT_GT(stuck_samples, 100u);
  EXPECT_GT(largest_T2_change, 1e-4);  // K per ms: the exhausting chamber cools while stuck
}

TEST(ChamberEnergy, NegativeHeatTransferIsRefusedNamingTheKey) {
  Scenario s;
  try {
    apply_setting(s, "thermal.heat_transfer_W_per_m2K", -1.0, "");
    FAIL() << "accepted a negative heat-transfer coefficient";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("thermal.heat_transfer_W_per_m2K"), std::string::npos);
  }
}

TEST(ChamberEnergy, OffByDefault) {
  const Plant plant(default_scenario());
  EXPECT_FALSE(plant.layout().has_temperatures());
}

}  // namespace
}  // namespace pneumachaos
