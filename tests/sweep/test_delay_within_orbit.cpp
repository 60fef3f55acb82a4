// The embedding delay of an oscillating record stays under one orbit (dysts's ShimizuMorioka
// has its mutual-information minimum three orbits out, Thomas two: with that delay they get no
// exponent and no verdict); a record resting between slips keeps its mutual-information delay.
#include <gtest/gtest.h>

#include <cmath>

#include "support/dysts_runner.hpp"
#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/analysis/embedding_parameters.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "support/variant_scenarios.hpp"

namespace pneumachaos {
namespace {

using namespace pneumachaos::testing;

TEST(DelayWithinAnOrbit, KeepsADelayUnderTheOrbitAndReplacesOneAtOrBeyondIt) {
  const DelayChoice mi{17, "mutual-information minimum", {}};
  EXPECT_EQ(delay_within_an_orbit(mi, 33.0).delay, 17u);  // half an orbit: kept
  EXPECT_EQ(delay_within_an_orbit(mi, 17.5).delay, 17u);
  const DelayChoice at = delay_within_an_orbit(mi, 17.0);  // a whole orbit
  EXPECT_EQ(at.delay, 4u);                                  // 17 / 4 = 4.25
  const DelayChoice far = delay_within_an_orbit({190, "mutual-information minimum", {}}, 63.0);
  EXPECT_EQ(far.delay, 16u);  // 63 / 4 = 15.75
  EXPECT_NE(far.method.find("a quarter of the orbit"), std::string::npos) << far.method;
  EXPECT_NE(far.method.find("190"), std::string::npos) << far.method;
  // Maps and noise (maxima a few samples apart) have no orbit to speak of.
  EXPECT_EQ(delay_within_an_orbit({5, "autocorrelation 1/e", {}}, 3.0).delay, 5u);
}

// dysts's ShimizuMorioka at 10,000 samples (50 per period): the first minimum of the mutual
// information lies three orbits out. Within an orbit, the record is judged chaotic and the
// flow's exponent (two trajectories from the equations) lies inside the 95 % interval.
TEST(DelayWithinAnOrbit, ShimizuMoriokaIsEmbeddedWithinAnOrbitAndJudgedChaotic) {
  dysts::System s;
  for (const dysts::System& c : dysts::load_systems(PNEUMACHAOS_DYSTS_TSV)) {
    if (c.name == "ShimizuMorioka") s = c;
  }
  ASSERT_EQ(s.name, "ShimizuMorioka");
  const auto x = dysts::record(s, 10000);
  const double rate = dysts::kPointsPerPeriod / s.period;
  AnalysisOptions o;  // with the exponent's embedding spread, as `analyze` runs it
  o.wolf = false;
  o.embedding_spread = true;
  const AnalysisResult r = analyze_series(x, rate, o);
  ASSERT_GE(static_cast<double>(choose_delay(x).delay), 2.0 * r.period_samples)
      << "the premise: a minimum two orbits or more out";
  EXPECT_EQ(r.delay.delay, static_cast<std::size_t>(std::lround(0.25 * r.period_samples)));
  EXPECT_EQ(r.verdict.regime, Regime::kChaotic);
  ASSERT_TRUE(r.divergence.found_linear_region);
  const double truth = dysts::benettin(s, 500.0).lambda;
  EXPECT_NEAR(r.divergence.lambda_per_s, truth, 1.96 * r.divergence.uncertainty_per_s);
}

// The compliant-mount rig (scenarios/variants/compliant_mount.toml) at S2 = 0.20 mm^2: stick-slip, its
// mutual-information minimum (136 samples) past its orbital period (107). As a velocity (rests
// judged) the delay is kept; as another quantity (no rests looked for) the rule replaces it.
TEST(DelayWithinAnOrbit, ARigRecordRestingBetweenSlipsKeepsItsDelay) {
  Scenario s = compliant_mount();
  s.circuit.S2_m2 = 0.20e-6;
  const SimulationResult sim = simulate(Plant(s), s.run);
  ASSERT_TRUE(sim.summary.ok());
  const std::vector<double>& v = sim.series.channel("v").values;
  const std::size_t mi = choose_delay(v).delay;
  AnalysisOptions o;
  o.wolf = false;
  const AnalysisResult velocity = analyze_series(v, sim.series.rate_Hz(), o);
  ASSERT_GE(static_cast<double>(mi), velocity.period_samples) << "the premise: delay >= orbit";
  EXPECT_TRUE(velocity.verdict.stick_slip);
  EXPECT_EQ(velocity.delay.delay, mi);
  o.velocity = false;
  const AnalysisResult other = analyze_series(v, sim.series.rate_Hz(), o);
  EXPECT_LT(static_cast<double>(other.delay.delay), other.period_samples);
}

}  // namespace
}  // namespace pneumachaos
