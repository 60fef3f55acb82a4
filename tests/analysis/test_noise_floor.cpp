// The record's white noise floor and the rests judged above it (docs/notes/analysis.md
// "Noise floor"): known noise levels are recovered, an oversampled clean signal shows none,
// and a noisy record keeps the stick-slip flag its clean record has, while a noisy
// oscillation through zero does not gain it.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "analysis/rests.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/analysis/noise_floor.hpp"
#include "pneumachaos/analysis/regime.hpp"

namespace pneumachaos {
namespace {

constexpr double kRate_Hz = 1000.0;
constexpr std::size_t kSamples = 10000;

std::vector<double> add_noise(std::vector<double> x, double sd, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, sd);
  for (double& v : x) v += n(rng);
  return x;
}

std::vector<double> tone(double f_Hz, double amplitude) {
  std::vector<double> x(kSamples);
  for (std::size_t i = 0; i < x.size(); ++i) {
    x[i] = amplitude * std::sin(2.0 * std::numbers::pi * f_Hz * static_cast<double>(i) / kRate_Hz);
  }
  return x;
}

// A stick-slip-like velocity: slips of a half sine, each followed by a rest of equal length
// at exactly zero (5 Hz: 100 ms of slip, 100 ms of rest).
std::vector<double> slips_and_rests(double amplitude) {
  std::vector<double> x = tone(5.0, amplitude);
  for (double& v : x) v = std::max(v, 0.0);
  return x;
}

RegimeEvidence rests_of(const std::vector<double>& x) {
  RegimeEvidence e;
  rest_statistics(x, VerdictOptions{}, estimate_noise_floor(x).sd, e);
  return e;
}

// The MAD's sd is about 1.1 / sqrt(N) of its value for normal data (N = 1e4: ~1 %); the
// highest order's differences overlap five samples each, so allow 5 %.
constexpr double kNoiseTolerance = 0.05;

TEST(NoiseFloor, RecoversWhiteNoiseOnAnOscillationAndSaysWhenItIsAllThereIs) {
  for (const double sd : {0.01, 0.3, 2.0}) {
    // Noise alone: white at every scale, but nothing above it to judge: not separated.
    const NoiseFloor alone = estimate_noise_floor(add_noise(std::vector<double>(kSamples), sd, 3));
    EXPECT_TRUE(alone.dominates) << sd;
    EXPECT_FALSE(alone.resolved) << sd;
    EXPECT_EQ(alone.sd, 0.0);
    EXPECT_NEAR(alone.bound, sd, kNoiseTolerance * sd);
    const NoiseFloor on_tone = estimate_noise_floor(add_noise(tone(10.0, 100.0 * sd), sd, 4));
    EXPECT_TRUE(on_tone.resolved) << sd;
    EXPECT_NEAR(on_tone.sd, sd, kNoiseTolerance * sd);
  }
}

TEST(NoiseFloor, AnOversampledCleanSignalHasNone) {
  const NoiseFloor f = estimate_noise_floor(tone(10.0, 1.0));
  EXPECT_FALSE(f.resolved);
  EXPECT_EQ(f.sd, 0.0);
  // (2 pi 10 / 1000)^5 / sqrt(252) of the amplitude, and falling with every order.
  EXPECT_LT(f.bound, 1e-6);
  for (std::size_t k = 1; k < f.by_order.size(); ++k) EXPECT_LT(f.by_order[k], f.by_order[k - 1]);
}

TEST(NoiseFloor, NoisyRestsKeepTheStickSlipFlag) {
  const double amplitude = 0.3;
  const RegimeEvidence clean = rests_of(slips_and_rests(amplitude));
  ASSERT_TRUE(rests_like_stick_slip(clean));
  for (const double relative : {0.005, 0.01, 0.02}) {
    const auto noisy = add_noise(slips_and_rests(amplitude), relative * amplitude, 5);
    const RegimeEvidence e = rests_of(noisy);
    EXPECT_TRUE(rests_like_stick_slip(e)) << "noise " << relative << " of the swing";
    // Half the record rests; the band widened by the noise takes in the slips' ends too.
    EXPECT_GT(e.rest_share, 0.4) << relative;
    EXPECT_LT(e.rest_share, 0.65) << relative;
  }
}

// Slips of a half sine of 48 samples, each followed by a rest of 12 samples at zero: rests
// shorter than the 20-sample window the noisy rule smooths over.
std::vector<double> short_rests(double amplitude) {
  constexpr std::size_t kSlip = 48, kRest = 12;
  std::vector<double> x(kSamples, 0.0);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const std::size_t phase = i % (kSlip + kRest);
    if (phase < kSlip) {
      x[i] = amplitude * std::sin(std::numbers::pi * static_cast<double>(phase) / kSlip);
    }
  }
  return x;
}

TEST(NoiseFloor, RestsShorterThanTheWindowKeepTheFlag) {
  // A running mean over 20 samples of a 12-sample rest between two slips takes in 8 slip
  // samples and leaves the band; the running median stays at the rest while it fills more
  // than half the window. The rig's stick-slip at S2 = 0.2 mm^2 rests 5-19 samples at a time.
  const double amplitude = 0.15;
  ASSERT_TRUE(rests_like_stick_slip(rests_of(short_rests(amplitude))));
  for (const double relative : {0.005, 0.01, 0.02}) {
    const RegimeEvidence e = rests_of(add_noise(short_rests(amplitude), relative * amplitude, 11));
    ASSERT_GT(e.rest_noise_sd, 0.0) << "the premise: the noisy rule applies";
    EXPECT_TRUE(rests_like_stick_slip(e)) << "noise " << relative << " of the swing";
  }
}

TEST(NoiseFloor, RestsAreNotJudgedWhereTheNoiseFillsTheBand) {
  // A stick-slip record whose noise is half its swing: the band on the running median over 20
  // samples, 1 % of max|x| + 3.5 x 1.25 x the noise / sqrt(20), exceeds a tenth of max|x| (itself
  // widened by the noise), where white noise alone would "rest" all the time.
  const auto x = add_noise(slips_and_rests(0.3), 0.5 * 0.3, 5);
  RegimeEvidence e;
  rest_statistics(x, VerdictOptions{}, 0.5 * 0.3, e);
  EXPECT_FALSE(e.rests_above_noise);
  EXPECT_GT(e.rest_level, VerdictOptions{}.max_rest_band * 0.3);
}

TEST(NoiseFloor, TheRunningMeanKeepsTheRestsWhoseEdgesRamp) {
  // Rests entered and left along a slow ramp (a 1 Hz half sine, 0.3 m/s: the first and last
  // few ms of every slip lie inside the noisy band): a run that took in the ramps would fail
  // the trend test; on the running median the runs end where the ramps leave the narrower band.
  std::vector<double> x(kSamples);
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double phase = std::fmod(static_cast<double>(i) / kRate_Hz, 1.0);
    x[i] = phase < 0.5 ? 0.3 * std::sin(2.0 * std::numbers::pi * phase) : 0.0;
  }
  const RegimeEvidence e = rests_of(add_noise(x, 0.02 * 0.3, 7));
  EXPECT_TRUE(rests_like_stick_slip(e));
  EXPECT_GT(e.rest_share, 0.45);
}

TEST(NoiseFloor, WhiteNoiseReadAsAVelocityDoesNotRest) {
  for (const unsigned seed : {8u, 9u, 10u}) {
    EXPECT_FALSE(rests_like_stick_slip(rests_of(add_noise(std::vector<double>(kSamples), 1.0, seed))));
  }
}

TEST(NoiseFloor, ANoisyOscillationThroughZeroDoesNotRest) {
  for (const double f_Hz : {1.0, 5.0, 20.0}) {
    for (const double relative : {0.005, 0.01, 0.02, 0.03}) {
      // Swing 2 x amplitude: the noise is `relative` of the swing.
      const auto x = add_noise(tone(f_Hz, 0.1), relative * 0.2, 6);
      const RegimeEvidence e = rests_of(x);
      EXPECT_FALSE(rests_like_stick_slip(e)) << f_Hz << " Hz, noise " << relative << ": "
                                             << e.rest_intervals << " rests, " << e.rest_share;
    }
  }
}

TEST(NoiseFloor, TheNoiseConditionsAreWhatRejectThePassages) {
  // A slow tone (0.1 Hz over 40 s) creeps through the clean band: the clean rule counts
  // 0.6 % of it at rest. With noise of 1 % of its swing the rule on the running median counts
  // about as much; with the trend and the RMS conditions made toothless it counts the noisy
  // passages through the wider band too, more than twice as much, which is why the
  // conditions are there.
  std::vector<double> slow(4 * kSamples);
  for (std::size_t i = 0; i < slow.size(); ++i) {
    slow[i] = 0.1 * std::sin(2.0 * std::numbers::pi * 0.1 * static_cast<double>(i) / kRate_Hz);
  }
  RegimeEvidence clean;
  rest_statistics(slow, VerdictOptions{}, 0.0, clean);
  ASSERT_GT(clean.rest_share, 0.0);
  const auto x = add_noise(slow, 0.01 * 0.2, 6);
  const double noise_sd = estimate_noise_floor(x).sd;
  RegimeEvidence e;
  rest_statistics(x, VerdictOptions{}, noise_sd, e);
  EXPECT_NEAR(e.rest_share, clean.rest_share, 0.3 * clean.rest_share);
  VerdictOptions loose;
  loose.rest_trend_sigmas = 1e6;
  loose.rest_max_rms = 1e6;
  rest_statistics(x, loose, noise_sd, e);
  EXPECT_GT(e.rest_share, 2.0 * clean.rest_share);
}

// An AR(1) process x' = 0.99 x + e read as a velocity: a noise-driven motion whose
// innovations the noise floor takes for measurement noise, lingering near zero for a few
// samples at a time.
std::vector<double> ar1(double a, unsigned seed) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> n(0.0, 1.0);
  std::vector<double> x(kSamples + 1000, 0.0);
  for (std::size_t i = 1; i < x.size(); ++i) x[i] = a * x[i - 1] + n(rng);
  return {x.begin() + 1000, x.end()};
}

TEST(NoiseFloor, ANoiseDrivenWanderThroughZeroDoesNotRest) {
  for (const unsigned seed : {1u, 2u, 3u}) {
    const auto x = ar1(0.99, seed);
    ASSERT_TRUE(estimate_noise_floor(x).resolved) << "the premise: its innovations read as noise";
    EXPECT_FALSE(rests_like_stick_slip(rests_of(x))) << seed;
  }
  // With the band judged on the raw samples (a window of one), its passages read as rests.
  VerdictOptions short_rests;
  short_rests.rest_window_in_noise = 1;
  const auto x = ar1(0.99, 1);
  RegimeEvidence e;
  rest_statistics(x, short_rests, estimate_noise_floor(x).sd, e);
  EXPECT_GT(e.rest_intervals, 2u);
}

}  // namespace
}  // namespace pneumachaos

namespace pneumachaos {
namespace {

TEST(NoiseFloor, MaximaAboveTheNoiseSpaceAtTheOrbit) {
  // A 10 Hz tone at 1 kHz (100 samples an orbit) with white noise of 0.2: the quarter-std
  // hysteresis (0.18) counts the noise's wiggles as maxima; six noise sd do not.
  const auto x = add_noise(tone(10.0, 1.0), 0.2, 11);
  EXPECT_LT(mean_maxima_spacing(x), 50.0);
  EXPECT_NEAR(mean_maxima_spacing(x, 0.2), 100.0, 2.0);
}

}  // namespace
}  // namespace pneumachaos
