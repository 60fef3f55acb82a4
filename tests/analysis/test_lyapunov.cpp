// Largest Lyapunov exponents from 1e4 samples of one coordinate, with DEFAULT automatic
// parameters (docs/validation.md, "The chaos analysis against known answers").
#include <fmt/format.h>
#include <gtest/gtest.h>

#include <cmath>
#include <limits>
#include <random>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/analysis/autocorrelation.hpp"
#include "pneumachaos/analysis/embedding_parameters.hpp"
#include "pneumachaos/analysis/lyapunov_divergence.hpp"
#include "analysis/log_array.hpp"
#include "analysis/pair_distances.hpp"
#include "pneumachaos/analysis/lyapunov_wolf.hpp"
#include "pneumachaos/core/error.hpp"
#include "support/automatic_embedding.hpp"
#include "support/reference_series.hpp"
#include "support/validation_corpus.hpp"

namespace pneumachaos {
namespace {

using namespace pneumachaos::testing;

DivergenceOptions automatic(const std::vector<double>& x) {
  return automatic_embedding<DivergenceOptions>(x);
}

struct Reference {
  const char* name;
  std::vector<double> (*make)();
  double step;    ///< sampling interval in the system's time unit
  double lambda;  ///< reference exponent per time unit (sources in reference_series.hpp)
};

class DivergenceTest : public ::testing::TestWithParam<Reference> {};

TEST_P(DivergenceTest, WithinTenPercentOfTheReference) {
  const Reference& ref = GetParam();
  const auto x = ref.make();
  const DivergenceResult r = divergence_exponent(x, 1.0 / ref.step, automatic(x));
  ASSERT_TRUE(r.found_linear_region);
  EXPECT_NEAR(r.lambda_per_s / ref.lambda, 1.0, 0.10)
      << ref.name << ": " << r.lambda_per_s << " +- " << r.uncertainty_per_s;
  // The reported uncertainty is an honest scale: positive, and the error within 3 of it
  // or within 3 %.
  EXPECT_GT(r.uncertainty_per_s, 0.0);
  EXPECT_LT(std::abs(r.lambda_per_s - ref.lambda),
            std::max(3.0 * r.uncertainty_per_s, 0.03 * ref.lambda));
}

INSTANTIATE_TEST_SUITE_P(
    References, DivergenceTest,
    ::testing::Values(Reference{"logistic", [] { return logistic_map(10000); }, 1.0, std::log(2.0)},
                      Reference{"henon", [] { return henon_map(10000); }, 1.0, 0.419},
                      Reference{"lorenz", [] { return lorenz_x(10000); }, 0.01, 0.906},
                      Reference{"rossler", [] { return rossler_x(10000); }, 0.1, 0.0714}),
    [](const auto& info) { return std::string(info.param.name); });

TEST(Divergence, ContinuousTimeAlignmentRemovesTheFlowBias) {
  // Without alignment the Rossler estimate falls 13-18 % low, as in the peers
  // docs/notes/analysis.md lists.
  const auto x = rossler_x(10000);
  DivergenceOptions o = automatic(x);
  o.alignment = DivergenceOptions::Alignment::kOff;
  const DivergenceResult plain = divergence_exponent(x, 10.0, o);
  o.alignment = DivergenceOptions::Alignment::kOn;
  const DivergenceResult aligned = divergence_exponent(x, 10.0, o);
  EXPECT_LT(plain.lambda_per_s / 0.0714, 0.9);
  EXPECT_NEAR(aligned.lambda_per_s / 0.0714, 1.0, 0.05);
}

// The segments see what the record does along its length: logistic r = 4 (ln 2 per step) for
// the first half, r = 3.7 (a slower exponent, about 0.35) for the second, shifted by 2 so
// that no reference finds its neighbour in the other half. The first segment reads ln 2, the
// last far less (measured: 0.686, 0.686, 0.529 across the junction, 0.355, 0.350 per step),
// and the value's uncertainty grows beyond the slope's.
TEST(Divergence, SegmentsFollowAChangeAlongTheRecord) {
  std::vector<double> x = logistic(5000, 4.0);
  for (double v : logistic(5000, 3.7)) x.push_back(v + 2.0);
  DivergenceOptions o;
  o.dimension = 1;
  const DivergenceResult r = divergence_exponent(x, 1.0, o);
  ASSERT_EQ(r.segment_slopes_per_step.size(), 5u);
  EXPECT_NEAR(r.segment_slopes_per_step.front() / std::log(2.0), 1.0, 0.05);
  EXPECT_LT(r.segment_slopes_per_step.back(), 0.6);
  EXPECT_GT(r.uncertainty_per_s, 2.0 * r.slope_uncertainty_per_s);
  // A stationary record: every segment near ln 2.
  const DivergenceResult s = divergence_exponent(logistic_map(10000), 1.0, o);
  for (double v : s.segment_slopes_per_step) EXPECT_NEAR(v / std::log(2.0), 1.0, 0.05);
  EXPECT_GE(s.uncertainty_per_s, s.slope_uncertainty_per_s);
}

TEST(Divergence, SegmentCountIsChecked) {
  const auto x = logistic_map(2000);
  for (std::size_t n : {1u, 11u}) {
    DivergenceOptions o;
    o.segments = n;  // 2 .. jackknife_blocks (10)
    try {
      divergence_exponent(x, 1.0, o);
      ADD_FAILURE() << n << " segments accepted";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("lyapunov.segments"), std::string::npos) << e.what();
    }
  }
}

TEST(Divergence, SineSineWithNoiseAndWhiteNoiseHaveNoRisingRegion) {
  for (const auto& x :
       {sine(10000, 10.0, 1000.0), sine(10000, 10.0, 1000.0, 0.05), white_noise(10000)}) {
    const DivergenceResult r = divergence_exponent(x, 1000.0, automatic(x));
    EXPECT_FALSE(r.found_linear_region && r.lambda_per_s > 0.0 &&
                 r.lambda_per_s > 3.0 * r.uncertainty_per_s)
        << r.lambda_per_s << " +- " << r.uncertainty_per_s;
  }
}

}  // namespace
}  // namespace pneumachaos

namespace pneumachaos {
namespace {

WolfOptions wolf_automatic(const std::vector<double>& x) {
  const DivergenceOptions d = automatic(x);
  WolfOptions o;
  o.dimension = d.dimension;
  o.delay = d.delay;
  o.theiler = d.theiler;
  return o;
}

class WolfTest : public ::testing::TestWithParam<Reference> {};

// Wolf is asked to be within 15 % (docs/notes/analysis.md). Measured on these records:
// logistic 0 %, Henon -7.6 %, Lorenz -6.2 %, Rossler -12.7 % (docs/validation.md).
TEST_P(WolfTest, WithinFifteenPercentOfTheReference) {
  const Reference& ref = GetParam();
  const auto x = ref.make();
  const WolfResult r = wolf_exponent(x, 1.0 / ref.step, wolf_automatic(x));
  EXPECT_NEAR(r.lambda_per_s / ref.lambda, 1.0, 0.15) << ref.name << ": " << r.lambda_per_s;
  ASSERT_FALSE(r.running_per_s.empty());
  EXPECT_EQ(r.running_per_s.size(), r.running_time_s.size());
}

INSTANTIATE_TEST_SUITE_P(
    References, WolfTest,
    ::testing::Values(Reference{"logistic", [] { return logistic_map(10000); }, 1.0, std::log(2.0)},
                      Reference{"henon", [] { return henon_map(10000); }, 1.0, 0.419},
                      Reference{"lorenz", [] { return lorenz_x(10000); }, 0.01, 0.906},
                      Reference{"rossler", [] { return rossler_x(10000); }, 0.1, 0.0714}),
    [](const auto& info) { return std::string(info.param.name); });

// Not one lucky record: eight records of each flow from different starting points, each within
// the bound below (skipping pairs for a period after each replacement instead of the settled
// handoff reads Lorenz +22 % on average, up to +44 %: docs/notes/analysis.md).
TEST(Wolf, FlowsAcrossEightRecords) {
  for (const bool lorenz : {true, false}) {
    double sum = 0.0, worst = 0.0;
    for (int k = 0; k < 8; ++k) {
      const auto x = lorenz
                         ? lorenz_x(10000, 0.01, {1.0 + 0.37 * k, 1.0 - 0.21 * k, 20.0 + 0.5 * k})
                         : rossler_x(10000, 0.1, {1.0 + 0.3 * k, 1.0 - 0.2 * k, 0.0});
      const double ratio = wolf_exponent(x, lorenz ? 100.0 : 10.0, wolf_automatic(x)).lambda_per_s /
                           (lorenz ? 0.906 : 0.0714);
      sum += ratio - 1.0;
      worst = std::max(worst, std::abs(ratio - 1.0));
    }
    // Measured: Lorenz mean -1.0 %, worst 8.4 %; Rossler mean -8.3 %, worst -16.4 %.
    EXPECT_LT(std::abs(sum / 8.0), 0.10) << (lorenz ? "lorenz" : "rossler");
    if (lorenz) EXPECT_LT(worst, 0.15);
  }
}

// Chains start staggered over the first orbit; an orbit longer than the record put the later
// chains' first query past its end (found by fuzz_analyze_series). They measure nothing.
TEST(Wolf, AnOrbitLongerThanTheRecordLeavesChainsNothingToFollow) {
  const auto x = sine(400, 3.0, 1000.0);
  WolfOptions o = wolf_automatic(x);
  o.typical_period = 5000;
  o.evolve = 1;
  WolfResult r;
  ASSERT_NO_THROW(r = wolf_exponent(x, 1000.0, o));
  EXPECT_TRUE(std::isfinite(r.lambda_per_s));
}

TEST(Wolf, StrictlyPeriodicRecordMeasuresNoStretching) {
  const auto x = sine(10000, 10.0, 1000.0);
  const WolfResult r = wolf_exponent(x, 1000.0, wolf_automatic(x));
  EXPECT_EQ(r.lambda_per_s, 0.0);
}

}  // namespace
}  // namespace pneumachaos

// Honest uncertainties (docs/notes/analysis.md "Open"): over records of known
// exponent, with the analysis' own automatic parameters, the true value must lie inside the
// reported 95 % interval (+-1.96 sigma) on at least 90 % of them (asserted for the divergence
// exponent; Wolf's coverage is printed).
// Reference exponents: Lorenz 0.9056 per time unit and Rossler (a = b = 0.2, c = 5.7) 0.0714
// (Sprott, Chaos and Time-Series Analysis, 2003, table A.1), logistic r = 4 ln 2 (exact),
// Henon 0.419 per step (Sprott 2003, A.1: 0.41922); an 8-bit A/D converter does not change
// Lorenz's exponent. Six starting points each, 1e4 samples.
namespace pneumachaos {
namespace {

using namespace pneumachaos::testing;

struct KnownExponent {
  std::string name;
  std::vector<double> x;
  double rate;    ///< samples per time unit
  double lambda;  ///< per time unit
};

std::vector<KnownExponent> coverage_records() {
  std::vector<KnownExponent> v;
  const double starts[6] = {0.11, 0.23, 0.31, 0.43, 0.57, 0.69};
  for (int k = 0; k < 6; ++k) {
    const std::array<double, 3> ls{1.0 + 0.37 * k, 1.0 - 0.21 * k, 20.0 + 0.5 * k};
    v.push_back({fmt::format("lorenz {}", k), lorenz_x(10000, 0.01, ls), 100.0, 0.9056});
    v.push_back({fmt::format("lorenz 8-bit {}", k), quantised(lorenz_x(10000, 0.01, ls), 256.0),
                 100.0, 0.9056});
    v.push_back({fmt::format("rossler {}", k),
                 rossler_x(10000, 0.1, {1.0 + 0.3 * k, 1.0 - 0.2 * k, 0.0}), 10.0, 0.0714});
    v.push_back(
        {fmt::format("logistic {}", k), logistic_map(10000, starts[k]), 1.0, std::log(2.0)});
  }
  v.push_back({"henon", henon_map(10000), 1.0, 0.419});
  return v;
}

TEST(ExponentUncertainty, NinetyFiveIntervalCoversTheTrueValueOnNinetyPercent) {
  const auto records = coverage_records();
  int divergence_in = 0, wolf_in = 0;
  for (const KnownExponent& k : records) {
    const AnalysisResult r = analyze_series(k.x, k.rate);
    const auto& d = r.divergence;
    const bool din = std::abs(d.lambda_per_s - k.lambda) <= 1.96 * d.uncertainty_per_s;
    const bool win =
        r.wolf_run && std::abs(r.wolf.lambda_per_s - k.lambda) <= 1.96 * r.wolf.uncertainty_per_s;
    divergence_in += din;
    wolf_in += win;
    fmt::print(
        "{:>16}: divergence {:+.4f} +- {:.4f} ({:+.1f} sigma) {}; Wolf {:+.4f} +- {:.4f} "
        "({:+.1f} sigma) {}\n",
        k.name, d.lambda_per_s / k.lambda - 1.0, d.uncertainty_per_s / k.lambda,
        (d.lambda_per_s - k.lambda) / d.uncertainty_per_s, din ? "in" : "OUT",
        r.wolf.lambda_per_s / k.lambda - 1.0, r.wolf.uncertainty_per_s / k.lambda,
        (r.wolf.lambda_per_s - k.lambda) / r.wolf.uncertainty_per_s, win ? "in" : "OUT");
  }
  const auto n = static_cast<int>(records.size());
  fmt::print("coverage of the 95 % interval: divergence {} of {}, Wolf {} of {}\n", divergence_in,
             n, wolf_in, n);
  EXPECT_GE(divergence_in, 0.9 * n);
  // Wolf's is printed, not asserted: it misses Henon (-7.6 %, a bias of the method,
  // docs/notes/analysis.md "Open") and reads 22 of 25 here.
}

}  // namespace
}  // namespace pneumachaos

namespace pneumachaos {
namespace {

// The divergence curve's squared distances (src/analysis/pair_distances.cpp), vectorised for
// the processor at hand, against the same sums taken one step and one coordinate at a time:
// equal bit for bit, at lengths that leave every remainder of the vector width.
TEST(PairDistances, EqualBitForBitToTheSumInCoordinateOrder) {
  std::mt19937_64 rng(11);
  std::normal_distribution<double> normal(0.0, 1.0);
  std::vector<double> x(400);
  for (double& v : x) v = std::exp(3.0 * normal(rng));
  for (std::size_t dimension = 1; dimension <= 9; ++dimension) {
    for (std::size_t steps = 1; steps <= 37; steps += 3) {
      const std::size_t delay = 1 + dimension % 4;
      const double* a = x.data() + 5;
      const double* b = x.data() + 101;
      std::vector<double> d2(steps);
      squared_pair_distances(a, b, dimension, delay, d2);
      for (std::size_t k = 0; k < steps; ++k) {
        double expected = 0.0;
        for (std::size_t c = 0; c < dimension; ++c) {
          const double diff = a[c * delay + k] - b[c * delay + k];
          expected += diff * diff;
        }
        ASSERT_EQ(d2[k], expected) << "dimension " << dimension << ", step " << k;
      }
    }
  }
}

// The divergence curve's logarithms (src/analysis/log_array.cpp) against the C library's,
// which is within about half an ulp of the exact value: at most 2 ulp apart over the whole
// normal range, near 1 (where ln x is small and cancellation would show), at powers of two
// and on both sides of sqrt(2) (where the reduction switches); exactly 0 at 1; the library's
// own answer for zero, subnormal, negative, infinite and NaN inputs.
TEST(LogArray, WithinTwoUlpOfTheLibraryLogAndSpecialValuesAsTheLibrary) {
  std::mt19937_64 rng(7);
  std::uniform_real_distribution<double> exponent(-708.0, 709.0), unit(-1.0, 1.0);
  std::vector<double> x{1.0};
  for (int i = 0; i < 200000; ++i) x.push_back(std::exp(exponent(rng)));
  for (int i = 0; i < 20000; ++i) x.push_back(1.0 + std::ldexp(unit(rng), -(i % 53)));
  for (int e = -1022; e <= 1023; ++e) {
    for (double m : {1.0, std::sqrt(2.0), std::nextafter(std::sqrt(2.0), 2.0),
                     std::nextafter(std::sqrt(2.0), 1.0), std::nextafter(2.0, 1.0)}) {
      x.push_back(std::ldexp(m, e));
    }
  }
  std::vector<double> y(x.size());
  log_array(x, y);
  EXPECT_EQ(y[0], 0.0);
  double worst = 0.0;
  for (std::size_t k = 0; k < x.size(); ++k) {
    const double r = std::log(x[k]);
    const double ulp = r == 0.0 ? std::numeric_limits<double>::denorm_min()
                                : std::abs(std::nextafter(r, 2.0 * r) - r);
    worst = std::max(worst, std::abs(y[k] - r) / ulp);
  }
  EXPECT_LE(worst, 2.0);

  constexpr double inf = std::numeric_limits<double>::infinity();
  const std::vector<double> special{0.0, -0.0, 4.9e-324, 1e-310, -1.0, inf, -inf,
                                    std::numeric_limits<double>::quiet_NaN()};
  std::vector<double> out(special.size());
  log_array(special, out);
  for (std::size_t k = 0; k < special.size(); ++k) {
    const double r = std::log(special[k]);
    if (std::isnan(r)) {
      EXPECT_TRUE(std::isnan(out[k])) << special[k];
    } else {
      EXPECT_EQ(out[k], r) << special[k];
    }
  }
}

}  // namespace
}  // namespace pneumachaos
