// The generalized Maxwell-slip model (friction.model = gms, docs/model.md "Friction") against
// known answers: steady sliding gives the Stribeck curve, small displacements a linear spring
// of the total stiffness, a sinusoidal displacement a hysteresis loop whose area grows with
// the amplitude; its keys reject bad values.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/friction.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos {
namespace {

FrictionParams gms_params(int elements) {
  FrictionParams p;
  p.kind = FrictionKind::kGms;
  p.curve.coulomb_N = 20.0;
  p.curve.static_N = 40.0;
  p.curve.viscous_Ns_per_m = 0.0;  // the loops below are the elements' own hysteresis
  p.curve.stribeck_velocity_m_per_s = 0.01;
  p.curve.stribeck_exponent = 2.0;
  p.gms.count = elements;
  p.gms.stiffness_N_per_m = 1.0e5;
  p.gms.attraction_length_m = 50e-6;
  return p;
}

// Drives the elements along a prescribed velocity v(t) with classical fourth-order Runge-Kutta
// and records the force at the end of each step.
struct Drive {
  const FrictionModel& f;
  std::vector<double> z;
  explicit Drive(const FrictionModel& model) : f(model), z(model.state_count(), 0.0) {}

  std::vector<double> rate(double v, const std::vector<double>& at) const {
    std::vector<double> dz(at.size());
    f.force_N({v, 0.0, 0.0}, 0, at, dz);
    return dz;
  }
  double force(double v) const {
    std::vector<double> dz(z.size());
    return f.force_N({v, 0.0, 0.0}, 0, z, dz);
  }
  template <typename Velocity>
  void step(Velocity v, double t, double h) {
    const auto shifted = [&](const std::vector<double>& k, double c) {
      std::vector<double> out = z;
      for (std::size_t i = 0; i < out.size(); ++i) out[i] += c * k[i];
      return out;
    };
    const auto k1 = rate(v(t), z);
    const auto k2 = rate(v(t + h / 2), shifted(k1, h / 2));
    const auto k3 = rate(v(t + h / 2), shifted(k2, h / 2));
    const auto k4 = rate(v(t + h), shifted(k3, h));
    for (std::size_t i = 0; i < z.size(); ++i)
      z[i] += h / 6 * (k1[i] + 2 * k2[i] + 2 * k3[i] + k4[i]);
  }
};

// Stribeck curve g(v) = Fc + (Fs - Fc) exp(-(v/vs)^2) of gms_params, written out.
double stribeck_level(double v) { return 20.0 + 20.0 * std::exp(-(v / 0.01) * (v / 0.01)); }

TEST(FrictionGms, ConstantSlidingTendsToTheStribeckLevel) {
  for (const int n : {1, 4}) {
    const auto f = make_friction_model(gms_params(n));
    ASSERT_EQ(f->state_count(), static_cast<std::size_t>(n));
    for (const double v : {0.002, 0.01, 0.03, -0.02}) {
      Drive d(*f);
      // 20 mm of sliding: 400 attraction lengths, far beyond the last element's breakaway.
      const double h = 1e-6 / std::abs(v);
      for (int i = 0; i < 20000; ++i) d.step([v](double) { return v; }, i * h, h);
      const double expected = std::copysign(stribeck_level(v), v);
      EXPECT_NEAR(d.force(v), expected, 1e-6 * std::abs(expected)) << n << " elements, v " << v;
      EXPECT_NEAR(f->steady_force_N({v, 0.0, 0.0}), expected, 1e-12 * std::abs(expected));
      // The steady internal state is a fixed point with the same force.
      std::vector<double> zs(static_cast<std::size_t>(n)), dz(zs.size());
      f->steady_state({v, 0.0, 0.0}, zs);
      EXPECT_NEAR(f->force_N({v, 0.0, 0.0}, 0, zs, dz), expected, 1e-12 * std::abs(expected));
      for (const double r : dz) EXPECT_NEAR(r, 0.0, 1e-15);
    }
  }
}

TEST(FrictionGms, SmallDisplacementIsALinearSpringUntilBreakaway) {
  for (const int n : {1, 4}) {
    const auto f = make_friction_model(gms_params(n));
    Drive d(*f);
    const double v = 1e-4;  // slow: the Stribeck level stays at Fs
    const double h = 1e-3;
    // The first element slips at (its share) * Fs / (K / n): for 4 elements 160 um.
    const double first_slip = 2.0 / (n * (n + 1.0)) * 40.0 / (1e5 / n);
    double x = 0.0;
    while (x < 0.1 * first_slip) {
      d.step([v](double) { return v; }, 0.0, h);
      x += v * h;
    }
    // Slip weight (x / x_slip)^4 ~ 1e-4 at a tenth of the breakaway deflection.
    EXPECT_NEAR(d.force(v) / (1e5 * x), 1.0, 2e-4) << n << " elements";
    while (x < 3.0 * first_slip) {
      d.step([v](double) { return v; }, 0.0, h);
      x += v * h;
    }
    EXPECT_LT(d.force(v), 0.9 * 1e5 * x) << "past breakaway the spring softens";
    EXPECT_LE(d.force(v), 40.0 * (1 + 1e-9));
  }
}

// Area of the loop F(x) over one period of x = A sin(2 pi t), after one period to settle.
double loop_area(const FrictionModel& f, double amplitude_m) {
  Drive d(f);
  const double w = 2.0 * std::numbers::pi;
  const auto v = [&](double t) { return amplitude_m * w * std::cos(w * t); };
  const int steps = 20000;
  const double h = 1.0 / steps;
  for (int i = 0; i < steps; ++i) d.step(v, i * h, h);
  double area = 0.0;
  double F = d.force(v(1.0));
  for (int i = 0; i < steps; ++i) {
    const double t = 1.0 + i * h;
    const double x0 = amplitude_m * std::sin(w * t);
    d.step(v, t, h);
    const double F1 = d.force(v(t + h));
    area += 0.5 * (F + F1) * (amplitude_m * std::sin(w * (t + h)) - x0);  // trapezoidal F dx
    F = F1;
  }
  return area;
}

TEST(FrictionGms, HysteresisLoopAreaIsPositiveAndGrowsWithAmplitude) {
  const auto f = make_friction_model(gms_params(4));
  double previous = 0.0;
  for (const double a : {20e-6, 80e-6, 200e-6, 500e-6}) {
    const double area = loop_area(*f, a);
    EXPECT_GT(area, previous) << "amplitude " << a;
    previous = area;
  }
  // A pure spring encloses no area: the loop is the elements' slip, bounded by the work of
  // the full level over the path (4 A Fs).
  EXPECT_GT(previous, 0.0);
  EXPECT_LT(previous, 4.0 * 500e-6 * 40.0);
}

// The quasi-static limit's deflection of an element tracking a rising share (docs/model.md,
// "Friction"): on the loading branch, at a constant speed s with the share r rising at dr/dt,
// the element settles where it loads as fast as the share rises, (1 - (m/r)^4) s = dr/dt, so
// m = r (1 - (dr/dt)/s)^(1/4): a lag of about r (dr/dt) / (4 s). The full law, integrated
// here with a rising pressure term, must settle on that manifold; what is left is the next
// order, the lag's own growth d(lag)/dt over the loading rate a = 4 s / r, i.e. the lag times
// (dr/dt) / (a r) (here 1e-3 of it; the limit neglects that term).
TEST(FrictionGms, ElementTrackingARisingShareSitsOnTheLoadingBranchsSlowManifold) {
  FrictionParams p = gms_params(1);
  p.curve.static_N =
      p.curve.coulomb_N;  // no Stribeck drop: the level moves with the pressure alone
  p.pressure_gain.coulomb_N_per_Pa = 1e-4;  // 100 N/MPa
  p.pressure_gain.static_N_per_Pa = 1e-4;
  p.gms.stiffness_N_per_m = 1e6;
  const auto f = make_friction_model(p);
  const double s = 0.05;              // m/s; the element's loading rate 4 s / r = 1e4 1/s
  const double gauge_rate = 2e6;      // Pa/s: the level rises at 200 N/s
  const auto level = [&](double t) { return 20.0 + 1e-4 * gauge_rate * t; };
  std::vector<double> z{level(0.0) / 1e6};  // starts on its share
  const auto rate = [&](double t, double zi) {
    std::vector<double> dz(1);
    f->force_N({s, gauge_rate * t, 0.0}, 0, std::vector<double>{zi}, dz);
    return dz[0];
  };
  const double h = 1e-7;  // a h = 1e-3: the classical Runge-Kutta error is negligible
  double t = 0.0;
  for (int i = 0; i < 50000; ++i, t += h) {  // 5 ms: 50 relaxation times
    const double k1 = rate(t, z[0]);
    const double k2 = rate(t + h / 2, z[0] + h / 2 * k1);
    const double k3 = rate(t + h / 2, z[0] + h / 2 * k2);
    const double k4 = rate(t + h, z[0] + h * k3);
    z[0] += h / 6 * (k1 + 2 * k2 + 2 * k3 + k4);
  }
  const double r = level(t) / 1e6;
  const double dr_dt = 1e-4 * gauge_rate / 1e6;
  const double manifold = r * std::pow(1.0 - dr_dt / s, 0.25);
  const double lag = r - manifold;
  // 2e-8 m: the first-order lag, within the binomial series' next term, 3/8 (dr/dt)/s of it.
  EXPECT_NEAR(lag, r * dr_dt / (4 * s), 0.375 * dr_dt / s * lag * 1.01);
  const double second_order = lag * dr_dt / (4 * s / r * r);
  EXPECT_LT(second_order, 2e-3 * lag);
  EXPECT_NEAR(z[0], manifold, 2.0 * second_order) << "full law " << z[0] << ", share " << r;
}

TEST(FrictionGms, KeysRejectBadValuesNamingTheKey) {
  Scenario s;
  apply_setting(s, "friction.model", std::string("gms"), "");
  apply_setting(s, "friction.gms_elements", 6.0, "");
  EXPECT_EQ(s.friction.gms.count, 6);
  for (const auto& [key, value] :
       {std::pair<const char*, double>{"friction.gms_elements", 0.0},
        {"friction.gms_elements", 11.0},
        {"friction.gms_elements", 2.5},
        {"friction.gms_stiffness_N_per_m", 0.0},
        {"friction.gms_attraction_length_um", -1.0},
        {"friction.gms_quasi_static_rate", -1.0}}) {
    try {
      apply_setting(s, key, value, "");
      ADD_FAILURE() << key << " = " << value << " accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(key), std::string::npos) << e.what();
    }
  }
}

// On the plant the elements are ODE states like LuGre's bristle: a run records each one, needs
// no stick events, and in steady sliding ends on the model's steady friction.
TEST(FrictionGms, PlantRunEndsOnTheSteadyCurveWithEveryElementRecorded) {
  Scenario s = simple_rig_scenario();
  s.friction.kind = FrictionKind::kGms;
  s.circuit.S2_m2 = 2.0e-6;  // a wide exhaust: steady sliding on the simple rig
  const Plant plant(s);
  ASSERT_EQ(plant.layout().seal_z_count, 4u);
  const auto r = simulate(plant, s.run);
  EXPECT_EQ(r.summary.events.stick, 0u);
  for (const char* name : {"z_gms", "z_gms2", "z_gms3", "z_gms4"})
    EXPECT_FALSE(r.series.channel(name).values.empty()) << name;
  const double v = r.series.channel("v").values.back();
  const double F = r.series.channel("F_friction").values.back();
  ASSERT_GT(v, 0.01);
  EXPECT_NEAR(F, plant.seal_friction().steady_force_N({v, 0.0, 0.0}), 1e-6 * F);
}

// Scenarios built in code are checked against the same ranges when validated.
TEST(FrictionGms, ValidateRejectsBadParametersNamingTheKey) {
  const auto key_of = [](const Scenario& s) {
    try {
      s.validate();
    } catch (const Error& e) {
      return e.where();
    }
    return std::string("(accepted)");
  };
  Scenario s;
  s.friction.kind = FrictionKind::kGms;
  EXPECT_EQ(key_of(s), "(accepted)");
  Scenario none = s;
  none.friction.gms.count = 0;
  EXPECT_EQ(key_of(none), "friction.gms_elements");
  Scenario soft = s;
  soft.friction.gms.stiffness_N_per_m = -1.0;
  EXPECT_EQ(key_of(soft), "friction.gms_stiffness_N_per_m");
  Scenario instant = s;
  instant.friction.gms.attraction_length_m = 0.0;
  EXPECT_EQ(key_of(instant), "friction.gms_attraction_length_um");
  Scenario frictionless = s;
  frictionless.friction.curve.coulomb_N = 0.0;
  EXPECT_EQ(key_of(frictionless), "friction.Fc_N");
}

}  // namespace
}  // namespace pneumachaos
