// Seeded run-to-run variation of the virtual rig.
#include <gtest/gtest.h>

#include <cmath>

#include "pneumachaos/model/scenario_keys.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/model/variation.hpp"

namespace pneumachaos {
namespace {

std::string text(const Scenario& s) { return scenario_to_toml(s); }

TEST(Variation, ZeroVariationLeavesTheScenarioUnchanged) {
  const Scenario base = default_scenario();
  for (std::uint64_t r = 0; r < 5; ++r) EXPECT_EQ(text(vary(base, run_seed(1, 7, r))), text(base));
}

TEST(Variation, NonzeroVariationDiffersPerRunAndIsReproducible) {
  const Scenario base =
      build_scenario("", {"variation.friction_rel_sd=0.1", "variation.texture_rel=0.05"});
  const Scenario a = vary(base, run_seed(1, 7, 0));
  const Scenario b = vary(base, run_seed(1, 7, 1));
  EXPECT_NE(a.friction.curve.coulomb_N, b.friction.curve.coulomb_N);
  EXPECT_EQ(a.friction.curve.coulomb_N, vary(base, run_seed(1, 7, 0)).friction.curve.coulomb_N);
  EXPECT_GE(a.friction.curve.static_N, a.friction.curve.coulomb_N);
  ASSERT_EQ(a.friction.texture.size(), 4u);
  // The texture makes the friction level depend on the position along the bore.
  const auto model = make_friction_model(a.friction);
  EXPECT_NE(model->steady_force_N({0.01, 0.0, 0.010}), model->steady_force_N({0.01, 0.0, 0.017}));
}

TEST(Variation, RunSeedsAreDistinctAcrossPointsAndRepeats) {
  EXPECT_NE(run_seed(1, 0, 1), run_seed(1, 1, 0));
  EXPECT_NE(run_seed(1, 2, 3), run_seed(2, 2, 3));
  EXPECT_EQ(run_seed(5, 2, 3), run_seed(5, 2, 3));
}

TEST(Variation, SensorNoiseIsSeededAndHasItsStandardDeviation) {
  const std::vector<double> a = sensor_noise(42, NoiseStream::kVelocity, 20000, 0.5e-3);
  EXPECT_EQ(a, sensor_noise(42, NoiseStream::kVelocity, 20000, 0.5e-3));
  EXPECT_NE(a, sensor_noise(43, NoiseStream::kVelocity, 20000, 0.5e-3));
  EXPECT_NE(a, sensor_noise(42, NoiseStream::kPressure1, 20000, 0.5e-3));
  double mean = 0.0, square = 0.0;
  for (double x : a) {
    mean += x / a.size();
    square += x * x / a.size();
  }
  // 20000 normal draws: the mean's standard error is sd/141, the sd's about sd/200; 5 of
  // each leaves a false failure a one-in-a-million event.
  EXPECT_NEAR(mean, 0.0, 5.0 * 0.5e-3 / 141.0);
  EXPECT_NEAR(std::sqrt(square - mean * mean), 0.5e-3, 5.0 * 0.5e-3 / 200.0);
}

}  // namespace
}  // namespace pneumachaos
