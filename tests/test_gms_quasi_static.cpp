// The GMS seal's quasi-static limit (friction.gms_quasi_static_rate, docs/model.md "Friction")
// against the full law integrated at tight tolerances, on the default rig. Off by default:
// at the chaotic and stick-slip points the elements' shares move too fast for it
// (docs/performance.md, "Simulation (fourth round: the GMS seal)"); where the contact slides
// fast it must keep the run within the default tolerances' own error and take the elements'
// stiffness out of the step.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "tight_options.hpp"

namespace pneumachaos {
namespace {

double largest_velocity_difference(const SimulationResult& a, const SimulationResult& b) {
  const auto& va = a.series.channel("v").values;
  const auto& vb = b.series.channel("v").values;
  EXPECT_EQ(va.size(), vb.size());
  double worst = 0.0;
  for (std::size_t i = 0; i < std::min(va.size(), vb.size()); ++i)
    worst = std::max(worst, std::abs(va[i] - vb[i]));
  return worst;
}

Scenario at(double S2_mm2, double limit_per_s) {
  Scenario s = default_scenario();
  s.circuit.S2_m2 = S2_mm2 * 1e-6;
  s.run.duration_s = 2.0;  // both points reach the stroke end before (0.84 and 1.1 s)
  s.friction.gms_quasi_static_rate_per_s = limit_per_s;
  return s;
}

TEST(GmsQuasiStatic, IsOffByDefault) {
  EXPECT_EQ(default_scenario().friction.gms_quasi_static_rate_per_s, 0.0);
}

// Asked of the limit at 8000 1/s: a velocity error against the tight reference within twice
// what the full law at the default tolerances makes (1.0e-6 and 3.3e-7 m/s here, 1e-6 of the
// speed), and fewer than half of its derivative evaluations.
TEST(GmsQuasiStatic, MatchesTheFullLawWhileSlidingFast) {
  for (const double S2_mm2 : {3.0, 4.4}) {  // 0.6-0.8 m/s
    const Scenario full = at(S2_mm2, 0.0);
    const auto reference = simulate(Plant(full), tight(2.0));
    const auto full_default = simulate(Plant(full), full.run);
    const auto limit = simulate(Plant(at(S2_mm2, 8000.0)), full.run);
    ASSERT_TRUE(reference.summary.ok() && full_default.summary.ok() && limit.summary.ok());
    EXPECT_LE(largest_velocity_difference(limit, reference),
              2.0 * largest_velocity_difference(full_default, reference))
        << "S2 " << S2_mm2;
    EXPECT_LT(2 * limit.summary.rhs_evaluations, full_default.summary.rhs_evaluations)
        << "S2 " << S2_mm2;
  }
}

// In the limit the recorded friction is the elements' force with their lag (drive - m dv/dt):
// in steady sliding at the end of a fast run it is the steady curve, as the full law's.
TEST(GmsQuasiStatic, RecordedFrictionIsTheSteadyCurveInSteadySliding) {
  const Scenario s = at(4.4, 8000.0);
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
