// Spectrum, autocorrelation and embedding parameters on series with known answers.
#include <gtest/gtest.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <set>

#include "pneumachaos/analysis/autocorrelation.hpp"
#include "analysis/delay_embedding.hpp"
#include "pneumachaos/analysis/embedding_parameters.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/analysis/spectral_lines.hpp"
#include "pneumachaos/analysis/spectrum.hpp"
#include "pneumachaos/core/error.hpp"
#include "support/reference_series.hpp"

namespace pneumachaos {
namespace {

using namespace pneumachaos::testing;

TEST(Spectrum, SinePeakWithinOneBinAndParsevalHolds) {
  const double rate = 1000.0;
  for (double f : {7.3, 12.5, 41.0}) {
    const auto x = sine(10000, f, rate);
    const Spectrum s = welch_spectrum(x, rate);
    EXPECT_LE(std::abs(s.peak_frequency_Hz - f), s.resolution_Hz) << f;
    EXPECT_GT(s.peak_share, 0.9);
    EXPECT_LT(s.broadband_share, 0.05);
    // The PSD integrates to the variance (1/2 for a unit sine): Welch with Hann keeps power.
    double power = 0.0;
    for (double p : s.psd) power += p * s.resolution_Hz;
    EXPECT_NEAR(power, 0.5, 0.01);
  }
}

TEST(Spectrum, WhiteNoiseIsFlatAtItsVariance) {
  const double rate = 1000.0;
  const auto x = white_noise(20000);
  const Spectrum s = welch_spectrum(x, rate);
  // One-sided white PSD = 2 sigma^2 / fs = 2e-3 per Hz.
  double mean = 0.0;
  for (std::size_t k = 1; k + 1 < s.psd.size(); ++k) mean += s.psd[k];
  mean /= static_cast<double>(s.psd.size() - 2);
  EXPECT_NEAR(mean, 2e-3, 1e-4);
  EXPECT_GT(s.spectral_flatness, 0.8);  // averaged periodograms: ~0.9 rather than 1
  EXPECT_GT(s.broadband_share, 0.9);
}

TEST(Spectrum, TooShortIsAnError) {
  const auto x = white_noise(40);
  EXPECT_THROW(welch_spectrum(x, 1000.0), Error);
}

TEST(MovingMedian, KeepsAPlateauShorterThanTheWindowAndDropsASpike) {
  // Six zeros between runs of 1 in a window of 10: the median stays 0 at the plateau's middle,
  // where the moving average (4 of 10 samples at 1) reads 0.4; a single spike vanishes.
  std::vector<double> x(30, 1.0);
  std::fill(x.begin() + 12, x.begin() + 18, 0.0);
  x[5] = 50.0;
  const std::vector<double> median = moving_median(x, 10);
  const std::vector<double> mean = moving_average(x, 10);
  EXPECT_EQ(median[15], 0.0);
  EXPECT_NEAR(mean[15], 0.4, 1e-12);
  EXPECT_EQ(median[5], 1.0);
  // An even window's median is the mean of its two middle values; the ends use shorter
  // windows, as the moving average does.
  EXPECT_EQ(moving_median(std::vector<double>{1.0, 2.0, 3.0, 4.0}, 4)[1], 2.5);
  EXPECT_EQ(moving_median(std::vector<double>{7.0}, 5)[0], 7.0);
}

TEST(Autocorrelation, SineIsCosineAndNoiseIsNearZero) {
  const auto x = sine(10000, 10.0, 1000.0);
  const Autocorrelation a = autocorrelation(x, 1000.0);
  // r(k) = cos(2 pi f k / fs) times the biased estimator's taper (1 - k/N), plus a finite-sum
  // term sum cos(2 a i + a k) / N of order 1 / (N sin a) = 1.6e-3 here (a = 2 pi f / fs).
  for (std::size_t k : {0u, 10u, 25u, 50u, 100u, 1000u}) {
    EXPECT_NEAR(a.r[k], std::cos(2.0 * std::numbers::pi * 10.0 * k / 1000.0) * (1.0 - k / 10000.0),
                3e-3)
        << k;
  }
  EXPECT_NEAR(a.first_zero_s, 0.025, 0.0011);
  EXPECT_GT(a.late_envelope, 0.7);
  EXPECT_LT(a.envelope_decay_per_s, 0.5);

  const auto n = white_noise(10000);
  const Autocorrelation b = autocorrelation(n, 1000.0);
  double worst = 0.0;
  for (std::size_t k = 1; k < b.r.size(); ++k) worst = std::max(worst, std::abs(b.r[k]));
  EXPECT_LT(worst, 4.5 / std::sqrt(10000.0));  // 4.5 sigma over 2500 lags
  EXPECT_LT(b.late_envelope, 0.05);
}

TEST(Embedding, NeighbourSearchMatchesBruteForceAndHonoursTheTheilerWindow) {
  const auto x = lorenz_x(3000);
  const DelayEmbedding e(x, 3, 17);
  const NeighbourIndex index(e);
  for (std::size_t i : {std::size_t{0}, std::size_t{500}, std::size_t{1234}, e.size() - 1}) {
    double best = 1e300;
    std::size_t arg = 0;
    for (std::size_t j = 0; j < e.size(); ++j) {
      const std::size_t gap = j > i ? j - i : i - j;
      if (gap <= 50) continue;
      if (e.distance2(i, j) < best) {
        best = e.distance2(i, j);
        arg = j;
      }
    }
    const Neighbour nb = index.nearest(i, 50);
    EXPECT_EQ(nb.index, arg);
    EXPECT_DOUBLE_EQ(nb.distance2, best);
  }
}

// The k-d tree (src/analysis/kd_tree.hpp) against an exhaustive search, every query: k
// nearest and radius queries, dimensions 1 to 6, a chaotic record and a quantised one whose
// coordinates repeat (equal values on the cut, repeated vectors grouped).
TEST(Embedding, EveryQueryMatchesAnExhaustiveSearch) {
  std::vector<double> quantised(1500);
  for (std::size_t i = 0; i < quantised.size(); ++i) {
    quantised[i] = std::round(8.0 * std::sin(0.07 * i) + 3.0 * std::sin(0.19 * i));
  }
  std::vector<double> chaotic = lorenz_x(1500);
  for (const auto* x : {&chaotic, &quantised}) {
    const double resolution = repeat_resolution(*x);
    for (std::size_t dim : {1u, 3u, 6u}) {
      const DelayEmbedding e(*x, dim, 5);
      const NeighbourIndex index(e, 0, resolution);
      for (std::size_t i = 0; i < e.size(); i += 7) {
        // The index reports each distinct vector once (repeats are grouped).
        std::set<std::vector<double>> seen;
        std::vector<double> d2;
        for (std::size_t j = 0; j < e.size(); ++j) {
          const std::size_t gap = j > i ? j - i : i - j;
          const double dist2 = e.distance2(i, j);
          std::vector<double> v(dim);
          for (std::size_t d = 0; d < dim; ++d) v[d] = e.coordinate(j, d);
          if (gap > 10 && dist2 > resolution * resolution && seen.insert(v).second) {
            d2.push_back(dist2);
          }
        }
        std::sort(d2.begin(), d2.end());
        ASSERT_FALSE(d2.empty());
        const auto knn = index.k_nearest(i, 4, 10);
        ASSERT_EQ(knn.size(), std::min<std::size_t>(4, d2.size()));
        for (std::size_t k = 0; k < knn.size(); ++k) {
          EXPECT_EQ(knn[k].distance2, d2[k]) << "dim " << dim << " query " << i;
          EXPECT_EQ(e.distance2(i, knn[k].index), knn[k].distance2);
        }
        const double r = std::sqrt(d2[d2.size() / 50]);
        const auto inside = std::count_if(d2.begin(), d2.end(), [&](double v) { return v < r * r; });
        EXPECT_EQ(static_cast<std::ptrdiff_t>(index.within(i, r, 10).size()), inside);
      }
    }
  }
}

TEST(Embedding, BatchedQueriesAnswerAsSingleOnes) {
  // Searched in the tree's order, answered in the caller's: the same neighbour for every
  // query, on a record with repeats (grouped vectors) and one without, including queries
  // past the indexed points and repeated queries.
  std::vector<double> quantised(1200);
  for (std::size_t i = 0; i < quantised.size(); ++i) {
    quantised[i] = std::round(8.0 * std::sin(0.07 * i) + 3.0 * std::sin(0.19 * i));
  }
  std::vector<double> chaotic = lorenz_x(1200);
  for (const auto* x : {&chaotic, &quantised}) {
    const DelayEmbedding e(*x, 3, 4);
    const NeighbourIndex index(e, 1000, repeat_resolution(*x));
    std::vector<std::size_t> queries;
    for (std::size_t i = e.size(); i-- > 0;) queries.push_back((i * 37) % e.size());
    queries.push_back(5);
    queries.push_back(5);
    const auto nearest = index.nearest_each(queries, 10);
    const auto knn = index.k_nearest_each(queries, 3, 10);
    ASSERT_EQ(nearest.size(), queries.size());
    ASSERT_EQ(knn.size(), queries.size());
    for (std::size_t q = 0; q < queries.size(); ++q) {
      const Neighbour one = index.nearest(queries[q], 10);
      EXPECT_EQ(nearest[q].index, one.index) << "query " << queries[q];
      EXPECT_EQ(nearest[q].distance2, one.distance2);
      const auto three = index.k_nearest(queries[q], 3, 10);
      ASSERT_EQ(knn[q].size(), three.size());
      for (std::size_t k = 0; k < three.size(); ++k) EXPECT_EQ(knn[q][k].index, three[k].index);
    }
  }
}

TEST(Embedding, BoundedNearestAreTheOpenSearchesEntriesBelowTheBound) {
  // Wolf's replacements search within a radius first; the answer must be the open search's
  // list cut at the radius, in the same order, ties included (the quantised record has many
  // equal distances, and a radius can fall exactly on one of them).
  std::vector<double> quantised(1500);
  for (std::size_t i = 0; i < quantised.size(); ++i) {
    quantised[i] = std::round(8.0 * std::sin(0.07 * i) + 3.0 * std::sin(0.19 * i));
  }
  std::vector<double> chaotic = lorenz_x(1500);
  std::size_t cut = 0, whole = 0;
  for (const auto* x : {&chaotic, &quantised}) {
    const DelayEmbedding e(*x, 2, 3);
    const NeighbourIndex index(e, 0, repeat_resolution(*x));
    for (std::size_t i = 0; i < e.size(); i += 7) {
      const auto open = index.k_nearest(i, 12, 10);
      ASSERT_FALSE(open.empty());
      for (const double r : {0.0, std::sqrt(open.front().distance2),
                             std::sqrt(open[open.size() / 2].distance2) * 1.000001,
                             std::sqrt(open.back().distance2), 1e9}) {
        const auto bounded = index.k_nearest_within(i, 12, 10, r);
        std::size_t below = 0;
        while (below < open.size() && open[below].distance2 < r * r) ++below;
        ASSERT_EQ(bounded.size(), below) << "query " << i << " r " << r;
        for (std::size_t k = 0; k < below; ++k) {
          EXPECT_EQ(bounded[k].index, open[k].index) << "query " << i << " r " << r;
          EXPECT_EQ(bounded[k].distance2, open[k].distance2);
        }
        (below < open.size() ? cut : whole) += 1;
      }
    }
  }
  EXPECT_GT(cut, 100u);  // the bound did cut lists short, and left some whole
  EXPECT_GT(whole, 100u);
}

TEST(Embedding, ExactRepeatsAreSkipped) {
  // A quantised record: many exact repeats, which carry no direction.
  std::vector<double> x(2000);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = std::round(10.0 * std::sin(0.1 * i));
  const DelayEmbedding e(x, 2, 3);
  const NeighbourIndex index(e, 0, repeat_resolution(x));
  for (std::size_t i = 0; i < e.size(); i += 97) {
    const Neighbour nb = index.nearest(i, 5);
    ASSERT_LT(nb.index, e.size());
    EXPECT_GT(nb.distance2, 0.0);
  }
}

// Known answers of the plug-in estimate with two bins: a series alternating 0, 1 (64
// samples) at lag 2 pairs every value with itself (31 + 31 pairs: I = ln 2 exactly); at lag 1
// with the other value (32 pairs (0, 1), 31 pairs (1, 0): I = the entropy of {32, 31} / 63).
TEST(MutualInformation, AlternatingSeriesKnownValues) {
  std::vector<double> x(64);
  for (std::size_t i = 0; i < x.size(); ++i) x[i] = static_cast<double>(i % 2);
  const std::vector<double> I = mutual_information(x, 2, 2);
  const double p = 32.0 / 63.0, q = 31.0 / 63.0;
  EXPECT_NEAR(I[0], std::log(2.0), 1e-14);
  EXPECT_NEAR(I[1], -p * std::log(p) - q * std::log(q), 1e-14);
  EXPECT_NEAR(I[2], std::log(2.0), 1e-14);
}

// The definition, one logarithm per cell (what the analysis computed before it counted in
// integers), on a record with long runs of one value (a stick-slip-like rest at 0 between
// noisy slips) and quantised values, so that bins hold ties and one cell most pairs.
TEST(MutualInformation, MatchesTheDefinitionOnARecordWithRests) {
  std::vector<double> x(6000);
  std::uint64_t state = 12345;
  for (std::size_t i = 0; i < x.size(); ++i) {
    state = state * 6364136223846793005ULL + 1442695040888963407ULL;
    const double u = static_cast<double>(state >> 11) * 0x1p-53;
    const bool slipping = (i / 150) % 3 == 0;
    x[i] = slipping ? std::round(100.0 * (std::sin(0.05 * i) + 0.3 * u)) / 100.0 : 0.0;
  }
  const std::size_t bins = 24, max_lag = 400;
  const std::vector<double> I = mutual_information(x, max_lag, bins);
  // Bins as documented: rank * bins / N, ties taking the bin of the first of equal values.
  std::vector<std::size_t> order(x.size());
  for (std::size_t i = 0; i < order.size(); ++i) order[i] = i;
  std::stable_sort(order.begin(), order.end(), [&](auto a, auto b) { return x[a] < x[b]; });
  std::vector<std::size_t> bin(x.size());
  for (std::size_t r = 0; r < order.size(); ++r) {
    bin[order[r]] = r > 0 && x[order[r]] == x[order[r - 1]] ? bin[order[r - 1]]
                                                             : r * bins / order.size();
  }
  for (const std::size_t lag : {0u, 1u, 7u, 150u, 399u, 400u}) {
    const std::size_t n = x.size() - lag;
    std::vector<double> joint(bins * bins, 0.0), pa(bins, 0.0), pb(bins, 0.0);
    for (std::size_t i = 0; i < n; ++i) {
      joint[bin[i] * bins + bin[i + lag]] += 1.0;
      pa[bin[i]] += 1.0;
      pb[bin[i + lag]] += 1.0;
    }
    double expected = 0.0;
    for (std::size_t a = 0; a < bins; ++a) {
      for (std::size_t b = 0; b < bins; ++b) {
        const double c = joint[a * bins + b];
        if (c > 0.0) expected += c / n * std::log(c * n / (pa[a] * pb[b]));
      }
    }
    EXPECT_NEAR(I[lag], expected, 1e-12 * std::max(1.0, expected)) << "lag " << lag;
  }
  EXPECT_GT(I[0], 1.0);  // the record is far from constant: the check above is not vacuous
}

TEST(EmbeddingParameters, TextbookDelaysAndDimensions) {
  // Lorenz x at dt = 0.01: first AMI minimum near 0.15-0.2 time units (Fraser & Swinney
  // 1986 give ~0.16), dimension 3; Henon: delay 1, dimension 2.
  const auto lorenz = lorenz_x(10000);
  const DelayChoice d = choose_delay(lorenz);
  EXPECT_EQ(d.method, "mutual-information minimum");
  EXPECT_GE(d.delay, 15u);
  EXPECT_LE(d.delay, 20u);
  const Autocorrelation acf = autocorrelation(lorenz, 1.0);
  EXPECT_EQ(choose_dimension(lorenz, d.delay, static_cast<std::size_t>(acf.first_zero_s)).dimension,
            3u);

  const auto henon = henon_map(10000);
  const DelayChoice h = choose_delay(henon);
  EXPECT_EQ(h.delay, 1u);
  EXPECT_EQ(choose_dimension(henon, h.delay, 1).dimension, 2u);
}

TEST(EmbeddingParameters, NoisySineDelayIsAQuarterPeriod) {
  // 10 Hz at 1 kHz: a quarter period is 25 samples (a 16-bin equal-width AMI puts the
  // minimum at ~5, docs/notes/analysis.md).
  const auto x = sine(10000, 10.0, 1000.0, 0.05);
  const DelayChoice d = choose_delay(x);
  EXPECT_GE(d.delay, 22u);
  EXPECT_LE(d.delay, 28u);
}

// A 6.25 Hz orbit at 1 kHz (160 samples) carrying a faster mode at 0.6 of its amplitude, like
// the rig's piston on its mount (docs/notes/analysis.md "Orbital period"): every swing of the
// faster mode is a maximum, so the maxima are 40 (its 4th harmonic) or 43.5 samples (23 Hz, not
// locked) apart; the orbit takes 160.
TEST(OrbitalPeriod, SeesThroughAFasterMode) {
  const auto slow = sine(10000, 6.25, 1000.0, 0.02, 3);
  for (const double f : {25.0, 23.0}) {
    const auto fast = sine(10000, f, 1000.0);
    std::vector<double> x(slow.size());
    for (std::size_t i = 0; i < x.size(); ++i) x[i] = slow[i] + 0.6 * fast[i];
    const double maxima = mean_maxima_spacing(x);
    EXPECT_NEAR(maxima, 1000.0 / f, 2.0) << f;
    EXPECT_NEAR(orbital_period(maxima, spectral_lines(x), x.size()), 160.0, 1.6) << f;
  }
}

// Otherwise the maxima spacing stands: a noisy sine (one line), a golden-ratio torus (its
// maxima follow neither line alone), Lorenz x (its strongest lines are the slow lobe
// switching, far from the maxima's rate) and Rossler x.
TEST(OrbitalPeriod, KeepsTheMaximaSpacingWithoutAFasterMode) {
  const auto a = sine(10000, 10.0, 1000.0, 0.05);
  const auto b = sine(10000, 10.0 * (1.0 + std::sqrt(5.0)) / 2.0, 1000.0);
  std::vector<double> torus(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) torus[i] = a[i] + 0.6 * b[i];
  for (const auto& x : {a, torus, lorenz_x(10000), rossler_x(10000)}) {
    const double maxima = mean_maxima_spacing(x);
    EXPECT_EQ(orbital_period(maxima, spectral_lines(x), x.size()), maxima);
  }
}

}  // namespace
}  // namespace pneumachaos
