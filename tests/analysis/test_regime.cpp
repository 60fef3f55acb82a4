// The regime verdict on records whose regime is known.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include <nlohmann/json.hpp>

#include "pneumachaos/analysis/analysis_output.hpp"
#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/analysis/regime.hpp"
#include "pneumachaos/core/error.hpp"
#include "support/reference_series.hpp"

namespace pneumachaos {
namespace {

using namespace pneumachaos::testing;

TEST(Regime, SineSineWithNoiseAndWhiteNoiseAreNeverChaotic) {
  for (double noise : {0.0, 0.05, 0.2}) {
    const AnalysisResult r = analyze_series(sine(10000, 10.0, 1000.0, noise), 1000.0);
    EXPECT_FALSE(r.verdict.chaotic) << "noise " << noise;
    EXPECT_NE(r.verdict.regime, Regime::kChaotic);
  }
  const AnalysisResult n = analyze_series(white_noise(10000), 1000.0);
  EXPECT_FALSE(n.verdict.chaotic);
  // Wolf's program reads white noise at ~300 /s (as docs/notes/analysis.md notes of the
  // peers); it is not run on a record whose neighbours predict no better than a linear rule.
  EXPECT_FALSE(n.wolf_run);
  EXPECT_NE(n.wolf_status.find("not run: no deterministic structure"), std::string::npos);
  EXPECT_GE(n.prediction.ratio(), 1.0);
  EXPECT_TRUE(analyze_series(lorenz_x(10000), 100.0).wolf_run);
  const AnalysisResult s = analyze_series(sine(10000, 10.0, 1000.0), 1000.0);
  EXPECT_EQ(s.verdict.regime, Regime::kPeriodic);
}

TEST(Regime, ChaoticReferencesAreChaotic) {
  EXPECT_TRUE(analyze_series(logistic_map(10000), 1.0).verdict.chaotic);
  EXPECT_TRUE(analyze_series(henon_map(10000), 1.0).verdict.chaotic);
  EXPECT_TRUE(analyze_series(lorenz_x(10000), 100.0).verdict.chaotic);
}

TEST(Regime, PhaseCoherentChaosIsChaotic) {
  // Rossler's autocorrelation barely decays within the record; it does not veto chaos: the
  // exponent, the 0-1 test and the prediction errors decide (docs/notes/analysis.md).
  const AnalysisResult r = analyze_series(rossler_x(10000), 10.0);
  EXPECT_TRUE(r.verdict.chaotic);
  EXPECT_EQ(r.verdict.regime, Regime::kChaotic);
  EXPECT_GT(r.divergence.lambda_per_s, 3.0 * r.divergence.uncertainty_per_s);
  EXPECT_GT(r.evidence.late_acf, 0.5);  // a late-ACF veto would fire
}

TEST(Regime, ShortLorenzIsNeverPeriodic) {
  // 1,000 samples (10 time units): too short for the 0-1 test and a linear region.
  const AnalysisResult r = analyze_series(lorenz_x(1000), 100.0);
  EXPECT_NE(r.verdict.regime, Regime::kPeriodic);
  EXPECT_NE(r.verdict.regime, Regime::kQuasiPeriodic);
}

// A velocity that rests at exactly zero for 40 % of each 0.5 s cycle, then a half sine
// (10,000 samples at 1 kHz).
std::vector<double> resting_half_sines() {
  std::vector<double> ss(10000);
  for (std::size_t i = 0; i < ss.size(); ++i) {
    const double phase = std::fmod(2.0 * static_cast<double>(i) / 1000.0, 1.0);
    ss[i] = phase < 0.4 ? 0.0 : 0.1 * std::sin((phase - 0.4) / 0.6 * std::numbers::pi);
  }
  return ss;
}

TEST(Regime, StickSlipAndSteadyRecords) {
  const std::vector<double> ss = resting_half_sines();
  const AnalysisResult s = analyze_series(ss, 1000.0);
  EXPECT_TRUE(s.verdict.stick_slip);
  EXPECT_EQ(s.verdict.regime, Regime::kStickSlip);
  EXPECT_NEAR(s.evidence.rest_share, 0.4, 0.01);

  std::vector<double> damped(10000);
  for (std::size_t i = 0; i < damped.size(); ++i) {
    const double t = static_cast<double>(i);
    damped[i] = 0.066 + 0.02 * std::exp(-t / 300.0) * std::cos(0.05 * t);
  }
  const AnalysisResult d = analyze_series(damped, 1000.0);
  EXPECT_EQ(d.verdict.regime, Regime::kSteady);
  EXPECT_FALSE(d.verdict.stick_slip);
}

// Low-passed Gaussian noise, cubed: it lingers flat at zero on each passage.
std::vector<double> cubed_lowpassed_noise() {
  std::mt19937_64 rng(3);
  std::normal_distribution<double> gauss;
  std::vector<double> cubed(10000);
  double y = 0.0;
  for (double& c : cubed) {
    y = 0.98 * y + gauss(rng);
    c = y * y * y;
  }
  return cubed;
}

// A rest is a run at zero velocity, not any flat stretch near zero of any signal: cubed
// low-passed Gaussian noise lingers flat at zero on each passage (d(x^3)/dt = 3 x^2 dx/dt),
// which read as rests. As a velocity it may be cut into rests; as what it is, another
// quantity, it is not judged for stick-slip, nor is the stick-slip record read as one.
TEST(Regime, RestsAreJudgedOnVelocitiesOnly) {
  const std::vector<double> cubed = cubed_lowpassed_noise();
  AnalysisOptions as_velocity;
  as_velocity.wolf = false;
  AnalysisOptions as_other = as_velocity;
  as_other.velocity = false;
  EXPECT_GT(analyze_series(cubed, 1000.0, as_velocity).evidence.rest_intervals, 0u);
  const AnalysisResult other = analyze_series(cubed, 1000.0, as_other);
  EXPECT_FALSE(other.verdict.stick_slip);
  EXPECT_NE(other.verdict.regime, Regime::kStickSlip);
  EXPECT_FALSE(other.evidence.rests_judged);
  EXPECT_EQ(other.evidence.rest_intervals, 0u);
  bool said = false;
  for (const std::string& line : other.verdict.evidence)
    said = said || line.find("stick-slip: not judged") != std::string::npos;
  EXPECT_TRUE(said);

  const std::vector<double> ss = resting_half_sines();
  EXPECT_TRUE(analyze_series(ss, 1000.0, as_velocity).verdict.stick_slip);
  EXPECT_FALSE(analyze_series(ss, 1000.0, as_other).verdict.stick_slip);
}

std::string evidence_text(const Verdict& v) {
  std::string all;
  for (const auto& line : v.evidence) all += line + "\n";
  return all;
}

// Read as a velocity, the same cubed noise has its "rests". IAAFT surrogates keep a record's
// values and spectrum, so they linger near zero as often; a record no more predictable than
// they are is a linear process seen through a static transform (the surrogates' null, which
// cubed low-passed noise is), and its rests are passages through zero: stochastic, not
// stick-slip. Without surrogates that cannot be told; a stick-slip record, noisy, keeps its
// verdict with them (its rests beat the surrogates' shuffled ones).
TEST(Regime, RestsOfNoiseThroughAStaticTransformAreNoStickSlip) {
  const std::vector<double> cubed = cubed_lowpassed_noise();
  std::mt19937_64 rng(4);
  std::normal_distribution<double> gauss;
  AnalysisOptions with_surrogates;
  with_surrogates.wolf = false;
  with_surrogates.surrogates.count = 39;
  const AnalysisResult noise = analyze_series(cubed, 1000.0, with_surrogates);
  ASSERT_GT(noise.evidence.rest_intervals, 2u);  // the rests are there
  EXPECT_EQ(noise.verdict.regime, Regime::kStochastic) << evidence_text(noise.verdict);
  EXPECT_FALSE(noise.verdict.stick_slip);

  AnalysisOptions without = with_surrogates;
  without.surrogates.count = 0;
  EXPECT_EQ(analyze_series(cubed, 1000.0, without).verdict.regime, Regime::kStickSlip);

  std::vector<double> ss = resting_half_sines();
  for (double& v : ss) v += 0.0002 * gauss(rng);  // a transducer's noise, 0.2 % of the peak
  const AnalysisResult stick = analyze_series(ss, 1000.0, with_surrogates);
  EXPECT_EQ(stick.verdict.regime, Regime::kStickSlip) << evidence_text(stick.verdict);
}

// Stick-slip whose slips follow a rule: each slip a half sine after a rest, the n-th slip's
// peak speed and duration set by slip_size(n) in [0, 1] (rest 40 % of a nominal 500-sample
// cycle, like the corpus's stick-slip record).
template <typename SlipSize>
std::vector<double> slips(std::size_t n, SlipSize slip_size) {
  std::vector<double> v;
  v.reserve(n);
  for (std::size_t k = 0; v.size() < n; ++k) {
    const double size = slip_size(k);
    v.insert(v.end(), 200, 0.0);
    const auto len = static_cast<std::size_t>(std::lround(200.0 + 200.0 * size));
    for (std::size_t i = 0; i < len; ++i) {
      v.push_back((0.05 + 0.1 * size) *
                  std::sin(std::numbers::pi * static_cast<double>(i) / static_cast<double>(len)));
    }
  }
  v.resize(n);
  return v;
}

TEST(Regime, PeriodTwoStickSlipIsNotChaotic) {
  // Slips alternate between two sizes: periodic stick-slip, period two cycles. Any evidence of
  // chaos between rests must leave it alone (docs/notes/analysis.md "Tried and not adopted":
  // chaos between rests from the 0-1 test).
  for (std::size_t n : {5000, 10000}) {
    const auto v = slips(n, [](std::size_t k) { return k % 2 == 0 ? 0.2 : 0.9; });
    const AnalysisResult r = analyze_series(v, 1000.0);
    EXPECT_TRUE(r.verdict.stick_slip) << n;
    EXPECT_FALSE(r.verdict.chaotic) << n;
    EXPECT_EQ(r.verdict.regime, Regime::kStickSlip) << n;
  }
}

TEST(Regime, StickSlipWithChaoticSlipsIsChaotic) {
  // The slips' sizes follow the logistic map x -> 4 x (1 - x) (Lyapunov exponent ln 2 per
  // slip): chaos in the slip sequence, rests between. Here the divergence curve does rise
  // (slips vary in length, so the rests do not line up); chaotic and stick-slip together.
  double x = 0.3;
  const auto v = slips(10000, [&x](std::size_t) { return x = 4.0 * x * (1.0 - x); });
  const AnalysisResult r = analyze_series(v, 1000.0);
  EXPECT_TRUE(r.verdict.stick_slip);
  EXPECT_TRUE(r.verdict.chaotic);
  EXPECT_EQ(r.verdict.regime, Regime::kChaotic);
}

TEST(Regime, TooShortOrNonFiniteSeriesIsAnError) {
  EXPECT_THROW(analyze_series(white_noise(150), 1000.0), Error);
  auto x = white_noise(1000);
  x[17] = std::nan("");
  EXPECT_THROW(analyze_series(x, 1000.0), Error);
  const AnalysisResult few = analyze_series(white_noise(500), 1000.0);
  EXPECT_EQ(few.verdict.regime, Regime::kUndetermined);  // below VerdictOptions::min_samples
}

// With no linear region there is no exponent, so its uncertainty is null too, whatever the
// estimator left in the fields (not the spread of placeholder zeros).
TEST(Regime, NoDivergenceValueMeansNoUncertainty) {
  std::vector<double> damped(10000);
  for (std::size_t i = 0; i < damped.size(); ++i) {
    const double t = static_cast<double>(i);
    damped[i] = 0.066 + 0.02 * std::exp(-t / 300.0) * std::cos(0.05 * t);
  }
  AnalysisResult d = analyze_series(damped, 1000.0);
  ASSERT_FALSE(d.divergence.found_linear_region);
  d.divergence.uncertainty_per_s = 0.5;  // whatever the estimator left there
  d.divergence.slope_uncertainty_per_s = 0.25;
  const auto j = nlohmann::json::parse(analysis_json(d, "rec.csv", "v", "m/s"));
  const auto& div = j["lyapunov"]["divergence"];
  EXPECT_TRUE(div["value"].is_null());
  EXPECT_TRUE(div["uncertainty"].is_null()) << div.dump();
  EXPECT_TRUE(div["slope_uncertainty"].is_null()) << div.dump();
}

// The evidence the verdict reads, irregular and not steady, the surrogate test run.
RegimeEvidence irregular_evidence() {
  RegimeEvidence e;
  e.samples = 5000;
  e.range = 2.0;
  e.last_half_std = 1.0;
  e.zero_one_run = true;
  e.zero_one_K = 0.9;
  e.zero_one_q25 = 0.85;
  e.zero_one_q75 = 0.95;
  e.prediction_computed = true;
  e.prediction_nonlinear = e.prediction_linear = 1.0;
  e.surrogate_run = true;
  e.surrogate_count = 39;
  return e;
}

// A record below every surrogate, better predicted locally than linearly, with the 0-1 test's K
// and quartiles given and the self-repetition test run.
RegimeEvidence deterministic_evidence(double K, double q25, double q75) {
  RegimeEvidence e = irregular_evidence();
  e.zero_one_K = K;
  e.zero_one_q25 = q25;
  e.zero_one_q75 = q75;
  e.surrogate_rejected = e.surrogate_more_predictable = true;
  e.prediction_nonlinear = 0.1;
  e.repetition.run = true;
  return e;
}

// The determinism line states where the record ranks among the surrogates: above all, above
// some, or below all; "below all N IAAFT surrogates" only when it is.
TEST(Regime, SurrogateEvidenceSaysWhereTheRecordRanks) {
  RegimeEvidence e = irregular_evidence();
  e.surrogate_rank = 39;  // every surrogate below the record: less predictable than all
  e.surrogate_rejected = true;
  const std::string above = evidence_text(decide_regime(e));
  EXPECT_NE(above.find("prediction error is above all 39 IAAFT surrogates (needs below all"),
            std::string::npos) << above;
  EXPECT_EQ(above.find("is below all"), std::string::npos) << above;
  e.surrogate_rank = 12;
  e.surrogate_rejected = false;
  EXPECT_NE(evidence_text(decide_regime(e)).find("is above 12 of 39 IAAFT surrogates"),
            std::string::npos);
  e.surrogate_rank = 0;
  e.surrogate_rejected = e.surrogate_more_predictable = true;
  EXPECT_NE(evidence_text(decide_regime(e)).find("is below all 39 IAAFT surrogates"),
            std::string::npos);
}

// "Stochastic" says what it means: no claim that the source is random (a noise-free simulated
// run can earn it).
TEST(Regime, StochasticSaysWhatItMeans) {
  RegimeEvidence e = irregular_evidence();
  e.surrogate_rank = 20;
  const Verdict v = decide_regime(e);
  ASSERT_EQ(v.regime, Regime::kStochastic);
  EXPECT_NE(evidence_text(v).find("it does not say the source is random"), std::string::npos);
}

// A sharp relaxation oscillator repeats itself over 90 % of its record while the 0-1
// test, misled by its sharp edges, reads K = 0.93; without a positive exponent a record that
// repeats itself is periodic whatever K says.
TEST(Regime, RepeatingRecordWithoutExponentIsPeriodicWhateverTheZeroOneTest) {
  RegimeEvidence e = deterministic_evidence(0.93, 0.9, 0.95);
  e.repetition.share = 0.9;
  e.repetition.repeats = true;
  EXPECT_EQ(decide_regime(e).regime, Regime::kPeriodic) << evidence_text(decide_regime(e));
  e.repetition.repeats = false;  // the same record without the repeat: not periodic
  EXPECT_NE(decide_regime(e).regime, Regime::kPeriodic);
  // ...and with a positive exponent the repeat has to veto it first (it does not here: the
  // mismatch grows at the exponent's rate), so the record stays chaotic.
  e.repetition.repeats = true;
  e.repetition.growth_per_s = 10.0;
  e.lyapunov_found = true;
  e.lyapunov_per_s = 5.0;
  e.lyapunov_slope_uncertainty_per_s = 0.5;
  EXPECT_EQ(decide_regime(e).regime, Regime::kChaotic);
}

// An Ornstein-Uhlenbeck record sampled at 1 kHz leaves the 0-1 test 28 points after
// down-sampling, too few to run. The surrogates keep the linear null, the predictor finds
// nothing, the spectrum is broadband and the autocorrelation dies: stochastic from that other
// evidence, not undetermined for want of the 0-1 test.
TEST(Regime, StochasticWithoutTheZeroOneTestFromTheOtherEvidence) {
  RegimeEvidence e = irregular_evidence();
  e.zero_one_run = false;
  e.zero_one_note = "not run: 28 points after down-sampling";
  e.surrogate_rank = 20;
  e.broadband_share = 0.8;
  e.late_acf = 0.05;
  EXPECT_EQ(decide_regime(e).regime, Regime::kStochastic) << evidence_text(decide_regime(e));
  e.surrogate_run = false;  // without the calibrated test against linear noise: not enough
  EXPECT_EQ(decide_regime(e).regime, Regime::kUndetermined);
  e.surrogate_run = true;
  e.late_acf = 0.8;  // a persisting autocorrelation is no noise's
  e.broadband_share = 0.1;
  EXPECT_NE(decide_regime(e).regime, Regime::kStochastic);
}

// dysts's BurkeShaw, Qi and WangSun are deterministic (below every surrogate), the 0-1 test
// reads K ~ 1, and their divergence curves rise all along without one straight stretch: with
// no linear region, everything else still says chaos. The rise counts where the spectrum is
// broadband, the autocorrelation dies and the 0-1 test supports it; not where the record
// repeats itself (a torus's curve also rises), has the lines and lasting autocorrelation of a
// noisy cycle, rests like stick-slip, or the 0-1 test reads it regular or did not run.
TEST(Regime, CurveRisingAllAlongWithoutAStraightStretchCountsWithTheZeroOneTest) {
  RegimeEvidence e = deterministic_evidence(0.998, 0.997, 0.999);
  e.repetition.share = 0.03;
  e.broadband_share = 0.6;
  e.late_acf = 0.04;
  e.rising_median_per_s = 2.0;
  e.rising_low_per_s = 1.46;
  const Verdict chaotic = decide_regime(e);
  EXPECT_EQ(chaotic.regime, Regime::kChaotic) << evidence_text(chaotic);
  EXPECT_NE(evidence_text(chaotic).find("[yes] a rise without a straight stretch"),
            std::string::npos);

  RegimeEvidence not_rising = e;
  not_rising.rising_low_per_s = -0.2;  // a tenth of its local slopes falls
  EXPECT_EQ(decide_regime(not_rising).regime, Regime::kUndetermined);

  RegimeEvidence torus = e;  // repeats over most of the record, the mismatch not growing
  torus.repetition.repeats = true;
  torus.repetition.share = 0.95;
  torus.repetition.growth_per_s = 0.0;
  EXPECT_EQ(decide_regime(torus).regime, Regime::kPeriodic) << evidence_text(decide_regime(torus));
  torus.repetition.growth_per_s = 3.0;  // a mismatch growing faster than the rise: no veto
  EXPECT_EQ(decide_regime(torus).regime, Regime::kChaotic);

  RegimeEvidence resting = e;  // 40 % of the time at rest in 30 rests
  resting.rest_intervals = 30;
  resting.rest_share = 0.4;
  EXPECT_EQ(decide_regime(resting).regime, Regime::kStickSlip);

  RegimeEvidence regular_K = e;
  regular_K.zero_one_K = 0.3;
  EXPECT_NE(decide_regime(regular_K).regime, Regime::kChaotic);
  RegimeEvidence no_zero_one = e;
  no_zero_one.zero_one_run = false;
  EXPECT_NE(decide_regime(no_zero_one).regime, Regime::kChaotic);

  RegimeEvidence noisy_cycle = e;  // lines in the spectrum, an autocorrelation that persists
  noisy_cycle.broadband_share = 0.05;
  noisy_cycle.late_acf = 0.8;
  EXPECT_NE(decide_regime(noisy_cycle).regime, Regime::kChaotic);
  noisy_cycle.late_acf = 0.04;  // either one alone withholds the rise
  EXPECT_NE(decide_regime(noisy_cycle).regime, Regime::kChaotic);
  noisy_cycle.broadband_share = 0.6;
  noisy_cycle.late_acf = 0.8;
  EXPECT_NE(decide_regime(noisy_cycle).regime, Regime::kChaotic);

  RegimeEvidence noise = e;  // no more predictable than the surrogates
  noise.surrogate_rejected = noise.surrogate_more_predictable = false;
  noise.surrogate_rank = 20;
  noise.prediction_nonlinear = 1.0;
  EXPECT_NE(decide_regime(noise).regime, Regime::kChaotic);
}

}  // namespace
}  // namespace pneumachaos

namespace pneumachaos {
namespace {

// A noisy cycle: its divergence curve finds a weak rise over a few orbits (the noise's phase
// diffusion), while the 0-1 test's upper quartile, the spectrum and the autocorrelation all
// read it regular: periodic. Take away any one of the three, or the noise, and the rise stands
// (not periodic).
TEST(Regime, ADivergenceEveryRegularitySignContradictsIsANoisyCyclesDiffusion) {
  RegimeEvidence e = deterministic_evidence(0.22, 0.13, 0.40);
  e.prediction_nonlinear = 0.64;  // not deterministic: the rise alone is the question
  e.surrogate_rejected = e.surrogate_more_predictable = false;
  e.lyapunov_found = true;
  e.lyapunov_per_s = 2.7;
  e.lyapunov_slope_uncertainty_per_s = 0.86;
  e.late_acf = 0.54;
  e.broadband_share = 0.02;
  e.noise_sd = 0.003;
  const Verdict v = decide_regime(e);
  EXPECT_EQ(v.regime, Regime::kPeriodic) << evidence_text(v);
  EXPECT_NE(evidence_text(v).find("phase diffusion"), std::string::npos);
  RegimeEvidence clean = e;  // no noise to diffuse: the rise stands
  clean.noise_sd = 0.0;
  EXPECT_NE(decide_regime(clean).regime, Regime::kPeriodic);
  RegimeEvidence broadband = e;
  broadband.broadband_share = 0.5;
  EXPECT_NE(decide_regime(broadband).regime, Regime::kPeriodic);
  RegimeEvidence dying = e;
  dying.late_acf = 0.2;
  EXPECT_NE(decide_regime(dying).regime, Regime::kPeriodic);
  RegimeEvidence spread_K = e;
  spread_K.zero_one_q75 = 0.6;
  EXPECT_NE(decide_regime(spread_K).regime, Regime::kPeriodic);
}

// The same noisy tone read whole: white noise of 10 % of its std adds 0.1 of the attractor's
// size to every window's mismatch, and the test of "small" is judged above it.
TEST(Regime, ANoisyToneStillRepeatsItself) {
  const auto x = sine(10000, 10.0, 1000.0, 0.1 * std::sqrt(0.5));
  const AnalysisResult r = analyze_series(x, 1000.0);
  ASSERT_GT(r.noise.sd, 0.0);
  EXPECT_TRUE(r.evidence.repetition.repeats) << evidence_text(r.verdict);
  EXPECT_GT(r.evidence.repetition.max_mismatch, VerdictOptions{}.repetition.max_mismatch);
  EXPECT_EQ(r.verdict.regime, Regime::kPeriodic);
}

}  // namespace
}  // namespace pneumachaos
