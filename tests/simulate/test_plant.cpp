// The cylinder model against conservation laws and closed-form answers, on the simple rig
// (one rigid mass, Stribeck seal, volumes following the piston).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "pneumachaos/model/variation.hpp"
#include "support/variant_scenarios.hpp"
#include "support/stuck_samples.hpp"
#include "support/tight_options.hpp"

namespace pneumachaos {
namespace {

Scenario frictionless_closed(double k) {
  Scenario s = simple_rig_scenario();
  s.circuit.S1_m2 = 0.0;  // both valves shut: two closed chambers, a gas spring
  s.circuit.S2_m2 = 0.0;
  s.friction.kind = FrictionKind::kClassic;
  s.friction.curve.coulomb_N = s.friction.curve.static_N = s.friction.curve.viscous_Ns_per_m = 0.0;
  s.polytropic_exponent = k;
  return s;
}

class ClosedChamberTest : public ::testing::TestWithParam<double> {};

TEST_P(ClosedChamberTest, KeepsPVkConstant) {
  const double k = GetParam();
  const Plant plant(frictionless_closed(k));
  const auto& geo = plant.geometry();
  std::vector<double> x0 = plant.initial_state();
  x0[plant.layout().x] = 0.2;
  x0[plant.layout().P1] = 3.0e5;
  x0[plant.layout().P2] = 1.5e5;
  const auto r = simulate_from(plant, x0, tight(1.0));
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  const auto& x = r.series.channel("x").values;
  const auto& P1 = r.series.channel("P1").values;
  const auto& P2 = r.series.channel("P2").values;
  const double c1 = P1[0] * std::pow(geo.volume_head_m3(x[0]), k);
  const double c2 = P2[0] * std::pow(geo.volume_rod_m3(x[0]), k);
  double x_min = x[0], x_max = x[0];
  for (std::size_t i = 0; i < x.size(); ++i) {
    // Relative drift bounded by the integration tolerance times the number of steps.
    EXPECT_NEAR(P1[i] * std::pow(geo.volume_head_m3(x[i]), k) / c1, 1.0, 1e-7);
    EXPECT_NEAR(P2[i] * std::pow(geo.volume_rod_m3(x[i]), k) / c2, 1.0, 1e-7);
    x_min = std::min(x_min, x[i]);
    x_max = std::max(x_max, x[i]);
  }
  EXPECT_GT(x_max - x_min, 0.01);            // the piston really moved
  EXPECT_GE(r.summary.events.reversal, 2u);  // and turned round (zero-friction reversal)
}

INSTANTIATE_TEST_SUITE_P(AdiabaticAndIsothermal, ClosedChamberTest, ::testing::Values(1.4, 1.0));

TEST(Plant, AdiabaticGasSpringConservesEnergy) {
  // E = m v^2/2 + (P1 V1 + P2 V2)/(k-1) + Pa (A1 - A2) x is a first integral when both valves
  // are shut and friction is zero (work of the gas on the piston against the atmosphere).
  const Scenario s = frictionless_closed(1.4);
  const Plant plant(s);
  std::vector<double> x0 = plant.initial_state();
  x0[plant.layout().x] = 0.2;
  x0[plant.layout().P1] = 3.0e5;
  x0[plant.layout().P2] = 1.5e5;
  const auto r = simulate_from(plant, x0, tight(1.0));
  const auto energy = [&](std::size_t i) {
    const double x = r.series.channel("x").values[i];
    const double v = r.series.channel("v").values[i];
    return 0.5 * s.load.mass_kg * v * v +
           (r.series.channel("P1").values[i] * s.cylinder.volume_head_m3(x) +
            r.series.channel("P2").values[i] * s.cylinder.volume_rod_m3(x)) /
               0.4 +
           s.ambient_pressure_Pa * (plant.A1() - plant.A2()) * x;
  };
  const double e0 = energy(0);
  for (std::size_t i = 0; i < r.series.size(); i += 10) EXPECT_NEAR(energy(i) / e0, 1.0, 1e-8);
}

TEST(Plant, SteadyMeterOutSpeedMatchesChokedFlowBalance) {
  // Choked exhaust, isothermal exhaust temperature: W2 = S2 C P2 and W2 = P2 A2 v/(R T) give
  // v = S2 C R T / A2 independent of P2 (C = choked_flux_factor; about 199 m/s * S2/A2).
  Scenario s = simple_rig_scenario();
  s.friction.kind = FrictionKind::kClassic;
  const Plant plant(s);
  const double v_expected = s.circuit.S2() * choked_flux_factor(s.gas, s.temperature_K) *
                            s.gas.R_J_per_kgK * s.temperature_K / plant.A2();
  EXPECT_NEAR(v_expected, 198.6 * s.circuit.S2() / plant.A2(), 1e-3 * v_expected);
  const auto r = simulate(plant, tight(4.0));
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  const std::size_t i = r.series.size() - 1;
  const double v = r.series.channel("v").values[i];
  const double P1 = r.series.channel("P1").values[i];
  const double P2 = r.series.channel("P2").values[i];
  ASSERT_GT(P2 * s.valve.critical_ratio, s.ambient_pressure_Pa);  // exhaust is choked
  // Settled to far better than 1 %; 1e-4 leaves room for the last decay.
  EXPECT_NEAR(v / v_expected, 1.0, 1e-4);
  const double Pa = s.ambient_pressure_Pa;
  const double friction = s.friction.curve.coulomb_N + s.friction.curve.viscous_Ns_per_m * v;
  EXPECT_NEAR(plant.A1() * (P1 - Pa) - plant.A2() * (P2 - Pa), friction, 1e-3);
}

TEST(Plant, TrueStictionHoldsPositionWhilePressuresEvolve) {
  Scenario s = simple_rig_scenario();
  s.circuit.S2_m2 = 0.05e-6;  // small exhaust: stick-slip
  const Plant plant(s);
  const auto r = simulate(plant, s.run);
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  EXPECT_GE(r.summary.events.stick, 3u);
  EXPECT_GE(r.summary.events.slip, 3u);
  const auto& P2 = r.series.channel("P2").values;
  const auto& F = r.series.channel("F_friction").values;
  double largest_P2_change = 0.0;
  const std::size_t stuck_samples = for_each_stuck_sample(r.series, [&](std::size_t i) {
    EXPECT_LE(std::abs(F[i]), s.friction.curve.static_N + 1e-9);
    largest_P2_change = std::max(largest_P2_change, std::abs(P2[i] - P2[i - 1]));
  });
  EXPECT_GT(stuck_samples, 100u);
  EXPECT_GT(largest_P2_change, 1.0);  // Pa per millisecond: the chamber keeps exhausting
}

TEST(Plant, BreaksAwayFromTheStopWhenDriveExceedsStaticFriction) {
  const Scenario s = simple_rig_scenario();
  const Plant plant(s);
  const auto r = simulate(plant, s.run);
  ASSERT_FALSE(r.summary.event_log.empty());
  EXPECT_EQ(r.summary.event_log.front().kind, EventKind::kStopRelease);
  const double t_release = r.summary.event_log.front().t_s;
  const std::size_t k = static_cast<std::size_t>(std::floor(t_release * 1000.0));
  const double Pa = s.ambient_pressure_Pa;
  const double drive = plant.A1() * (r.series.channel("P1").values[k] - Pa) -
                       plant.A2() * (r.series.channel("P2").values[k] - Pa);
  EXPECT_LE(drive, s.friction.curve.static_N);  // the last sample before release is still held
  for (std::size_t i = 0; i <= k; ++i) EXPECT_EQ(r.series.channel("x").values[i], 0.0);
}

TEST(Plant, RunEndsAtTheEndOfStroke) {
  Scenario s = simple_rig_scenario();
  s.cylinder.stroke_m = 0.1;
  const Plant plant(s);
  const auto r = simulate(plant, s.run);
  EXPECT_EQ(r.summary.termination, Termination::kTerminalEvent);
  for (double x : r.series.channel("x").values) EXPECT_LE(x, 0.1);
  EXPECT_LT(r.summary.t_final_s, s.run.duration_s);
}

TEST(Plant, LuGreGivesTheSameSteadySpeedWithEitherStepper) {
  Scenario s = simple_rig_scenario();
  s.friction.kind = FrictionKind::kLuGre;
  s.run.duration_s = 3.0;
  const Plant plant(s);
  auto o = s.run;
  const auto a = simulate(plant, o);
  o.stepper = StepperKind::kRosenbrock4;
  const auto b = simulate(plant, o);
  ASSERT_TRUE(a.summary.ok() && b.summary.ok());
  ASSERT_EQ(a.series.size(), b.series.size());
  const auto& va = a.series.channel("v").values;
  const auto& vb = b.series.channel("v").values;
  for (std::size_t i = 0; i < va.size(); ++i) EXPECT_NEAR(va[i], vb[i], 1e-6);
}

// The compliant-mount rig's guide (scenarios/variants/compliant_mount.toml) has a Stribeck exponent of 0.5, whose slope is infinite at rest: the Jacobian
// there takes the columns of difference quotients (docs/model.md, "Friction"), finite, and
// the stiff stepper runs that rig from rest (a NaN Jacobian would make Rosenbrock 4 fail at
// t = 0 with "step size underflow").
TEST(Plant, JacobianIsFiniteAtRestWhereTheStribeckSlopeIsInfinite) {
  const Scenario s = compliant_mount();
  ASSERT_EQ(s.load.guide_friction.curve.stribeck_exponent, 0.5);
  const Plant plant(s);
  const std::vector<double> x = plant.initial_state();
  ASSERT_EQ(x[plant.layout().load_v], 0.0);
  const std::size_t n = x.size();
  std::vector<double> J(n * n), dfdt(n);
  ASSERT_TRUE(plant.jacobian(plant.initial_mode(x, 0.0), x, 0.0, J, dfdt));
  for (std::size_t k = 0; k < n * n; ++k) EXPECT_TRUE(std::isfinite(J[k])) << "entry " << k;
}

TEST(Plant, StiffStepperRunsTheDefaultRigWithinTheTolerancesError) {
  Scenario s = default_scenario();
  s.run.duration_s = 0.5;
  const Plant plant(s);
  auto o = s.run;
  o.stepper = StepperKind::kRosenbrock4;
  const auto stiff = simulate(plant, o);
  ASSERT_TRUE(stiff.summary.ok()) << stiff.summary.message;
  const auto reference = simulate(plant, tight(0.5));
  ASSERT_TRUE(reference.summary.ok());
  // dopri5 at the default tolerances is 2e-6 m/s off the reference by 0.5 s here, Rosenbrock 4
  // 7e-7 (docs/notes/performance.md, "The simulation's floor"); 1e-5 m/s is a tenth of a
  // transducer's resolution and far below the chaotic motion's 0.1 m/s.
  EXPECT_LT(largest_velocity_difference(stiff, reference), 1e-5);
}

// LuGre's quasi-static limit (docs/model.md, "Friction") against the full bristle equation
// integrated at tight tolerances. Its first neglected term is the bristle's lag behind its
// steady state, z - z0 ~ -(dz0/dt) / rate, a force error (sigma1 - g/|v|) dz0/dt that
// vanishes in steady sliding. Asked of it: a velocity error below what the default relative
// tolerance admits in one step at this speed, 1e-7 x 0.8 m/s (the full equation at the
// default tolerances is 1e-8 m/s off the same reference here; docs/notes/performance.md).
Scenario without_quasi_static(Scenario s) {
  s.friction.lugre.quasi_static_rate_per_s = 0.0;
  s.load.guide_friction.lugre.quasi_static_rate_per_s = 0.0;
  return s;
}

// The frozen LuGre rig (tests/support/variant_scenarios.hpp) at S2 for `seconds`: the full bristle equation
// at tight tolerances (the reference) and at the default ones, and the rig as it is
// (quasi-static limit on).
struct QuasiStaticRuns {
  SimulationResult full, full_default, limit;
};
QuasiStaticRuns quasi_static_runs(double S2_mm2, double seconds) {
  Scenario s = frozen_light_piston();
  s.circuit.S2_m2 = S2_mm2 * 1e-6;
  s.run.duration_s = seconds;
  return {simulate(Plant(without_quasi_static(s)), tight(seconds)),
          simulate(Plant(without_quasi_static(s)), s.run), simulate(Plant(s), s.run)};
}

TEST(Plant, LuGreQuasiStaticLimitMatchesTheBristleEquationWhileSlidingFast) {
  for (const double S2_mm2 : {2.0, 4.4}) {  // the map's sliding points: ~0.5-0.8 m/s
    const auto [full, full_default, limit] = quasi_static_runs(S2_mm2, 2.0);
    ASSERT_TRUE(full.summary.ok() && full_default.summary.ok() && limit.summary.ok());
    EXPECT_LT(largest_velocity_difference(limit, full), 1e-7 * 0.8) << "S2 " << S2_mm2;
    // The limit was used: the bristles do not bound the step.
    EXPECT_LT(2 * limit.summary.rhs_evaluations, full_default.summary.rhs_evaluations)
        << "S2 " << S2_mm2;
  }
}

TEST(Plant, LuGreQuasiStaticLimitKeepsTheChaoticAndStickSlipRuns) {
  // Chaos amplifies any difference (~e^4 in 1 s), so the limit is asked to stay within twice
  // the default tolerances' own error against the reference over 1 s.
  for (const double S2_mm2 : {0.35, 0.05}) {  // the default (chaotic) point and stick-slip
    const auto [full, full_default, limit] = quasi_static_runs(S2_mm2, 1.0);
    ASSERT_TRUE(full.summary.ok() && full_default.summary.ok() && limit.summary.ok());
    EXPECT_LE(largest_velocity_difference(limit, full),
              2.0 * largest_velocity_difference(full_default, full))
        << "S2 = " << S2_mm2 << " mm^2";
  }
}

TEST(Plant, StiffSpringCouplingMovesLikeOneRigidMass) {
  // A very stiff, damped coupling with a frictionless guide must reproduce the rigid model's
  // steady speed: the load and the piston then share the choked meter-out velocity.
  Scenario s = simple_rig_scenario();
  s.friction.kind = FrictionKind::kClassic;
  s.load.coupling = LoadCoupling::kSpring;
  s.load.piston_mass_kg = 0.5;
  s.load.mass_kg = 1.0;
  s.load.coupling_stiffness_N_per_m = 1e6;
  s.load.coupling_damping_Ns_per_m = 2000.0;
  s.load.guide_friction.kind = FrictionKind::kClassic;
  s.load.guide_friction.curve.coulomb_N = s.load.guide_friction.curve.static_N = 0.0;
  s.load.guide_friction.curve.viscous_Ns_per_m = 0.0;
  const Plant plant(s);
  const auto r = simulate(plant, tight(3.0));
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  const double v_expected = s.circuit.S2() * choked_flux_factor(s.gas, s.temperature_K) *
                            s.gas.R_J_per_kgK * s.temperature_K / plant.A2();
  EXPECT_NEAR(r.series.channel("v_load").values.back() / v_expected, 1.0, 1e-4);
  EXPECT_NEAR(r.series.channel("v").values.back() / v_expected, 1.0, 1e-4);
}

// The full-state Jacobian the stiff stepper uses, against central differences of the
// plant's own derivative, in a sliding mode and, for true stiction, the stuck mode (whose
// x and v rows must be exactly zero: v held at 0, x frozen).
void expect_jacobian_matches_differences(const Plant& plant, const Mode& mode,
                                         const std::vector<double>& x) {
  const std::size_t n = x.size();
  std::vector<double> J(n * n), dfdt(n);
  ASSERT_TRUE(plant.jacobian(mode, x, 0.0, J, dfdt));
  for (std::size_t j = 0; j < n; ++j) {
    // Step ~ cube root of epsilon relative to the state's magnitude (pressures ~1e5 Pa).
    const double h = 6e-6 * std::max(std::abs(x[j]), 1e-3);
    std::vector<double> xp = x, xm = x, fp(n), fm(n);
    xp[j] += h;
    xm[j] -= h;
    plant.derivative(mode, xp, fp, 0.0);
    plant.derivative(mode, xm, fm, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      double scale = 1e-12;
      for (std::size_t k = 0; k < n; ++k) scale = std::max(scale, std::abs(J[i * n + k]));
      // Relative to the row's largest entry: truncation and rounding of the differences.
      EXPECT_NEAR(J[i * n + j] / scale, (fp[i] - fm[i]) / (2.0 * h) / scale, 1e-6)
          << "row " << i << " column " << j;
    }
  }
  for (double d : dfdt) EXPECT_EQ(d, 0.0);  // the plant is autonomous
}

// A one-body plant's state sliding forward at mid-stroke: x 0.2 m, v 0.05 m/s, P1 0.3 MPa and
// P2 0.2 MPa absolute, the rest at their start values.
std::vector<double> sliding_state(const Plant& plant) {
  std::vector<double> x = plant.initial_state();
  const StateLayout& L = plant.layout();
  x[L.x] = 0.2;
  x[L.v] = 0.05;
  x[L.P1] = 3.0e5;
  x[L.P2] = 2.0e5;
  return x;
}

TEST(Plant, ExactJacobianMatchesDifferencesOnTheSimpleRig) {
  Scenario s = simple_rig_scenario();
  s.friction.pressure_gain.coulomb_N_per_Pa =
      8e-6;  // pressure dependence couples friction to P1, P2
  s.friction.pressure_gain.static_N_per_Pa = 12e-6;
  const Plant simple(s);
  std::vector<double> x = sliding_state(simple);
  const StateLayout& L = simple.layout();
  expect_jacobian_matches_differences(simple, simple.sliding_mode(+1), x);
  x[L.v] = 0.0;
  Mode stuck;
  stuck.value[0] = static_cast<std::int8_t>(ContactMode::kStuck);
  expect_jacobian_matches_differences(simple, stuck, x);
  std::vector<double> J(L.size * L.size), dfdt(L.size);
  simple.jacobian(stuck, x, 0.0, J, dfdt);
  for (std::size_t j = 0; j < L.size; ++j) {
    EXPECT_EQ(J[L.x * L.size + j], 0.0);
    EXPECT_EQ(J[L.v * L.size + j], 0.0);
  }
}

// With the seal's random level field, the Jacobian takes the table's slope at the position:
// the derivative of the level the integrator reads (the field varies over millimetres, so a
// Jacobian that missed it would be wrong in the x column by the field's slope times Fc). A
// 20 mm correlation keeps the field smooth at the differences' step (its shortest wavelength,
// 8 mm, against a 1.2 um step), so the differences are accurate to the comparison's 1e-6.
TEST(Plant, ExactJacobianMatchesDifferencesWithTheRandomSealLevel) {
  Scenario s = simple_rig_scenario();
  s.variation.seal_noise_rel = 0.1;
  s.variation.seal_noise_correlation_m = 0.02;
  const Plant plant(vary(s, run_seed(5, 0, 0)));
  ASSERT_NE(plant.seal_friction().params().level_table, nullptr);
  expect_jacobian_matches_differences(plant, plant.sliding_mode(+1), sliding_state(plant));
}

TEST(Plant, ExactJacobianMatchesDifferencesOnTheTwoMassRig) {
  const Plant rig(frozen_light_piston());  // LuGre on both contacts, spring-coupled load
  std::vector<double> y = rig.initial_state();
  const StateLayout& R = rig.layout();
  y[R.x] = 0.42;
  y[R.v] = 0.06;
  y[R.P1] = 3.2e5;
  y[R.P2] = 2.6e5;
  y[R.seal_z] = 2e-4;
  y[R.load_x] = 0.419;
  y[R.load_v] = 0.05;
  y[R.guide_z] = 5e-5;
  expect_jacobian_matches_differences(rig, rig.sliding_mode(+1), y);
  // Both contacts fast, in LuGre's quasi-static limit (the bristle held on its steady state).
  y[R.v] = 0.8;
  y[R.load_v] = 0.78;
  Mode quasi;
  quasi.value[0] = quasi.value[1] = static_cast<std::int8_t>(ContactMode::kQuasiPos);
  expect_jacobian_matches_differences(rig, quasi, y);
}

// The two-state memory (memory = rate_state) on the simple rig: both states off their steady
// values, with a direct effect and pressure gains.
TEST(Plant, ExactJacobianMatchesDifferencesWithTheTwoStateMemory) {
  Scenario s = simple_rig_scenario();
  s.friction.memory = FrictionMemory::kRateState;
  s.friction.rate_state.direct_N = 2.0;
  s.friction.pressure_gain = {.coulomb_N_per_Pa = 8e-6, .static_N_per_Pa = 12e-6};
  const Plant plant(s);
  std::vector<double> x = plant.initial_state();
  const StateLayout& L = plant.layout();
  ASSERT_EQ(L.seal_z_count, 2u);
  x[L.x] = 0.2;
  x[L.v] = 0.012;
  x[L.P1] = 3.0e5;
  x[L.P2] = 2.0e5;
  x[L.seal_z] = 0.6;
  x[L.seal_z + 1] = 0.8;
  expect_jacobian_matches_differences(plant, plant.sliding_mode(+1), x);
}

TEST(Plant, ExactJacobianMatchesDifferencesWithAGmsSeal) {
  // Generalized Maxwell-slip seal: elements below, on the way to and past their slip
  // deflections (about 0.1, 0.2, 0.3, 0.4 mm at this speed), away from the weight's kinks.
  // The two-mass LuGre rig with the GMS model's own defaults (1e5 N/m in all).
  Scenario g = frozen_light_piston();
  g.friction.kind = FrictionKind::kGms;
  const Plant gms(g);
  std::vector<double> u = gms.initial_state();
  const StateLayout& G = gms.layout();
  ASSERT_EQ(G.seal_z_count, 4u);
  u[G.x] = 0.42;
  u[G.v] = 0.06;
  u[G.P1] = 3.2e5;
  u[G.P2] = 2.6e5;
  const double z_gms[] = {3e-5, 1e-4, 2e-4, 5e-4};
  for (std::size_t i = 0; i < 4; ++i) u[G.seal_z + i] = z_gms[i];
  u[G.load_x] = 0.419;
  u[G.load_v] = 0.05;
  u[G.guide_z] = 5e-5;
  expect_jacobian_matches_differences(gms, gms.sliding_mode(+1), u);
}

TEST(Plant, ExactJacobianMatchesDifferencesWithTheSupplyLine) {
  // The supply line's P0 couples into P1 through S1 (forward and back-flow) and is fed by
  // the regulator; with the energy equation the back-flow carries T1; S1's opening fraction
  // scales its flow.
  for (const ChamberModel chambers : {ChamberModel::kPolytropic, ChamberModel::kEnergy}) {
    Scenario l = simple_rig_scenario();
    l.supply_line.volume_m3 = 40e-6;
    l.supply_line.regulator_S_m2 = 5e-6;
    l.thermal.chamber_model = chambers;
    if (chambers == ChamberModel::kEnergy) l.valve_opening.kind = ValveOpening::kLag;
    const Plant line(l);
    std::vector<double> w = line.initial_state();
    const StateLayout& W = line.layout();
    w[W.x] = 0.2;
    w[W.v] = 0.05;
    w[W.P2] = 2.0e5;
    for (const double P1 : {2.8e5, 3.2e5}) {  // below and above P0: S1 flows either way
      w[W.P1] = P1;
      w[W.P0] = 3.0e5;
      if (W.has_valve_opening()) w[W.S1_open] = 0.4;  // S1 still opening
      expect_jacobian_matches_differences(line, line.sliding_mode(+1), w);
    }
  }
}

}  // namespace
}  // namespace pneumachaos
