// The paper's judge (src/analysis/paper_judge.cpp): its three indices as the paper states them,
// beside the regime verdict. They call linear noise chaotic, which is why the verdict stays
// the product's own.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/analysis/paper_judge.hpp"

namespace pneumachaos {
namespace {

constexpr double kRate_Hz = 1000.0;

std::vector<double> white_noise(std::size_t n) {
  std::mt19937_64 rng(7);
  std::normal_distribution<double> normal;
  std::vector<double> x(n);
  for (double& v : x) v = normal(rng);
  return x;
}

std::vector<double> tone(std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t k = 0; k < n; ++k) x[k] = std::sin(2.0 * std::numbers::pi * 5.0 * k / kRate_Hz);
  return x;
}

AnalysisResult analysed(const std::vector<double>& x, bool paper) {
  AnalysisOptions o;
  o.paper_judge = paper;
  o.velocity = false;
  return analyze_series(x, kRate_Hz, o);
}

// White noise: a flat spectrum, an autocorrelation that dies at once, and Wolf's program
// reads hundreds of 1/s (it follows the noise's own separation). The paper's indices call it
// chaotic; the verdict calls it stochastic.
TEST(PaperJudge, CallsWhiteNoiseChaoticWhereTheVerdictDoesNot) {
  const AnalysisResult r = analysed(white_noise(5000), true);
  const PaperJudgement j = paper_judge(r);
  ASSERT_TRUE(j.evaluated) << j.why;
  EXPECT_TRUE(j.flat_spectrum);
  EXPECT_TRUE(j.acf_converges);
  EXPECT_TRUE(j.wolf_positive);
  EXPECT_TRUE(j.chaotic);
  EXPECT_EQ(r.verdict.regime, Regime::kStochastic);
  // Without the paper's judge Wolf is not run on linear noise, and the judge says so.
  const PaperJudgement strict = paper_judge(analysed(white_noise(5000), false));
  EXPECT_FALSE(strict.evaluated);
  EXPECT_FALSE(strict.chaotic);
  EXPECT_NE(strict.why.find("Wolf"), std::string::npos);
}

// A tone fails all three: one line holds the power, the autocorrelation never dies, and
// Wolf's exponent is not above three times its uncertainty.
TEST(PaperJudge, ATonesIndicesAllSayRegular) {
  const PaperJudgement j = paper_judge(analysed(tone(5000), true));
  ASSERT_TRUE(j.evaluated) << j.why;
  EXPECT_FALSE(j.flat_spectrum);
  EXPECT_FALSE(j.acf_converges);
  EXPECT_FALSE(j.wolf_positive);
  EXPECT_FALSE(j.chaotic);
}

// Each index alone can refuse: the judge is their AND, at the claim rules' thresholds.
TEST(PaperJudge, EachIndexAloneRefusesAndTheThresholdsAreTheClaimRules) {
  AnalysisResult r;
  r.acf.rate_Hz = kRate_Hz;
  r.acf.r.assign(2000, 0.0);
  r.acf.r[1500] = kPaperAcfEnvelope;  // at the threshold, after 1 s: still converged
  r.spectrum.peak_share = kPaperPeakShare;
  r.wolf_run = true;
  r.wolf.lambda_per_s = 3.1;
  r.wolf.uncertainty_per_s = 1.0;
  EXPECT_TRUE(paper_judge(r).chaotic);
  AnalysisResult peak = r;
  peak.spectrum.peak_share = 0.26;
  EXPECT_FALSE(paper_judge(peak).chaotic);
  AnalysisResult acf = r;
  acf.acf.r[1500] = 0.21;
  EXPECT_FALSE(paper_judge(acf).chaotic);
  AnalysisResult wolf = r;
  wolf.wolf.lambda_per_s = 2.9;
  EXPECT_FALSE(paper_judge(wolf).chaotic);
  AnalysisResult short_acf = r;
  short_acf.acf.r.resize(900);  // no lag of 1 s: not judged
  EXPECT_FALSE(paper_judge(short_acf).evaluated);
}

// Chaos needs all three indices, so one that refuses decides without Wolf's exponent; where
// the other two say chaos, a missing exponent leaves the record unjudged.
TEST(PaperJudge, ARefusingIndexDecidesWithoutWolfsExponent) {
  AnalysisResult r;
  r.acf.rate_Hz = kRate_Hz;
  r.acf.r.assign(2000, 0.0);
  r.spectrum.peak_share = 0.6;  // a dominant line
  const PaperJudgement line = paper_judge(r);
  ASSERT_TRUE(line.evaluated) << line.why;
  EXPECT_FALSE(line.chaotic);
  EXPECT_FALSE(line.wolf_computed);
  EXPECT_NE(describe(line).find("not computed, not needed"), std::string::npos);
  AnalysisResult acf = r;
  acf.spectrum.peak_share = 0.1;
  acf.acf.r[1500] = 0.5;  // the autocorrelation has not died after 1 s
  EXPECT_TRUE(paper_judge(acf).evaluated);
  EXPECT_FALSE(paper_judge(acf).chaotic);
  AnalysisResult open = r;
  open.spectrum.peak_share = 0.1;  // both indices at hand say chaos
  const PaperJudgement undecided = paper_judge(open);
  EXPECT_FALSE(undecided.evaluated);
  EXPECT_NE(undecided.why.find("Wolf"), std::string::npos);
}

}  // namespace
}  // namespace pneumachaos
