// The seal's random level field (src/model/level_field.hpp): its statistics against the
// exponential correlation it is drawn from, the Plant's table against its sines, and runs
// through it.
#include <gtest/gtest.h>

#include <cmath>
#include <optional>

#include "model/level_field.hpp"
#include "pneumachaos/model/variation.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "support/tight_options.hpp"

namespace pneumachaos {
namespace {

RandomLevelField field_of(double rel_sd, double correlation_m, std::uint64_t seed) {
  std::mt19937_64 rng(seed);
  return draw_level_field(rel_sd, correlation_m, 0.6, rng);
}

// The correlation of an Ornstein-Uhlenbeck field made periodic over L with its mean over the
// period removed (no n = 0 term), the known answer the modes are drawn for: summing the
// Lorentzian weights 1 / (1 + (2 pi n l / L)^2) cos(2 pi n lag / L) over all integers n gives
// (L / 2l) cosh((L/2 - lag) / l) / sinh(L / 2l) (Poisson summation of exp(-|lag| / l)); the
// n = 0 term is 1 and n, -n are the one-sided sum twice.
double periodic_ou_correlation(double lag, double l, double L) {
  const double half = L / (2.0 * l);
  const auto all_n = [&](double d) { return half * std::cosh((L / 2.0 - d) / l) / std::sinh(half); };
  return (all_n(lag) - 1.0) / (all_n(0.0) - 1.0);
}

// The variance is the stated one exactly (the amplitudes are scaled to it), and the
// correlation at lags of one to three lengths is the periodic field's above, to 0.03: the
// spectrum's cutoff at k l = 16 moves it by less (1 - 2/pi atan 16 = 4 % of the variance,
// restored by the scaling).
TEST(LevelField, ItsModesGiveTheStatedVarianceAndAnExponentialCorrelation) {
  for (const double l : {0.002, 0.005, 0.02}) {
    const RandomLevelField f = field_of(0.05, l, 7);
    const double variance = level_field_covariance(f, 0.0);
    EXPECT_NEAR(variance, 0.05 * 0.05, 1e-15);
    for (const double lags : {1.0, 2.0, 3.0}) {
      EXPECT_NEAR(level_field_covariance(f, lags * l) / variance,
                  periodic_ou_correlation(lags * l, l, f.period_m), 0.03)
          << "l = " << l << ", lag " << lags << " l";
    }
  }
}

// One realisation along the bore: its sample mean, variance and lag-l correlation are those
// of the field within their sampling error over 600 mm / 5 mm = 120 correlation lengths.
TEST(LevelField, ARealisationAlongTheBoreHasTheFieldsStatistics) {
  const RandomLevelField f = field_of(0.05, 0.005, 11);
  const auto table = tabulate_level_field(f, -0.05);
  ASSERT_NE(table, nullptr);
  const int n = 6000;
  double sum = 0.0, square = 0.0, lagged = 0.0;
  for (int i = 0; i < n; ++i) {
    const double x = -0.05 + 0.6 * i / n, a = *table->at(x), b = *table->at(x + 0.005);
    sum += a;
    square += a * a;
    lagged += a * b;
  }
  EXPECT_NEAR(sum / n, 0.0, 1e-12);  // no n = 0 mode: the mean over the period is zero
  EXPECT_NEAR(square / n, 0.05 * 0.05, 0.05 * 0.05 * 0.02);  // the exact variance, sampled
  EXPECT_NEAR(lagged / square, std::exp(-1.0), 0.15);  // about 1 / sqrt(60) of sampling error
}

// The table (an inverse FFT) against the field's sines, within the cubic Hermite bound at
// 32 nodes per shortest wavelength, (2 pi / 32)^4 / 384 sum |a|, and repeating every period.
TEST(LevelField, TheTableIsTheSinesWithinTheHermiteBoundAndRepeats) {
  const RandomLevelField f = field_of(0.08, 0.003, 3);
  const auto table = tabulate_level_field(f, -0.05);
  double amplitude_sum = 0.0;
  for (const TextureMode& m : f.modes) amplitude_sum += std::abs(m.amplitude);
  const double bound = std::pow(2.0 * std::numbers::pi / 32.0, 4) / 384.0 * amplitude_sum;
  double worst = 0.0, low = 1.0;
  for (int i = 0; i <= 50000; ++i) {
    const double x = -0.05 + 0.6 * i / 50000.0;
    double sines = 0.0;
    for (const TextureMode& m : f.modes) sines += m.amplitude * std::sin(m.wavenumber_per_m * x + m.phase);
    worst = std::max(worst, std::abs(*table->at(x) - sines));
    low = std::min(low, *table->at(x));
    EXPECT_NEAR(*table->at(x + 0.6), *table->at(x), 1e-12) << x;
    EXPECT_NEAR(*table->at(x - 1.2), *table->at(x), 1e-12) << x;
  }
  // A position a rounding error below the table's start wraps to its start, not past its end.
  const std::optional<double> below = table->at(std::nextafter(-0.05, -1.0));
  ASSERT_TRUE(below.has_value());
  EXPECT_NEAR(*below, *table->at(-0.05), 1e-12);
  EXPECT_LE(worst, bound);
  EXPECT_GT(worst, 0.0);
  EXPECT_LE(table->lowest(), low);  // lowest() bounds the interpolant from below
  EXPECT_GT(table->lowest(), low - 0.05);
}

// The field draws from a stream of its own: the scatter and the texture are the same with
// or without it; the same seed gives the same field, another seed another.
TEST(LevelField, ItsOwnStreamLeavesTheOtherDrawsAlone) {
  const Scenario base = build_scenario(
      "", {"variation.friction_rel_sd=0.03", "variation.texture_rel=0.05"});
  Scenario noisy = base;
  noisy.variation.seal_noise_rel = 0.05;
  const Scenario a = vary(base, run_seed(1, 2, 3)), b = vary(noisy, run_seed(1, 2, 3));
  EXPECT_EQ(a.friction.curve.coulomb_N, b.friction.curve.coulomb_N);
  ASSERT_EQ(a.friction.texture.size(), b.friction.texture.size());
  EXPECT_EQ(a.friction.texture[2].phase, b.friction.texture[2].phase);
  EXPECT_TRUE(a.friction.level_field.modes.empty());
  ASSERT_FALSE(b.friction.level_field.modes.empty());
  EXPECT_TRUE(b.load.guide_friction.level_field.modes.empty());  // the seal's, not the guide's
  EXPECT_EQ(vary(noisy, run_seed(1, 2, 3)).friction.level_field.modes[5].phase,
            b.friction.level_field.modes[5].phase);
  EXPECT_NE(vary(noisy, run_seed(1, 2, 4)).friction.level_field.modes[5].phase,
            b.friction.level_field.modes[5].phase);
}

// A field that would take the seal's friction to zero somewhere is refused, naming its key.
TEST(LevelField, AFieldThatCancelsTheFrictionIsRefusedNamingItsKey) {
  Scenario s = simple_rig_scenario();
  s.friction.level_field = {{{1.2, 2.0 * std::numbers::pi / 0.6, 0.0}}, 0.6};
  try {
    const Plant plant(s);
    FAIL() << "a level reaching -20 % of the friction was accepted";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("variation.seal_noise_rel"), std::string::npos);
  }
  s.friction.level_field.modes[0].amplitude = 0.5;
  EXPECT_NO_THROW(Plant{s});
}

// Sliding over the random bore: the run converges with the tolerance (the default tolerances
// against tight ones differ by far less than the field moves the velocity), and the field
// does move it.
TEST(LevelField, RunsThroughTheFieldConvergeWithTheTolerance) {
  Scenario s = simple_rig_scenario();
  s.circuit.S2_m2 = 0.9e-6;  // steady sliding without the field
  s.variation.seal_noise_rel = 0.05;
  s.variation.seal_noise_correlation_m = 0.005;
  const Scenario rough = vary(s, run_seed(2, 0, 0));
  RunParams loose = s.run;
  loose.duration_s = 3.0;
  const auto r = simulate(Plant(rough), loose), tight_run = simulate(Plant(rough), tight(3.0));
  const auto smooth = simulate(Plant(s), loose);
  const double error = largest_velocity_difference(r, tight_run);
  const double effect = largest_velocity_difference(r, smooth);
  EXPECT_LT(error, 1e-3 * effect) << "error " << error << " effect " << effect;
  EXPECT_GT(effect, 1e-3);  // over 1 mm/s of velocity from a 5 % level field
}

}  // namespace
}  // namespace pneumachaos
