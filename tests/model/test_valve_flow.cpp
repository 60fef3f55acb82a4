// Valve flow laws (docs/model.md, "Valves").
#include <gtest/gtest.h>

#include <cmath>

#include "pneumachaos/model/valve_flow.hpp"

namespace pneumachaos {
namespace {

constexpr double kT = 293.15;
constexpr double kS = 1e-6;  // 1 mm^2

TEST(ValveFlow, ChokedFlowMatchesClosedForm) {
  // Closed form for k = 1.4, R = 287: W = S P sqrt(k/(R T)) (2/(k+1))^3 = S P * 2.3606e-3 s/m.
  const GasConstants gas;
  const ValveLaw law;
  const double P_up = 6e5;
  const double expected = kS * P_up * std::sqrt(1.4 / (287.0 * kT)) * std::pow(2.0 / 2.4, 3.0);
  EXPECT_NEAR(valve_mass_flow(law, gas, kS, P_up, kT, 1e5, kT), expected, 1e-12 * expected);
  EXPECT_NEAR(choked_flux_factor(gas, kT), 2.3606e-3, 1e-6);
  // Fully choked below b: the downstream pressure does not matter.
  EXPECT_DOUBLE_EQ(valve_mass_flow(law, gas, kS, P_up, kT, 0.3 * P_up, kT),
                   valve_mass_flow(law, gas, kS, P_up, kT, 0.5 * P_up, kT));
}

TEST(ValveFlow, MeterOutSpeedConstantIs199MetresPerSecond) {
  // docs/model.md, "Defaults": choked meter-out speed ~ 199 m/s * S2/A2, i.e. W R T / P = S * 198.6 m/s.
  const GasConstants gas;
  EXPECT_NEAR(choked_flux_factor(gas, kT) * 287.0 * kT, 198.6, 0.1);
}

class FlowLawTest : public ::testing::TestWithParam<FlowLaw> {};

TEST_P(FlowLawTest, ContinuousAtCriticalRatioAndLaminarJunction) {
  const GasConstants gas;
  ValveLaw law;
  law.law = GetParam();
  const double k = gas.heat_capacity_ratio;
  const double b =
      law.law == FlowLaw::kIso6358 ? law.critical_ratio : std::pow(2.0 / (k + 1.0), k / (k - 1.0));
  const double eps = 1e-9;
  EXPECT_NEAR(flow_function(law, gas, b - eps), flow_function(law, gas, b + eps), 1e-6);
  const double r = law.laminar_ratio;
  EXPECT_NEAR(flow_function(law, gas, r - eps), flow_function(law, gas, r + eps), 1e-6);
  // The slope is continuous too: the junction is no kink (a linear branch matched in value
  // only would be twice as steep as the ellipse there). Slopes over 1e-6 on either side agree
  // to 1e-3 of their size.
  const auto slope = [&](double from, double to) {
    return (flow_function(law, gas, to) - flow_function(law, gas, from)) / (to - from);
  };
  const double below = slope(r - 1e-6, r), above = slope(r, r + 1e-6);
  EXPECT_NEAR(above, below, 1e-3 * std::abs(below));
  // Laminar as r -> 1: psi(1 - d) / d tends to a constant (linear in the pressure difference).
  const double d = 1e-7;
  EXPECT_NEAR(flow_function(law, gas, 1.0 - d) / d, flow_function(law, gas, 1.0 - 2 * d) / (2 * d),
              1e-5 * flow_function(law, gas, 1.0 - d) / d);
}

TEST_P(FlowLawTest, ZeroAtEqualPressuresAndReversesSign) {
  const GasConstants gas;
  ValveLaw law;
  law.law = GetParam();
  EXPECT_EQ(valve_mass_flow(law, gas, kS, 3e5, kT, 3e5, kT), 0.0);
  for (double P_b : {1e5, 2.5e5, 2.99e5, 2.9999e5}) {
    const double forward = valve_mass_flow(law, gas, kS, 3e5, kT, P_b, kT);
    EXPECT_GT(forward, 0.0);
    EXPECT_DOUBLE_EQ(valve_mass_flow(law, gas, kS, P_b, kT, 3e5, kT), -forward);
  }
  EXPECT_EQ(valve_mass_flow(law, gas, 0.0, 3e5, kT, 1e5, kT), 0.0);
}

TEST_P(FlowLawTest, FlowFunctionIsMonotoneAndBounded) {
  const GasConstants gas;
  ValveLaw law;
  law.law = GetParam();
  double previous = 1.0;
  for (int i = 0; i <= 1000; ++i) {
    const double psi = flow_function(law, gas, i / 1000.0);
    EXPECT_LE(psi, previous + 1e-15);
    EXPECT_GE(psi, 0.0);
    previous = psi;
  }
  EXPECT_EQ(flow_function(law, gas, 1.0), 0.0);
}

INSTANTIATE_TEST_SUITE_P(Laws, FlowLawTest,
                         ::testing::Values(FlowLaw::kIso6358, FlowLaw::kIsentropic));

TEST(ValveFlow, IsentropicSubsonicMatchesSaintVenant) {
  // Saint-Venant: W = S P_up sqrt(2k/((k-1) R T) (r^(2/k) - r^((k+1)/k))).
  const GasConstants gas;
  ValveLaw law;
  law.law = FlowLaw::kIsentropic;
  const double k = 1.4, r = 0.8, P_up = 5e5;
  const double expected = kS * P_up *
                          std::sqrt(2.0 * k / ((k - 1.0) * 287.0 * kT) *
                                    (std::pow(r, 2.0 / k) - std::pow(r, (k + 1.0) / k)));
  EXPECT_NEAR(valve_mass_flow(law, gas, kS, P_up, kT, r * P_up, kT), expected, 1e-10 * expected);
}

}  // namespace
}  // namespace pneumachaos
