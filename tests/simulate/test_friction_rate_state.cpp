// The two-state memory (stribeck with memory = rate_state, docs/model.md "Friction") against
// known answers: its steady curve is the Stribeck curve plus the direct effect, each state
// relaxes exponentially in the slip (not in time) over its own length, a velocity step gives
// the direct effect's jump and then the states' decay, and stiction holds the states still.
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/friction.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "support/stuck_samples.hpp"

namespace pneumachaos {
namespace {

constexpr double kL1 = 20e-6;
constexpr double kL2 = 200e-6;
constexpr double kShare = 0.3;
constexpr double kDirect = 2.0;
constexpr double kDirectVelocity = 1e-3;

FrictionParams rate_state_params() {
  FrictionParams p;
  p.kind = FrictionKind::kStribeck;
  p.memory = FrictionMemory::kRateState;
  p.curve = {.coulomb_N = 20.0,
             .static_N = 40.0,
             .viscous_Ns_per_m = 30.0,
             .stribeck_velocity_m_per_s = 0.01,
             .stribeck_exponent = 2.0};
  p.rate_state = {.slip_length_m = kL1,
                  .slip_length2_m = kL2,
                  .share = kShare,
                  .direct_N = kDirect,
                  .direct_velocity_m_per_s = kDirectVelocity};
  return p;
}

struct ForceAndRates {
  double force_N;
  std::array<double, 2> dtheta;
};

ForceAndRates evaluate(const FrictionModel& f, double v, const std::array<double, 2>& theta) {
  std::array<double, 2> dz{};
  const double F = f.force_N({v, 0.0, 0.0}, +1, theta, dz);
  return {F, dz};
}

// Classical fourth-order Runge-Kutta for both states at a constant velocity v.
std::array<double, 2> rk4_step(const FrictionModel& f, double v, std::array<double, 2> th,
                               double h) {
  const auto rates = [&](const std::array<double, 2>& t) { return evaluate(f, v, t).dtheta; };
  const auto add = [](std::array<double, 2> a, const std::array<double, 2>& b, double c) {
    a[0] += c * b[0];
    a[1] += c * b[1];
    return a;
  };
  const auto k1 = rates(th);
  const auto k2 = rates(add(th, k1, h / 2));
  const auto k3 = rates(add(th, k2, h / 2));
  const auto k4 = rates(add(th, k3, h));
  th = add(th, k1, h / 6);
  th = add(th, k2, h / 3);
  th = add(th, k3, h / 3);
  return add(th, k4, h / 6);
}

TEST(FrictionRateState, SteadyStateIsTheStribeckCurvePlusTheDirectEffect) {
  const auto f = make_friction_model(rate_state_params());
  FrictionParams plain = rate_state_params();
  plain.memory = FrictionMemory::kNone;
  const auto stribeck = make_friction_model(plain);
  ASSERT_EQ(f->state_count(), 2u);
  for (const double v : {0.001, 0.005, 0.01, 0.03, 0.1}) {
    const FrictionInput in{v, 0.0, 0.0};
    std::array<double, 2> z{};
    f->steady_state(in, z);
    const auto [F, dz] = evaluate(*f, v, z);
    const double direct = kDirect * std::log(1.0 + v / kDirectVelocity);
    EXPECT_NEAR(F, stribeck->steady_force_N(in) + direct, 1e-12);
    EXPECT_EQ(dz[0], 0.0);
    EXPECT_EQ(dz[1], 0.0);
    EXPECT_NEAR(f->steady_force_N(in), F, 1e-12);
  }
}

TEST(FrictionRateState, EachStateRelaxesOverItsSlipLengthNotItsTime) {
  // From rest (theta = 1) at constant v: theta_i = w + (1 - w) exp(-d / L_i) with d = v t the
  // slip. Two speeds reach the same states at the same slip, in different times.
  const auto f = make_friction_model(rate_state_params());
  for (const double v : {0.005, 0.02}) {
    const double w = std::exp(-(v / 0.01) * (v / 0.01));
    std::array<double, 2> th{1.0, 1.0};
    const double h = kL1 / v / 200.0;  // RK4 at L1/200 of slip: error far below 1e-10
    for (int i = 1; i <= 4000; ++i) {
      th = rk4_step(*f, v, th, h);
      const double slip = v * h * i;
      EXPECT_NEAR(th[0], w + (1.0 - w) * std::exp(-slip / kL1), 1e-10) << v << " " << i;
      EXPECT_NEAR(th[1], w + (1.0 - w) * std::exp(-slip / kL2), 1e-10) << v << " " << i;
    }
  }
}

TEST(FrictionRateState, AVelocityStepJumpsByTheDirectEffectThenDecaysToTheSteadyCurve) {
  // Ruina's velocity-step response: at the step the states have not moved, so the force
  // changes by the direct effect and the viscous term alone; after a slip of many L2 it is
  // the steady curve at the new speed.
  const auto f = make_friction_model(rate_state_params());
  const double v1 = 0.005, v2 = 0.02;
  std::array<double, 2> th{};
  f->steady_state({v1, 0.0, 0.0}, th);
  const double before = evaluate(*f, v1, th).force_N;
  const double jump = evaluate(*f, v2, th).force_N - before;
  EXPECT_NEAR(jump,
              kDirect * std::log((1.0 + v2 / kDirectVelocity) / (1.0 + v1 / kDirectVelocity)) +
                  30.0 * (v2 - v1),
              1e-12);
  const double h = kL1 / v2 / 50.0;
  for (int i = 0; i < 50 * 200; ++i) th = rk4_step(*f, v2, th, h);  // 200 L1 = 20 L2 of slip
  const double settled = evaluate(*f, v2, th).force_N;
  EXPECT_NEAR(settled, f->steady_force_N({v2, 0.0, 0.0}), 20.0 * std::exp(-20.0));
  EXPECT_LT(settled, before + jump);  // the drop: the states weaken with the faster slip
}

TEST(FrictionRateState, BreakawayIsTheLevelTheStatesHold) {
  const auto f = make_friction_model(rate_state_params());
  const std::array<double, 2> rested{1.0, 1.0};
  EXPECT_DOUBLE_EQ(f->holding_force_N({0.0, 0.0, 0.0}, rested), 40.0);
  const std::array<double, 2> weakened{0.5, 0.0};
  const double expected = 20.0 + 20.0 * (kShare * 0.5);
  EXPECT_DOUBLE_EQ(f->holding_force_N({0.0, 0.0, 0.0}, weakened), expected);
  // Breakaway continues into sliding without a jump.
  EXPECT_DOUBLE_EQ(evaluate(*f, 0.0, weakened).force_N, expected);
}

TEST(FrictionRateState, KeysAreRefusedOutOfRangeNamingTheKey) {
  const std::array<std::pair<const char*, double>, 4> bad{{{"friction.rate_state_slip_length_um", 0.0},
                                                           {"friction.rate_state_slip_length2_um", -1.0},
                                                           {"friction.rate_state_share", 1.5},
                                                           {"friction.rate_state_direct_N", -0.1}}};
  for (const auto& [key, value] : bad) {
    Scenario s;
    try {
      apply_setting(s, key, value, "");
      FAIL() << "accepted " << key << " = " << value;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

// A scenario built in code, not through the keys, is checked by validate() too.
TEST(FrictionRateState, ValidateRefusesASlipLengthOfZeroSetInCode) {
  Scenario s = simple_rig_scenario();
  s.friction.memory = FrictionMemory::kRateState;
  s.validate();
  s.friction.rate_state.slip_length2_m = 0.0;
  try {
    s.validate();
    FAIL() << "accepted a slip length of zero";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), "friction.rate_state_slip_length2_um");
  }
}

TEST(FrictionRateState, OnlyTheStribeckModelTakesTheMemory) {
  Scenario s = default_scenario();
  s.friction.kind = FrictionKind::kLuGre;
  s.friction.memory = FrictionMemory::kRateState;
  try {
    s.validate();
    FAIL() << "accepted rate-and-state memory on a lugre seal";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), "friction.memory");
  }
}

TEST(FrictionRateState, TheStatesAreNamedChannelsAndHoldStillWhileStuck) {
  Scenario s = simple_rig_scenario();
  s.friction.memory = FrictionMemory::kRateState;  // the simple rig's seal is stribeck
  s.friction.rate_state.direct_N = 1.0;
  s.circuit.S2_m2 = 0.05e-6;  // small exhaust: stick-slip on the simple rig
  const Plant plant(s);
  const StateLayout& L = plant.layout();
  ASSERT_EQ(L.seal_z_count, 2u);
  EXPECT_EQ(plant.initial_state()[L.seal_z], 1.0);  // rested before the start
  EXPECT_EQ(plant.initial_state()[L.seal_z + 1], 1.0);
  const auto r = simulate(plant, s.run);
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  EXPECT_GE(r.summary.events.stick, 3u);
  const auto& theta = r.series.channel("theta").values;
  const auto& theta2 = r.series.channel("theta2").values;
  double lowest = 1.0;
  const std::size_t held = for_each_stuck_sample(r.series, [&](std::size_t i) {
    EXPECT_EQ(theta[i], theta[i - 1]) << "sample " << i;  // the slip law: no slip, no change
    EXPECT_EQ(theta2[i], theta2[i - 1]) << "sample " << i;
    lowest = std::min(lowest, theta[i]);
  });
  EXPECT_GT(held, 10u);
  EXPECT_LT(lowest, 0.99);  // the slips weakened the first state before it stuck again
}

}  // namespace
}  // namespace pneumachaos
