// The GMS seal's quasi-static limit (friction.gms_quasi_static_rate, docs/model.md "Friction")
// against the full law integrated at tight tolerances. The default scenario turns it on at a
// threshold its chaotic and stick-slip points never reach: there the elements' shares move
// too fast for it (docs/notes/performance.md, "The GMS seal's quasi-static limit"); where the
// contact slides fast it must keep the run within the default tolerances' own error and take
// the elements' stiffness out of the step, measured on the compliant-mount rig it was chosen
// on (scenarios/variants/compliant_mount.toml).
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "support/tight_options.hpp"
#include "support/variant_scenarios.hpp"

namespace pneumachaos {
namespace {

Scenario at(double S2_mm2, double limit_per_s, Scenario s = default_scenario()) {
  s.circuit.S2_m2 = S2_mm2 * 1e-6;
  s.run.duration_s = 2.0;  // both points reach the stroke end before (0.84 and 1.1 s)
  s.friction.gms.quasi_static_rate_per_s = limit_per_s;
  return s;
}

// The default threshold is above every loading rate of the chaotic point (S2 0.35 mm^2) and
// of stick-slip (0.05, 0.20): those runs are the full law's, bit for bit.
TEST(GmsQuasiStatic, DefaultThresholdLeavesTheChaoticAndStickSlipPointsUntouched) {
  const double threshold = default_scenario().friction.gms.quasi_static_rate_per_s;
  EXPECT_GT(threshold, 0.0);
  for (const double S2_mm2 : {0.05, 0.20, 0.35}) {
    const Scenario full = at(S2_mm2, 0.0);
    const auto a = simulate(Plant(full), full.run);
    const auto b = simulate(Plant(at(S2_mm2, threshold)), full.run);
    ASSERT_TRUE(a.summary.ok() && b.summary.ok());
    EXPECT_EQ(a.series.channel("v").values, b.series.channel("v").values) << "S2 " << S2_mm2;
    EXPECT_EQ(a.summary.rhs_evaluations, b.summary.rhs_evaluations) << "S2 " << S2_mm2;
  }
}

// Asked of the limit at 8000 1/s and at the default threshold: a velocity error against the
// tight reference within twice what the full law at the default tolerances makes (1.0e-6 and
// 3.3e-7 m/s here, 1e-6 of the speed), and fewer than half of its derivative evaluations.
TEST(GmsQuasiStatic, MatchesTheFullLawWhileSlidingFast) {
  const Scenario rig = compliant_mount();
  const double threshold = rig.friction.gms.quasi_static_rate_per_s;
  for (const double S2_mm2 : {3.0, 4.4}) {  // 0.6-0.8 m/s
    const Scenario full = at(S2_mm2, 0.0, rig);
    const auto reference = simulate(Plant(full), tight(2.0));
    const auto full_default = simulate(Plant(full), full.run);
    ASSERT_TRUE(reference.summary.ok() && full_default.summary.ok());
    for (const double limit_per_s : {8000.0, threshold}) {
      const auto limit = simulate(Plant(at(S2_mm2, limit_per_s, rig)), full.run);
      ASSERT_TRUE(limit.summary.ok());
      EXPECT_LE(largest_velocity_difference(limit, reference),
                2.0 * largest_velocity_difference(full_default, reference))
          << "S2 " << S2_mm2 << ", limit at " << limit_per_s << " 1/s";
      EXPECT_LT(2 * limit.summary.rhs_evaluations, full_default.summary.rhs_evaluations)
          << "S2 " << S2_mm2 << ", limit at " << limit_per_s << " 1/s";
    }
  }
}

// In the limit the recorded friction is the elements' force with their lag (drive - m dv/dt):
// in steady sliding at the end of a fast run it is the steady curve, as the full law's.
TEST(GmsQuasiStatic, RecordedFrictionIsTheSteadyCurveInSteadySliding) {
  const Scenario s = at(4.4, 8000.0, compliant_mount());
  const Plant plant(s);
  const auto r = simulate(plant, s.run);
  ASSERT_TRUE(r.summary.ok());
  const double v = r.series.channel("v").values.back();
  const double F = r.series.channel("F_friction").values.back();
  const double P = r.series.channel("P1").values.back() + r.series.channel("P2").values.back() -
                   2.0 * plant.ambient_pressure_Pa();
  const double x = r.series.channel("x").values.back();
  ASSERT_GT(v, 0.5);
  EXPECT_NEAR(F, plant.seal_friction().steady_force_N({v, P, x}), 1e-3);
}

}  // namespace
}  // namespace pneumachaos
