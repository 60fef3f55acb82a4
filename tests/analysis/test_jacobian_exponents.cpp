// Exponents from local Jacobians (pneumachaos/analysis/jacobian_exponents.hpp) against known
// answers, 1e4 samples of one coordinate. Reference values: logistic map r = 4, ln 2 per
// iteration (exact); Henon a = 1.4, b = 0.3, 0.41922 and -1.62319 per iteration, summing to
// ln 0.3 (Sprott, Chaos and Time-Series Analysis, 2003, table A.1); Lorenz 63 at the standard
// parameters, 0.9056 per time unit (ibid.); the sources are also cited in reference_series.hpp.
#include <gtest/gtest.h>

#include <cmath>
#include <string>

#include "analysis/jacobian_output.hpp"
#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/analysis/autocorrelation.hpp"
#include "pneumachaos/analysis/embedding_parameters.hpp"
#include "pneumachaos/analysis/jacobian_exponents.hpp"
#include "pneumachaos/core/error.hpp"
#include "support/automatic_embedding.hpp"
#include "support/reference_series.hpp"

namespace pneumachaos {
namespace {

using namespace pneumachaos::testing;

JacobianOptions automatic(const std::vector<double>& x) {
  return automatic_embedding<JacobianOptions>(x);
}

std::string describe(const JacobianResult& r) {
  std::string s = "exponents";
  for (double l : r.exponents_per_s) s += " " + std::to_string(l);
  return s + " +- " + std::to_string(r.uncertainty_per_s) +
         ", unexplained " + std::to_string(r.unexplained);
}

}  // namespace

// A smooth one-dimensional map: the local fits are exact up to the map's curvature over a
// neighbourhood 1e-3 of the interval wide, so only averaging is left: 1 %.
TEST(JacobianExponents, LogisticMapReadsLnTwo) {
  JacobianOptions o;
  o.dimension = 1;
  const JacobianResult r = jacobian_exponents(logistic_map(10000), 1.0, o);
  EXPECT_NEAR(r.lambda_per_s / std::log(2.0), 1.0, 0.01) << describe(r);
  EXPECT_TRUE(r.reliable) << describe(r);
}

// Both exponents of a two-dimensional map in its own dimension. The negative one rests on the
// thin direction across the attractor's folds, which a neighbourhood resolves less well than
// the stretching one: 5 % for each, and their sum (the map's constant log |det J| = ln b)
// within 5 % as well.
TEST(JacobianExponents, HenonMapReadsBothExponents) {
  JacobianOptions o;
  o.dimension = 2;
  const JacobianResult r = jacobian_exponents(henon_map(10000), 1.0, o);
  ASSERT_EQ(r.exponents_per_s.size(), 2u);
  EXPECT_NEAR(r.exponents_per_s[0] / 0.41922, 1.0, 0.05) << describe(r);
  EXPECT_NEAR(r.exponents_per_s[1] / -1.62319, 1.0, 0.05) << describe(r);
  EXPECT_NEAR(r.sum_per_s / std::log(0.3), 1.0, 0.05) << describe(r);
  EXPECT_TRUE(r.reliable) << describe(r);
}

// A flow with the embedding `analyze` chooses: 10 %, the divergence estimator's own test
// (test_lyapunov.cpp), and the error inside three of the reported uncertainties or 3 %.
// The second exponent is the flow's direction, 0 for any flow: within a tenth of the first.
// The sum is negative: the flow is dissipative (its divergence is -13.7 per time unit).
TEST(JacobianExponents, LorenzReadsItsLargestExponent) {
  const auto x = lorenz_x(10000);
  const JacobianResult r = jacobian_exponents(x, 100.0, automatic(x));
  ASSERT_GE(r.exponents_per_s.size(), 3u);
  EXPECT_NEAR(r.lambda_per_s / 0.9056, 1.0, 0.10) << describe(r);
  EXPECT_GT(r.uncertainty_per_s, 0.0);
  EXPECT_LT(std::abs(r.lambda_per_s - 0.9056),
            std::max(3.0 * r.uncertainty_per_s, 0.03 * 0.9056)) << describe(r);
  EXPECT_LT(std::abs(r.exponents_per_s[1]), 0.1 * 0.9056) << describe(r);
  EXPECT_LT(r.sum_per_s, 0.0) << describe(r);
  EXPECT_TRUE(r.reliable) << describe(r);
}

// A periodic record whose samples never repeat exactly (7.3 Hz at 1 kHz): the largest
// exponent is 0. Tolerance: 2 % of a nat per orbit (0.146 1/s), a growth too slow to read
// as chaos over the record's 73 orbits.
TEST(JacobianExponents, PeriodicRecordReadsZero) {
  const auto x = sine(10000, 7.3, 1000.0);
  const JacobianResult r = jacobian_exponents(x, 1000.0, automatic(x));
  EXPECT_LT(std::abs(r.lambda_per_s), 0.02 * 7.3) << describe(r);
  EXPECT_TRUE(r.reliable) << describe(r);
}

// Noise has no local map: white noise and a noisy sine read a positive number, which must be
// flagged unreliable (their fits leave most of the images' variance unexplained).
TEST(JacobianExponents, NoiseIsFlaggedUnreliable) {
  for (const auto& x : {white_noise(10000), sine(10000, 10.0, 1000.0, 0.05)}) {
    const JacobianResult r = jacobian_exponents(x, 1000.0, automatic(x));
    EXPECT_FALSE(r.reliable && r.lambda_per_s > 0.0) << describe(r);
    EXPECT_GT(r.unexplained, 0.5) << describe(r);
  }
}

// A strictly periodic record repeats its samples exactly (10 Hz at 1 kHz): most
// neighbourhoods outside the repeats lie on one line and determine no map. They are skipped,
// not fitted into a spurious contraction, and the maps left read 0 within the tolerance above.
TEST(JacobianExponents, StrictlyPeriodicRecordSkipsFlatNeighbourhoods) {
  const auto x = sine(10000, 10.0, 1000.0);
  const JacobianResult r = jacobian_exponents(x, 1000.0, automatic(x));
  EXPECT_GT(r.skipped, 0u);
  EXPECT_LT(std::abs(r.lambda_per_s), 0.02 * 10.0) << describe(r);
}

TEST(JacobianExponents, BadOptionsAndShortRecordsAreRefused) {
  const auto x = lorenz_x(10000);
  JacobianOptions o = automatic(x);  // dimension 3, delay 17, Theiler 159
  const auto refused = [&](std::span<const double> record, const JacobianOptions& opt,
                           const char* words) {
    try {
      jacobian_exponents(record, 100.0, opt);
      ADD_FAILURE() << "accepted; expected: " << words;
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find(words), std::string::npos) << e.what();
    }
  };
  refused(std::span(x).first(300), o, "at least");
  JacobianOptions few = o;
  few.neighbours = 3;  // an affine fit in 3 coordinates needs 4 points
  refused(x, few, "jacobian.neighbours = 3: must be 0 (automatic) or >= 4");
  JacobianOptions zero = o;
  zero.delay = 0;
  refused(x, zero, "jacobian.delay = 0: must be >= 1");
  // The shortest record accepted gives a value.
  EXPECT_NO_THROW(jacobian_exponents(std::span(x).first(2000), 100.0, o));
}

// `analyze` runs the estimator only when asked, on its own embedding, and compares the two
// exponents: on Lorenz both are near 0.906, so their difference is well inside the combined
// uncertainty; on white noise the estimate is flagged in its status.
TEST(JacobianExponents, AnalyzeReportsItBesideTheDivergenceEstimate) {
  AnalysisOptions o;
  o.verdict_seeds = 1;
  const auto x = lorenz_x(10000);
  EXPECT_TRUE(analyze_series(x, 100.0, o).jacobian_status.empty());  // off by default
  o.jacobian = true;
  const AnalysisResult r = analyze_series(x, 100.0, o);
  ASSERT_TRUE(r.jacobian_run) << r.jacobian_status;
  EXPECT_NEAR(r.jacobian.lambda_per_s / 0.9056, 1.0, 0.10) << describe(r.jacobian);
  const EstimatorDisagreement d = estimator_disagreement(r);
  ASSERT_TRUE(d.defined);
  EXPECT_NEAR(d.difference_per_s, r.jacobian.lambda_per_s - r.divergence.lambda_per_s, 1e-12);
  EXPECT_FALSE(d.beyond_95) << d.difference_per_s << " vs " << d.combined_uncertainty_per_s;
  EXPECT_NE(jacobian_text(r).find("the two estimates"), std::string::npos) << jacobian_text(r);
  const AnalysisResult noise = analyze_series(white_noise(10000), 1000.0, o);
  EXPECT_NE(noise.jacobian_status.find("unreliable"), std::string::npos) << noise.jacobian_status;
}

// Two estimates, worked by hand: 1.0 +- 0.1 and 1.3 +- 0.2 (weights 100 and 25) average to
// (100 + 32.5) / 125 = 1.06 with a standard error 1 / sqrt(125) = 0.0894; their difference,
// 0.3, is 1.342 of their combined uncertainty sqrt(0.05) = 0.2236, so the error is scaled by
// 1.342 to 0.12. Closer together (1.1 +- 0.2: 0.447 of it) the scale stays 1.
AnalysisResult two_estimates(double jacobian, double jacobian_sd) {
  AnalysisResult r;
  r.jacobian_run = true;
  r.jacobian_status = "computed";
  r.jacobian.reliable = true;
  r.jacobian.lambda_per_s = jacobian;
  r.jacobian.uncertainty_per_s = jacobian_sd;
  r.divergence.found_linear_region = true;
  r.divergence.lambda_per_s = 1.0;
  r.divergence.uncertainty_per_s = 0.1;
  return r;
}

TEST(JacobianExponents, TheTwoCombineByInverseVarianceWithTheScaleFactor) {
  const CombinedExponent c = combined_exponent(two_estimates(1.3, 0.2));
  ASSERT_TRUE(c.defined);
  EXPECT_NEAR(c.value_per_s, 1.06, 1e-12);
  EXPECT_NEAR(c.scale, 0.3 / std::sqrt(0.05), 1e-12);
  EXPECT_NEAR(c.uncertainty_per_s, c.scale / std::sqrt(125.0), 1e-12);
  const CombinedExponent close = combined_exponent(two_estimates(1.1, 0.2));
  EXPECT_EQ(close.scale, 1.0);
  EXPECT_NEAR(close.uncertainty_per_s, 1.0 / std::sqrt(125.0), 1e-12);
  AnalysisResult unreliable = two_estimates(1.3, 0.2);
  unreliable.jacobian.reliable = false;
  EXPECT_FALSE(combined_exponent(unreliable).defined);
  AnalysisResult no_region = two_estimates(1.3, 0.2);
  no_region.divergence.found_linear_region = false;
  EXPECT_FALSE(combined_exponent(no_region).defined);
  EXPECT_NE(jacobian_text(two_estimates(1.3, 0.2)).find("the two combined: 1.06"),
            std::string::npos);
}

}  // namespace pneumachaos
