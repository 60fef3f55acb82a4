// The Hess-Soom lag model (stribeck with memory = lag, docs/model.md "Friction") against known answers:
// its steady curve is the static Stribeck curve, a velocity step relaxes with tau, and a
// velocity sweep opens a loop whose width follows tau dv/dt.
#include <gtest/gtest.h>

#include <array>
#include <cmath>
#include <numbers>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/friction.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "support/stuck_samples.hpp"

namespace pneumachaos {
namespace {

FrictionParams lag_params(double tau_s) {
  FrictionParams p;
  p.kind = FrictionKind::kStribeck;
  p.memory = FrictionMemory::kLag;
  p.curve.coulomb_N = 20.0;
  p.curve.static_N = 40.0;
  p.curve.viscous_Ns_per_m = 30.0;
  p.curve.stribeck_velocity_m_per_s = 0.01;
  p.curve.stribeck_exponent = 2.0;
  p.lag.time_s = tau_s;
  return p;
}

// Force and ds/dt of the model at velocity v (> 0) and lag state s.
std::array<double, 2> force_and_rate(const FrictionModel& f, double v, double s) {
  std::array<double, 1> z{s};
  std::array<double, 1> dz{};
  const double F = f.force_N({v, 0.0, 0.0}, +1, z, dz);
  return {F, dz[0]};
}

// Classical fourth-order Runge-Kutta for s under a prescribed velocity v(t).
template <typename Velocity>
double rk4_step(const FrictionModel& f, Velocity v, double t, double s, double h) {
  const double k1 = force_and_rate(f, v(t), s)[1];
  const double k2 = force_and_rate(f, v(t + h / 2), s + h / 2 * k1)[1];
  const double k3 = force_and_rate(f, v(t + h / 2), s + h / 2 * k2)[1];
  const double k4 = force_and_rate(f, v(t + h), s + h * k3)[1];
  return s + h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
}

TEST(FrictionLag, SteadyStateIsTheStaticStribeckCurve) {
  const auto lag = make_friction_model(lag_params(0.005));
  FrictionParams static_p = lag_params(0.005);
  static_p.memory = FrictionMemory::kNone;
  const auto stribeck = make_friction_model(static_p);
  for (const double v : {0.001, 0.005, 0.01, 0.03, 0.1}) {
    const FrictionInput in{v, 0.0, 0.0};
    std::array<double, 1> z{};
    lag->steady_state(in, z);
    const auto [F, ds] = force_and_rate(*lag, v, z[0]);
    EXPECT_NEAR(F, stribeck->steady_force_N(in), 1e-12);  // same arithmetic up to rounding
    EXPECT_NEAR(ds, 0.0, 1e-12);
    EXPECT_NEAR(lag->steady_force_N(in), stribeck->steady_force_N(in), 1e-12);
  }
}

TEST(FrictionLag, AVelocityStepRelaxesWithTau) {
  // From rest (s = 1) to v = 20 mm/s: s(t) = w + (1 - w) exp(-t / tau), w = exp(-(v/vs)^2).
  constexpr double kTau = 0.01;
  const auto f = make_friction_model(lag_params(kTau));
  const double v = 0.02;
  const double w = std::exp(-4.0);
  double s = 1.0;
  const double h = kTau / 200.0;
  for (int i = 1; i <= 1000; ++i) {
    s = rk4_step(*f, [&](double) { return v; }, 0.0, s, h);
    const double expected = w + (1.0 - w) * std::exp(-i * h / kTau);
    EXPECT_NEAR(s, expected, 1e-10);  // RK4 at tau/200: error far below 1e-10
  }
  // The force went from Fs + B v to the static curve's value.
  EXPECT_NEAR(force_and_rate(*f, v, s)[0], 20.0 + 20.0 * w + 30.0 * v, 20.0 * 1e-2);
}

// Width of the friction-velocity loop at the mean velocity under v = v0 + a sin(omega t):
// the force on the accelerating branch minus that on the decelerating one.
double loop_width(double tau_s, double v0, double a, double omega) {
  const auto f = make_friction_model(lag_params(tau_s));
  const auto v = [&](double t) { return v0 + a * std::sin(omega * t); };
  const double period = 2.0 * std::numbers::pi / omega;
  const int steps_per_period = 20000;
  const double h = period / steps_per_period;
  double s = std::exp(-std::pow(v0 / 0.01, 2));
  // Ten periods: far more than the transient of a few tau.
  for (int i = 0; i < 10 * steps_per_period; ++i) s = rk4_step(*f, v, i * h, s, h);
  const double rising = force_and_rate(*f, v0, s)[0];  // t = 10 periods: v = v0, dv/dt > 0
  for (int i = 0; i < steps_per_period / 2; ++i) s = rk4_step(*f, v, i * h, s, h);
  const double falling = force_and_rate(*f, v0, s)[0];  // half a period on: dv/dt < 0
  return rising - falling;
}

TEST(FrictionLag, HysteresisWidthGrowsWithTauTimesAcceleration) {
  // On the drop the lagging weight stays high while v rises and low while it falls, so the
  // rising branch lies above the falling one: to first order in tau omega the width is
  // 2 tau (Fs - Fc) |dw/dv| a omega.
  const double v0 = 0.01, a = 0.002, omega = 2.0 * std::numbers::pi * 2.0;
  const double dw_dv = 2.0 * v0 / (0.01 * 0.01) * std::exp(-1.0);
  for (const double tau : {0.0005, 0.001}) {
    const double predicted = 2.0 * tau * 20.0 * dw_dv * a * omega;
    // tau omega <= 0.013: the first-order formula holds to a few parts in a thousand,
    // and the loop's curvature in a adds a few per cent at a / v0 = 0.2.
    EXPECT_NEAR(loop_width(tau, v0, a, omega) / predicted, 1.0, 0.05) << "tau " << tau;
  }
  const double narrow = loop_width(0.001, v0, a, omega);
  EXPECT_GT(narrow, 0.0);
  EXPECT_GT(loop_width(0.004, v0, a, omega), 3.0 * narrow);      // grows with tau
  EXPECT_GT(loop_width(0.001, v0, a, 2.0 * omega), 1.8 * narrow);  // and with dv/dt
}

TEST(FrictionLag, LagTimeMustBePositiveNamingTheKey) {
  for (const double bad : {0.0, -1.0}) {
    Scenario s;
    try {
      apply_setting(s, "friction.lag_time_ms", bad, "");
      FAIL() << "accepted lag time " << bad;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("friction.lag_time_ms"), std::string::npos);
    }
  }
}

TEST(FrictionLag, OnlyTheStribeckModelTakesTheLag) {
  Scenario s = default_scenario();
  s.friction.kind = FrictionKind::kLuGre;
  s.friction.memory = FrictionMemory::kLag;
  try {
    s.validate();
    FAIL() << "accepted a lag on a lugre seal";
  } catch (const Error& e) {
    EXPECT_EQ(e.where(), "friction.memory");
  }
}

TEST(FrictionLag, StictionHoldsAndTheLagRecoversWhileStuck) {
  Scenario s = simple_rig_scenario();
  s.friction.memory = FrictionMemory::kLag;  // the simple rig's seal is stribeck
  s.friction.lag.time_s = 0.01;
  s.circuit.S2_m2 = 0.05e-6;  // small exhaust: stick-slip on the simple rig
  const Plant plant(s);
  EXPECT_EQ(plant.initial_state()[plant.layout().seal_z], 1.0);  // rested before the start
  const auto r = simulate(plant, s.run);
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  EXPECT_GE(r.summary.events.stick, 3u);
  const auto& lag = r.series.channel("s_lag").values;
  std::size_t recovering = 0;
  for_each_stuck_sample(r.series, [&](std::size_t i) {
    // s -> 1 at rest, monotonically up to the integrator's relative tolerance (1e-7)
    EXPECT_GE(lag[i], lag[i - 1] - 1e-7);
    if (lag[i] > lag[i - 1] + 1e-7) ++recovering;
  });
  EXPECT_GT(recovering, 10u);
}

}  // namespace
}  // namespace pneumachaos
