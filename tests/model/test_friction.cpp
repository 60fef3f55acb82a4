// Friction models (docs/model.md, "Friction").
#include <gtest/gtest.h>

#include <array>
#include <cmath>

#include "pneumachaos/model/friction.hpp"

namespace pneumachaos {
namespace {

FrictionParams params(FrictionKind kind) {
  FrictionParams p;
  p.kind = kind;
  p.curve.coulomb_N = 20.0;
  p.curve.static_N = 40.0;
  p.curve.viscous_Ns_per_m = 30.0;
  p.curve.stribeck_velocity_m_per_s = 0.01;
  p.curve.stribeck_exponent = 2.0;
  p.lugre.sigma0_N_per_m = 1e5;
  p.lugre.sigma1_Ns_per_m = 300.0;
  return p;
}

TEST(Friction, ClassicIsPaperEquation4) {
  const auto f = make_friction_model(params(FrictionKind::kClassic));
  EXPECT_TRUE(f->has_stiction());
  EXPECT_DOUBLE_EQ(f->holding_force_N({0.0, 0.0, 0.0}, {}), 40.0);
  EXPECT_DOUBLE_EQ(f->force_N({0.1, 0.0, 0.0}, +1, {}, {}), 20.0 + 30.0 * 0.1);
  EXPECT_DOUBLE_EQ(f->force_N({-0.1, 0.0, 0.0}, -1, {}, {}), -(20.0 + 30.0 * 0.1));
  EXPECT_NEAR(f->steady_slope_Ns_per_m({0.05, 0.0, 0.0}), 30.0, 1e-6);
}

TEST(Friction, StribeckHasNegativeSlopeAtLowSpeed) {
  const auto f = make_friction_model(params(FrictionKind::kStribeck));
  // d/dv [Fc + (Fs-Fc) exp(-(v/vs)^2)] + B at v = vs: -2 (Fs-Fc)/vs e^-1 + B = -1441.5 N s/m.
  const double expected = -2.0 * 20.0 / 0.01 * std::exp(-1.0) + 30.0;
  EXPECT_NEAR(f->steady_slope_Ns_per_m({0.01, 0.0, 0.0}), expected, 1e-4 * std::abs(expected));
  EXPECT_GT(f->steady_slope_Ns_per_m({0.2, 0.0, 0.0}), 0.0);  // viscous side of the curve
}

TEST(Friction, PressureDependenceRaisesBothLevels) {
  FrictionParams p = params(FrictionKind::kClassic);
  p.pressure_gain.coulomb_N_per_Pa = 10e-6;  // 10 N/MPa
  p.pressure_gain.static_N_per_Pa = 20e-6;
  const auto f = make_friction_model(p);
  EXPECT_NEAR(f->holding_force_N({0.0, 0.5e6, 0.0}, {}), 50.0, 1e-12);
  EXPECT_NEAR(f->force_N({0.0, 0.5e6, 0.0}, +1, {}, {}), 25.0, 1e-12);
}

TEST(Friction, TextureScalesBothLevelsByOneFactor) {
  // Fc and Fs share the texture factor 1 + sum a sin(k x + phi) (docs/model.md), summed once
  // for both (docs/notes/performance.md): the steady force must equal the law written out here
  // operation for operation, to the last bit.
  FrictionParams p = params(FrictionKind::kStribeck);
  p.curve.stribeck_exponent = 1.0;
  p.pressure_gain.coulomb_N_per_Pa = 10e-6;
  p.pressure_gain.static_N_per_Pa = 20e-6;
  p.texture = {{0.02, 300.0, 0.4}, {-0.01, 150.0, 2.0}, {0.015, 610.0, 5.1}, {0.005, 90.0, 1.0}};
  const double gauge = 0.3e6;
  for (FrictionKind kind : {FrictionKind::kStribeck, FrictionKind::kLuGre}) {
    p.kind = kind;
    const auto f = make_friction_model(p);
    for (double x : {0.0, 0.0123, 0.41}) {
      double texture = 1.0;
      for (const TextureMode& m : p.texture)
        texture += m.amplitude * std::sin(m.wavenumber_per_m * x + m.phase);
      const double fc = (20.0 + 10e-6 * gauge) * texture;
      const double fs = (40.0 + 20e-6 * gauge) * texture;
      const double v = 0.004;
      const double expected = fc + (fs - fc) * std::exp(-(std::abs(v) / 0.01)) + 30.0 * v;
      EXPECT_EQ(f->steady_force_N({v, gauge, x}), expected) << "x = " << x;
      EXPECT_NE(texture, 1.0);
    }
  }
}

TEST(Friction, LuGreAtConstantVelocitySettlesOnItsStribeckCurve) {
  // At constant v, dz/dt = v - sigma0 |v| z / g(v) is linear in z and relaxes to
  // z = g(v)/sigma0 with time constant g/(sigma0 |v|); the force then equals g(v) + sigma2 v.
  // Small explicit steps over 40 time constants (residual e^-40): the step's fixed point is exact.
  const auto f = make_friction_model(params(FrictionKind::kLuGre));
  for (double v : {0.002, 0.01, 0.05}) {
    const FrictionInput in{v, 0.0, 0.0};
    std::array<double, 1> z{0.0};
    std::array<double, 1> dz{0.0};
    const double g = 20.0 + 20.0 * std::exp(-std::pow(v / 0.01, 2.0));
    const double tau = g / (1e5 * v);
    const double h = tau / 2000.0;
    for (int i = 0; i < 80000; ++i) {
      f->force_N(in, 0, z, dz);
      z[0] += h * dz[0];
    }
    const double F = f->force_N(in, 0, z, dz);
    const double steady = f->steady_force_N(in);
    EXPECT_NEAR(steady, g + 30.0 * v, 1e-12);
    EXPECT_NEAR(F, steady, 1e-6 * steady) << "v = " << v;
    std::array<double, 1> z_ss{};
    f->steady_state(in, z_ss);
    EXPECT_NEAR(z[0], z_ss[0], 1e-9 * z_ss[0]);
  }
}

}  // namespace
}  // namespace pneumachaos
