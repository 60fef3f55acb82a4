// IAAFT surrogates, the surrogate-data test and the 0-1 test on records whose answer is known
// from theory: chaotic maps and flows reject the linear-stochastic null, linear Gaussian
// processes keep it (at the test's 5 % level); K -> 1 for chaos, -> 0 for periodic motion.
#include <gtest/gtest.h>
#include <tbb/task_arena.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/analysis/analysis_output.hpp"
#include "pneumachaos/analysis/analyze.hpp"
#include "analysis/fft.hpp"
#include "pneumachaos/analysis/prediction_error.hpp"
#include "pneumachaos/analysis/regime.hpp"
#include "pneumachaos/analysis/surrogates.hpp"
#include "pneumachaos/analysis/zero_one_test.hpp"
#include "pneumachaos/core/error.hpp"
#include "support/validation_corpus.hpp"

namespace pneumachaos {
namespace {

using namespace pneumachaos::testing;

double spectral_mismatch(std::span<const double> a, std::span<const double> b) {
  const auto A = forward_dft(a, a.size()), B = forward_dft(b, b.size());
  double d = 0.0, t = 0.0;
  for (std::size_t k = 0; k < A.size(); ++k) {
    d += std::pow(std::abs(A[k]) - std::abs(B[k]), 2);
    t += std::norm(A[k]);
  }
  return std::sqrt(d / t);
}

TEST(Surrogates, IaaftKeepsTheValuesAndTheSpectrumAndFollowsItsSeed) {
  const auto x = lorenz_x(4000);  // 4000 = 2^5 5^3: a fast transform length
  const auto s = iaaft_surrogate(x, 5);
  auto xs = x, ss = s;
  std::sort(xs.begin(), xs.end());
  std::sort(ss.begin(), ss.end());
  EXPECT_EQ(xs, ss);  // exactly the record's values (the amplitude adjustment)
  EXPECT_LE(spectral_mismatch(x, s), 1e-2);  // SurrogateOptions::spectral_tolerance
  EXPECT_NE(s, x);
  EXPECT_EQ(iaaft_surrogate(x, 5), s);  // deterministic for a seed
  EXPECT_NE(iaaft_surrogate(x, 6), s);
}

TEST(Surrogates, ChaosRejectsTheLinearNullAndLinearNoiseKeepsIt) {
  PredictionOptions p;
  p.dimension = 2;
  p.delay = 1;
  SurrogateOptions o;  // 39 surrogates, two-sided 95 %
  const SurrogateTest henon = surrogate_test(henon_map(4000), p, o);
  ASSERT_TRUE(henon.run);
  EXPECT_TRUE(henon.rejected);
  EXPECT_TRUE(henon.more_predictable);
  EXPECT_NEAR(henon.p_value, 0.05, 1e-12);  // 2 / (39 + 1): the smallest two-sided p
  EXPECT_EQ(henon.surrogate_statistics.size(), 39u);

  p.dimension = 3;
  p.delay = 17;
  p.theiler = 34;
  const SurrogateTest lorenz = surrogate_test(lorenz_x(5000), p, o);
  EXPECT_TRUE(lorenz.more_predictable);
  // AR(1) is the null itself: kept at four seeds (each could reject by chance with p = 0.05).
  int kept = 0;
  p.dimension = 2;
  p.delay = 5;
  p.theiler = 20;
  for (unsigned seed : {21u, 22u, 23u, 24u}) {
    kept += surrogate_test(autoregressive(4000, 0.9, 0.0, seed), p, o).rejected ? 0 : 1;
  }
  EXPECT_GE(kept, 3);
}

// The surrogates are made side by side on the available threads; each one's seed follows
// from its index, so the statistics, in order, are the same on one thread and on two.
TEST(Surrogates, SameStatisticsOnOneThreadAndOnTwo) {
  PredictionOptions p;
  p.dimension = 2;
  p.delay = 1;
  SurrogateOptions o;
  o.count = 19;
  const auto x = henon_map(2000);
  const auto on = [&](int threads) {
    SurrogateTest t;
    tbb::task_arena(threads).execute([&] { t = surrogate_test(x, p, o); });
    return t;
  };
  const SurrogateTest one = on(1), two = on(2);
  ASSERT_TRUE(one.run);
  ASSERT_EQ(one.surrogate_statistics.size(), 19u);
  EXPECT_EQ(one.surrogate_statistics, two.surrogate_statistics);
  EXPECT_EQ(one.statistic, two.statistic);
  // And each is the statistic of the surrogate its seed makes, on its own.
  const auto third = iaaft_surrogate(std::span<const double>(x).subspan(one.offset, one.samples),
                                     o.seed * 0x9E3779B97F4A7C15ULL + 2, o.max_iterations,
                                     o.spectral_tolerance);
  EXPECT_EQ(one.surrogate_statistics[2], nonlinear_prediction_error(third, p));
}

TEST(Surrogates, ShortRecordsAndZeroCountAreNotRunAndSaySo) {
  PredictionOptions p;
  SurrogateOptions o;
  const SurrogateTest shortr = surrogate_test(henon_map(300), p, o);
  EXPECT_FALSE(shortr.run);
  EXPECT_NE(shortr.reason.find("at least 500"), std::string::npos);
  o.count = 0;
  EXPECT_FALSE(surrogate_test(henon_map(4000), p, o).run);
  o.max_iterations = 0;
  EXPECT_THROW(surrogate_test(henon_map(4000), p, o), Error);
}

TEST(Surrogates, CountIsOffOrEnoughForATestAtFivePercent) {
  // 1/(N+1) <= 0.05 needs N >= 19; every caller (analyze, sweep, Python) goes through this.
  for (std::size_t n : {std::size_t{0}, kMinSurrogates, std::size_t{39}, kMaxSurrogates}) {
    EXPECT_NO_THROW(check_surrogate_count(n, "n")) << n;
  }
  for (std::size_t n : {std::size_t{1}, kMinSurrogates - 1, kMaxSurrogates + 1}) {
    EXPECT_THROW(check_surrogate_count(n, "n"), Error) << n;
  }
  SurrogateOptions o;
  o.count = 18;
  EXPECT_THROW(surrogate_test(henon_map(4000), PredictionOptions{}, o), Error);
}

TEST(ZeroOne, ChaosNearOnePeriodicNearZero) {
  // Gottwald & Melbourne 2004/2009: K -> 1 for the chaotic logistic map, -> 0 for periodic.
  const ZeroOneResult chaos = zero_one_test(logistic(5000, 3.97), 1);
  ASSERT_TRUE(chaos.run);
  EXPECT_GT(chaos.K, 0.9);
  EXPECT_LE(chaos.K_q25, chaos.K);
  EXPECT_GE(chaos.K_q75, chaos.K);
  EXPECT_LT(zero_one_test(logistic(5000, 3.55), 1).K, 0.1);  // period 8
  EXPECT_EQ(zero_one_test(logistic(5000, 3.97), 1).K, chaos.K);  // seeded
}

TEST(ZeroOne, OversampledFlowNeedsDownSampling) {
  // Lorenz at dt = 0.01 moves little per sample: every sample reads regular, every 17th
  // (the mutual-information delay) reads chaotic.
  const auto x = lorenz_x(10000);
  EXPECT_LT(zero_one_test(x, 1).K, 0.5);
  EXPECT_GT(zero_one_test(x, 17).K, 0.9);
  const ZeroOneResult few = zero_one_test(lorenz_x(1000), 17);
  EXPECT_FALSE(few.run);
  EXPECT_NE(few.reason.find("at least 200"), std::string::npos);
}

TEST(Evidence, TooShortForTheTestsSaysSoAndDegradesWithoutNaN) {
  // 1,500 samples of a 10 Hz tone at 1 kHz: the 0-1 test gets 1500 / 25 = 60 points (< 200)
  // and 39 surrogates are asked for on a record long enough for them (>= 500 samples).
  AnalysisOptions o;
  o.surrogates.count = 39;
  const AnalysisResult r = analyze_series(sine(1500, 10.0, 1000.0, 0.05), 1000.0, o);
  EXPECT_FALSE(r.zero_one.run);
  bool said = false;
  for (const auto& line : r.verdict.evidence) {
    said = said || line.find("0-1 test: not run") != std::string::npos;
  }
  EXPECT_TRUE(said);
  // Without the 0-1 test, regular rests on the concentrated spectrum and the persisting ACF.
  EXPECT_EQ(r.verdict.regime, Regime::kPeriodic);
  const std::string json = analysis_json(r, "test", "x", "-");
  EXPECT_EQ(json.find("NaN"), std::string::npos);
  EXPECT_EQ(json.find("nan"), std::string::npos);
  EXPECT_NE(json.find("\"zero_one\""), std::string::npos);
  // 300 samples: too short for the surrogates too, and for a verdict (undetermined).
  const AnalysisResult tiny = analyze_series(sine(300, 10.0, 1000.0, 0.05), 1000.0, o);
  EXPECT_FALSE(tiny.surrogate.run);
  EXPECT_NE(tiny.surrogate.reason.find("at least 500"), std::string::npos);
  EXPECT_EQ(tiny.verdict.regime, Regime::kUndetermined);
}

// A linear process beats all 39 surrogates in one record of 40 by chance (the test's level),
// and a noise-driven nonlinear oscillator beats them always; both are forecast about as well
// by the linear predictor as by the local-constant one, so the surrogate rejection alone must
// not make them deterministic (the blind records of docs/notes/analysis.md: a noise-driven linear
// oscillator at 5,000 samples and van der Pol with dynamic noise, which that alone calls chaotic).
TEST(Verdict, SurrogateRejectionAloneDoesNotMakeALinearRecordChaotic) {
  RegimeEvidence e;
  e.samples = 5000;
  e.range = 11.0;
  e.last_half_std = 1.5;
  e.lyapunov_found = true;  // a noise-driven phase drifts: a slow rise of the curve
  e.lyapunov_per_s = 0.026;
  e.lyapunov_slope_uncertainty_per_s = 0.005;
  e.surrogate_run = true;
  e.surrogate_count = 39;
  e.surrogate_rejected = e.surrogate_more_predictable = true;
  e.prediction_computed = true;
  e.prediction_nonlinear = 0.264;  // the record's figures
  e.prediction_linear = 0.194;
  const Verdict linear = decide_regime(e);
  EXPECT_FALSE(linear.chaotic);
  e.prediction_nonlinear = 0.19;  // ratio 0.98: a noise-driven van der Pol oscillator's
  EXPECT_FALSE(decide_regime(e).chaotic);  // (its waveform beats the surrogates, not linearity)
  e.prediction_nonlinear = 0.12;  // ratio 0.62, as noisy chaos: structure a linear model misses
  EXPECT_TRUE(decide_regime(e).chaotic);
  e.surrogate_more_predictable = false;  // and without the rejection, never
  EXPECT_FALSE(decide_regime(e).chaotic);
}

}  // namespace
}  // namespace pneumachaos
