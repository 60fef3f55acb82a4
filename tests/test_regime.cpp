// The regime verdict on records whose regime is known.
#include <gtest/gtest.h>

#include <cmath>
#include <cstdint>
#include <span>
#include <string>
#include <numbers>
#include <vector>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/core/error.hpp"
#include "reference_series.hpp"

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
  // Wolf's program reads white noise at ~300 /s (as docs/analysis.md notes of the peers); it is
  // no longer run on a record whose neighbours predict no better than a linear rule.
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
  // Rossler's autocorrelation barely decays within the record; it no longer vetoes: the
  // exponent, the 0-1 test and the prediction errors decide (docs/analysis.md).
  const AnalysisResult r = analyze_series(rossler_x(10000), 10.0);
  EXPECT_TRUE(r.verdict.chaotic);
  EXPECT_EQ(r.verdict.regime, Regime::kChaotic);
  EXPECT_GT(r.divergence.lambda_per_s, 3.0 * r.divergence.uncertainty_per_s);
  EXPECT_GT(r.evidence.late_acf, 0.5);  // the old veto's criterion would still fire
}

TEST(Regime, ShortLorenzIsNeverPeriodic) {
  // 1,000 samples (10 time units): too short for the 0-1 test and a linear region.
  const AnalysisResult r = analyze_series(lorenz_x(1000), 100.0);
  EXPECT_NE(r.verdict.regime, Regime::kPeriodic);
  EXPECT_NE(r.verdict.regime, Regime::kQuasiPeriodic);
}

TEST(Regime, StickSlipAndSteadyRecords) {
  // A velocity that rests at exactly zero for 40 % of each 0.5 s cycle, then a half sine.
  std::vector<double> ss(10000);
  for (std::size_t i = 0; i < ss.size(); ++i) {
    const double phase = std::fmod(2.0 * static_cast<double>(i) / 1000.0, 1.0);
    ss[i] = phase < 0.4 ? 0.0 : 0.1 * std::sin((phase - 0.4) / 0.6 * std::numbers::pi);
  }
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
  // chaos between rests must leave it alone (docs/analysis.md "Tried and not adopted: chaos
  // between rests from the 0-1 test").
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

// The evidence of a stick-slip record whose divergence curve found no linear region (the
// rests fill the embedding): only the slip sequence can make it chaotic.
RegimeEvidence stick_slip_without_divergence() {
  RegimeEvidence e;
  e.samples = 10000;
  e.range = 1.0;
  e.last_half_std = 0.3;
  e.rest_intervals = 40;
  e.rest_share = 0.3;
  e.lyapunov_found = false;
  e.zero_one_run = true;
  e.zero_one_K = e.zero_one_q25 = e.zero_one_q75 = 0.99;
  e.prediction_computed = true;
  e.prediction_nonlinear = 0.2;
  e.prediction_linear = 1.0;
  return e;
}

TEST(Regime, ChaoticSlipSequenceDecidesOnlyWithoutADivergenceRegion) {
  RegimeEvidence e = stick_slip_without_divergence();
  double x = 0.3;
  std::vector<double> logistic(60);
  for (double& s : logistic) s = x = 4.0 * x * (1.0 - x);
  e.slips = slip_sequence_test(logistic);
  ASSERT_TRUE(e.slips.chaotic);
  const Verdict chaotic = decide_regime(e);
  EXPECT_EQ(chaotic.regime, Regime::kChaotic);
  EXPECT_TRUE(chaotic.chaotic);
  EXPECT_TRUE(chaotic.stick_slip);
  // With a divergence region the curve decides (here: not above 3 sigma), not the slips.
  e.lyapunov_found = true;
  e.lyapunov_per_s = 0.5;
  e.lyapunov_slope_uncertainty_per_s = 0.5;
  EXPECT_EQ(decide_regime(e).regime, Regime::kStickSlip);
  // Without rests there are no slips to speak of.
  e = stick_slip_without_divergence();
  e.slips = slip_sequence_test(logistic);
  e.rest_intervals = 0;
  e.rest_share = 0.0;
  EXPECT_FALSE(decide_regime(e).chaotic);
  // Too few slips: the test says so and the record stays stick-slip.
  e = stick_slip_without_divergence();
  e.slips = slip_sequence_test(std::span<const double>(logistic).first(12));
  const Verdict few = decide_regime(e);
  EXPECT_EQ(few.regime, Regime::kStickSlip);
  bool said = false;
  for (const std::string& line : few.evidence) {
    said = said || line.find("slip sequence: not run: 12 slips") != std::string::npos;
  }
  EXPECT_TRUE(said);
}

TEST(Regime, SlipSequenceOfRecordsWithManySlips) {
  // Short slips (the slips() generator scaled down: rest 40 samples, slip 60 .. 120), ~75 in
  // 10,000 samples. Logistic slips: chaotic (by the divergence curve or the slips); period 2
  // and i.i.d. slips: not chaotic, whatever route the verdict takes.
  const auto record = [](auto size) {
    std::vector<double> v;
    for (std::size_t k = 0; v.size() < 10000; ++k) {
      const double s = size(k);
      v.insert(v.end(), 40, 0.0);
      const auto len = static_cast<std::size_t>(std::lround(60.0 + 60.0 * s));
      for (std::size_t i = 0; i < len; ++i) {
        v.push_back((0.05 + 0.1 * s) * std::sin(std::numbers::pi * static_cast<double>(i) /
                                                static_cast<double>(len)));
      }
    }
    v.resize(10000);
    return analyze_series(v, 1000.0);
  };
  double x = 0.3;
  const AnalysisResult c = record([&x](std::size_t) { return x = 4.0 * x * (1.0 - x); });
  EXPECT_TRUE(c.verdict.stick_slip);
  EXPECT_TRUE(c.verdict.chaotic);
  EXPECT_TRUE(c.evidence.slips.run);
  EXPECT_TRUE(c.evidence.slips.chaotic);
  const AnalysisResult p = record([](std::size_t k) { return k % 2 == 0 ? 0.2 : 0.9; });
  EXPECT_EQ(p.verdict.regime, Regime::kStickSlip);
  EXPECT_TRUE(p.evidence.slips.repeats);
  std::uint64_t state = 12345;
  const AnalysisResult n = record([&state](std::size_t) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;  // Knuth's MMIX LCG
    return static_cast<double>(state >> 11) * 0x1.0p-53;
  });
  EXPECT_TRUE(n.verdict.stick_slip);
  EXPECT_FALSE(n.evidence.slips.chaotic);
  EXPECT_FALSE(n.verdict.chaotic);
}

TEST(Regime, TooShortOrNonFiniteSeriesIsAnError) {
  EXPECT_THROW(analyze_series(white_noise(150), 1000.0), Error);
  auto x = white_noise(1000);
  x[17] = std::nan("");
  EXPECT_THROW(analyze_series(x, 1000.0), Error);
  const AnalysisResult few = analyze_series(white_noise(500), 1000.0);
  EXPECT_EQ(few.verdict.regime, Regime::kUndetermined);  // below VerdictOptions::min_samples
}

}  // namespace
}  // namespace pneumachaos
