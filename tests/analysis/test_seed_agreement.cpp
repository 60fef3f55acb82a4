// The verdict across the seeds of its random tests (the 0-1 test's frequencies, the
// surrogates): decided again where one of them could turn it, reported with the tally.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <random>
#include <string>
#include <vector>

#include "analysis/seed_agreement.hpp"
#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/core/error.hpp"
#include "support/reference_series.hpp"

namespace pneumachaos {
namespace {

// Two incommensurate tones in white noise: at a noise level around a quarter of the first
// tone's amplitude the 0-1 test's K sits near its split, and whether the record reads
// quasi-periodic or stochastic depends on the frequencies the seed draws.
std::vector<double> tones_in_noise(double noise) {
  std::mt19937_64 rng(5);
  std::normal_distribution<double> gauss;
  std::vector<double> x(5000);
  const double ratio = 3.1 * (std::sqrt(5.0) - 1.0) / 2.0;
  for (std::size_t i = 0; i < x.size(); ++i) {
    const double t = 0.21 * static_cast<double>(i);
    x[i] = std::sin(t) + 0.7 * std::sin(ratio * t) + noise * gauss(rng);
  }
  return x;
}

AnalysisOptions quick(std::uint64_t seed, std::size_t verdict_seeds) {
  AnalysisOptions o;
  o.wolf = false;
  o.seed = seed;
  o.verdict_seeds = verdict_seeds;
  return o;
}

// Each seed's regime is what the analysis on that seed alone gives, the reported regime is
// the majority's, and a flip is said in the evidence; over a range of noise levels at least
// one record flips (else this test shows nothing).
TEST(SeedAgreement, AFlippingVerdictIsReportedAsTheMajorityWithItsTally) {
  std::size_t flipping = 0;
  for (double noise : {0.22, 0.25, 0.28, 0.31}) {
    const std::vector<double> x = tones_in_noise(noise);
    const AnalysisResult r = analyze_series(x, 10.0, quick(1, 5));
    const SeedAgreement& a = r.seed_agreement;
    ASSERT_EQ(a.regimes.size(), a.seeds) << "noise " << noise;
    if (a.seeds == 1) continue;
    for (std::size_t k = 0; k < a.seeds; ++k) {
      EXPECT_EQ(a.regimes[k], analyze_series(x, 10.0, quick(1 + k, 1)).verdict.regime)
          << "noise " << noise << ", seed " << 1 + k;
    }
    const auto n = static_cast<std::size_t>(
        std::count(a.regimes.begin(), a.regimes.end(), r.verdict.regime));
    EXPECT_EQ(n, a.agreeing);
    EXPECT_GT(2 * n, a.seeds) << "noise " << noise;
    const std::string& last = r.verdict.evidence.back();
    if (n < a.seeds) {
      ++flipping;
      EXPECT_NE(last.find("flips with the seed"), std::string::npos) << last;
      // The numbers shown are those of a seed that gave the reported regime.
      EXPECT_EQ(decide_regime(r.evidence).regime, r.verdict.regime);
    } else {
      EXPECT_NE(last.find("on all 5 seeds"), std::string::npos) << last;
    }
  }
  EXPECT_GE(flipping, 1u);
}

TEST(SeedAgreement, OneSeedWhenNoRandomTestCouldTurnTheVerdict) {
  // A pure tone repeats itself: periodic whatever the 0-1 test says.
  const AnalysisResult r =
      analyze_series(testing::sine(10000, 10.0, 1000.0), 1000.0, quick(1, 5));
  EXPECT_EQ(r.verdict.regime, Regime::kPeriodic);
  EXPECT_EQ(r.seed_agreement.seeds, 1u);
  EXPECT_FALSE(r.seed_agreement.zero_one_rerun);
  EXPECT_FALSE(r.seed_agreement.surrogates_rerun);
}

// The chance that 39 new surrogates all lie above the record, for normal statistics:
// (1 - Phi(z))^39 at the record's z-score; its complement when they all did.
TEST(SeedAgreement, SurrogateFlipProbabilityIsTheNormalTailOverTheSurrogates) {
  SurrogateTest s;
  s.run = true;
  std::vector<double> v(39);
  for (std::size_t i = 0; i < v.size(); ++i) v[i] = 1.0 + 0.1 * std::sin(0.7 * static_cast<double>(i));
  s.surrogate_statistics = v;
  double mean = 0.0, var = 0.0;
  for (double u : v) mean += u / 39.0;
  for (double u : v) var += (u - mean) * (u - mean) / 38.0;
  const auto all_above = [&](double r) {
    const double z = (r - mean) / std::sqrt(var);
    return std::pow(1.0 - 0.5 * std::erfc(-z / std::sqrt(2.0)), 39.0);
  };
  s.statistic = 0.6;
  s.more_predictable = true;
  EXPECT_NEAR(surrogate_flip_probability(s), 1.0 - all_above(0.6), 1e-12);
  EXPECT_LT(surrogate_flip_probability(s), 0.01);  // far below every surrogate: not rerun
  s.statistic = 0.9;
  EXPECT_GT(surrogate_flip_probability(s), 0.1);   // just below: worth rerunning
  s.statistic = 1.0;
  s.more_predictable = false;
  EXPECT_NEAR(surrogate_flip_probability(s), all_above(1.0), 1e-12);
  s.run = false;
  EXPECT_EQ(surrogate_flip_probability(s), 0.0);
}

// The 0-1 test's K is a median over 100 frequencies: its standard error is 1.2533 sd / 10
// with sd = IQR / 1.349, and the chance of the other side of the split is the normal tail.
TEST(SeedAgreement, ZeroOneFlipProbabilityIsTheNormalTailOfTheMedian) {
  ZeroOneResult z;
  z.run = true;
  z.K = 0.52;
  z.K_q25 = 0.3;
  z.K_q75 = 0.9;  // far above the split: the median decides
  const double se = 1.2533 * (0.6 / 1.349) / 10.0;
  EXPECT_NEAR(zero_one_flip_probability(z, 100, 0.5),
              0.5 * std::erfc(0.02 / (se * std::sqrt(2.0))), 1e-12);
  z.K = 0.99;
  z.K_q25 = 0.97;
  z.K_q75 = 1.0;  // Lorenz-like: no seed turns it
  EXPECT_LT(zero_one_flip_probability(z, 100, 0.5), 1e-12);
  z.run = false;
  EXPECT_EQ(zero_one_flip_probability(z, 100, 0.5), 0.0);
}

TEST(SeedAgreement, AnEvenNumberOfSeedsIsRefused) {
  AnalysisOptions o;
  for (std::size_t n : {0u, 2u, 101u}) {
    o.verdict_seeds = n;
    try {
      o.validate();
      FAIL() << n << " seeds accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("verdict_seeds"), std::string::npos) << e.what();
    }
  }
  o.verdict_seeds = 1;
  EXPECT_NO_THROW(o.validate());
}

}  // namespace
}  // namespace pneumachaos
