#include "pneumachaos/analysis/embedding_parameters.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numeric>

#include "pneumachaos/analysis/autocorrelation.hpp"
#include "analysis/delay_embedding.hpp"
#include "mutual_information.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// Bins per axis of the mutual information: sqrt(N / kSamplesPerBinSquared), clipped to
// [kMinBins, kMaxBins] (the contract of mutual_information's `bins` in the header). The
// joint histogram has B^2 cells, so N / B^2 >= kSamplesPerBinSquared pairs fill each cell on
// average where B is not clipped; the plug-in bias (B - 1)^2 / 2N then stays below
// 1 / (2 kSamplesPerBinSquared).
constexpr double kSamplesPerBinSquared = 10.0;
constexpr std::size_t kMinBins = 8;
constexpr std::size_t kMaxBins = 64;

// Shortest record I(tau) is estimated on: four samples per margin bin at kMinBins bins.
constexpr std::size_t kMinSamples = 32;

// Lags searched by default: a tenth of the record (choose_delay's contract in the header), at
// least kMinLagsSearched.
constexpr std::size_t kRecordShareSearched = 10;
constexpr std::size_t kMinLagsSearched = 8;

// I(tau) is smoothed over +-kSmoothingHalfWidth lags: binning makes it jitter lag to lag.
constexpr std::size_t kSmoothingHalfWidth = 2;

// A minimum counts only once I has fallen at least this share of the way from I(1) to the
// bias floor: shallow dips of the estimate are binning jitter (docs/notes/analysis.md, the
// delay's "first deep minimum").
constexpr double kMinDepth = 0.25;

// I below this multiple of the bias floor is decorrelated: no minimum follows (maps, noise),
// and the delay falls back to the autocorrelation's 1/e time.
constexpr double kDecorrelatedFloors = 3.0;

// A minimum must be the lowest over +-lag / kMinimumWidthDivisor lags (at least
// kSmoothingHalfWidth): a quarter of the lag on either side.
constexpr std::size_t kMinimumWidthDivisor = 4;

// Cao's E1 is averaged over at most this many reference points spread over the record, which
// keeps the dimension's cost near N log N (docs/notes/analysis.md: "1500 reference points").
constexpr std::size_t kCaoReferences = 1500;

// E1 has reached its plateau once two successive values exceed this (Cao 1997: E1 -> 1 for a
// deterministic series once the attractor is unfolded; 0.8 leaves room for a plateau below 1).
constexpr double kPlateauLevel = 0.8;

// Without a plateau (noise), the first d where E1 grows by less than this has flattened.
constexpr double kFlatteningStep = 0.05;

// Orbits shorter than this many samples are no oscillation to take a quarter of (maps, noise).
constexpr double kMinOrbitSamples = 8.0;

std::size_t default_bins(std::size_t n) {
  return std::clamp<std::size_t>(static_cast<std::size_t>(std::sqrt(n / kSamplesPerBinSquared)),
                                 kMinBins, kMaxBins);
}

}  // namespace

std::vector<double> mutual_information(std::span<const double> x, std::size_t max_lag,
                                       std::size_t bins) {
  if (x.size() < kMinSamples) {
    throw Error("mutual information", fmt::format("at least {} samples are needed", kMinSamples));
  }
  if (bins == 0) bins = default_bins(x.size());
  max_lag = std::min(max_lag, x.size() / 2);
  detail::LaggedMutualInformation mi(x, bins);
  std::vector<double> I(max_lag + 1);
  for (std::size_t lag = 0; lag <= max_lag; ++lag) I[lag] = mi.at(lag);
  return I;
}

DelayChoice choose_delay(std::span<const double> x, std::size_t max_lag, double noise_sd) {
  if (x.size() < kMinSamples) {
    throw Error("embedding delay", fmt::format("at least {} samples are needed", kMinSamples));
  }
  if (max_lag == 0) {
    max_lag = std::max<std::size_t>(kMinLagsSearched, x.size() / kRecordShareSearched);
  }
  const std::size_t bins = default_bins(x.size());
  const double resolution = kNoiseBinWidth * noise_sd;
  detail::LaggedMutualInformation mi(x, bins, resolution);
  // Plug-in bias of I for independent data, (B - 1)^2 / (2 N) with B the bins in use: the
  // level the estimate sinks to once the record has decorrelated. Bins merged because the
  // noise cannot tell their values apart are not in use; bins left empty by exact ties count
  // as the record's own binning always has.
  const double in_use =
      static_cast<double>(bins) - static_cast<double>(detail::bins_merged_by(x, bins, resolution));
  const double floor = std::pow(in_use - 1.0, 2) / (2.0 * x.size());
  DelayChoice c;
  const auto I = [&](std::size_t lag) {
    while (c.ami.size() <= lag) c.ami.push_back(mi.at(c.ami.size()));
    return c.ami[lag];
  };
  constexpr std::size_t h = kSmoothingHalfWidth;
  const auto S = [&](std::size_t lag) {
    double sum = 0.0;
    const std::size_t lo = lag >= h ? lag - h : 0;
    for (std::size_t k = lo; k <= lag + h; ++k) sum += I(k);
    return sum / static_cast<double>(lag + h + 1 - lo);
  };
  const double deep_enough = I(1) - kMinDepth * (I(1) - floor);
  bool fallback = false;
  for (std::size_t lag = 2; lag + h <= max_lag && !fallback; ++lag) {
    if (I(lag) < kDecorrelatedFloors * floor) {
      fallback = true;  // decorrelated without a minimum: maps, noise
      break;
    }
    const std::size_t w = std::max<std::size_t>(h, lag / kMinimumWidthDivisor);
    if (lag + w + h > max_lag) break;
    const double here = S(lag);
    if (here > deep_enough) continue;
    bool is_min = true;
    for (std::size_t k = lag - std::min(lag - 1, w); k <= lag + w; ++k) {
      if (S(k) < here) is_min = false;
    }
    if (!is_min) continue;
    // A real minimum is followed by a rise above the estimator's noise within one more delay.
    double rise = 0.0;
    for (std::size_t k = lag + 1; k <= std::min(2 * lag, max_lag - h); ++k) {
      rise = std::max(rise, S(k) - here);
    }
    if (rise > floor) {
      c.delay = lag;
      c.method = "mutual-information minimum";
      return c;
    }
  }
  const Autocorrelation acf = autocorrelation(x, 1.0);
  c.delay = std::max<std::size_t>(1, static_cast<std::size_t>(std::max(acf.one_over_e_s, 1.0)));
  c.method = "autocorrelation 1/e";
  return c;
}

DimensionChoice choose_dimension(std::span<const double> x, std::size_t delay, std::size_t theiler,
                                 std::size_t max_dimension, double saturation) {
  DimensionChoice c;
  const double resolution = repeat_resolution(x);
  // E(d), E*(d) for growing d, stopping as soon as E1 has saturated.
  std::vector<double> E, Es;
  const auto compute = [&](std::size_t d) {
    // Vectors that also exist in dimension d + 1, so one index set serves both; at most
    // kCaoReferences reference points, spread over the record.
    const DelayEmbedding emb(x, d + 1, delay);
    const DelayEmbedding low(x, d, delay);
    const NeighbourIndex index(low, emb.size(), resolution);
    const std::size_t stride = std::max<std::size_t>(1, emb.size() / kCaoReferences);
    std::vector<std::size_t> references;
    for (std::size_t i = 0; i < emb.size(); i += stride) references.push_back(i);
    const std::vector<Neighbour> neighbours = index.nearest_each(references, theiler);
    double sum = 0.0, sum_star = 0.0;
    std::size_t count = 0;
    for (std::size_t r = 0; r < references.size(); ++r) {
      const std::size_t i = references[r];
      const Neighbour& nb = neighbours[r];
      if (nb.index >= emb.size()) continue;
      sum += std::sqrt(emb.distance2(i, nb.index) / nb.distance2);
      sum_star += std::abs(x[i + d * delay] - x[nb.index + d * delay]);
      ++count;
    }
    if (count == 0) throw Error("embedding dimension", "no neighbours outside the Theiler window");
    E.push_back(sum / count);
    Es.push_back(sum_star / count);
  };
  compute(1);
  // E1 climbs to a plateau near (not exactly at) 1 once the attractor is unfolded; its value
  // there varies with the record, so saturation is judged against the plateau itself: the
  // first d with E1(d) >= saturation * plateau, once two successive E1 exceed kPlateauLevel.
  for (std::size_t d = 1; d <= max_dimension; ++d) {
    compute(d + 1);
    c.E1.push_back(E[d] / E[d - 1]);
    c.E2.push_back(Es[d] / Es[d - 1]);
    const std::size_t n = c.E1.size();
    if (n >= 2 && c.E1[n - 1] > kPlateauLevel && c.E1[n - 2] > kPlateauLevel) break;
  }
  const double plateau = *std::max_element(c.E1.begin(), c.E1.end());
  c.dimension = 0;
  for (std::size_t d = 1; d <= c.E1.size() && c.dimension == 0; ++d) {
    if (plateau > kPlateauLevel && c.E1[d - 1] >= saturation * plateau) c.dimension = d;
  }
  // No plateau (noise, or noise-dominated small scales): the first flattening of E1.
  for (std::size_t d = 2; c.dimension == 0 && d <= c.E1.size(); ++d) {
    if (c.E1[d - 1] - c.E1[d - 2] < kFlatteningStep) c.dimension = d - 1;
  }
  if (c.dimension == 0) c.dimension = max_dimension;
  return c;
}

// On an oscillating record the first minimum of I lies near a quarter of the orbit. A minimum
// a whole orbit or more away (dysts's ShimizuMorioka: three orbits, Thomas: two) is a later
// minimum or an artefact of the binning, and with it x(t + tau) nearly repeats x(t): the
// reconstruction folds onto itself.
DelayChoice delay_within_an_orbit(DelayChoice c, double orbit_samples) {
  if (!(orbit_samples >= kMinOrbitSamples) || static_cast<double>(c.delay) < orbit_samples) {
    return c;
  }
  c.method = fmt::format("a quarter of the orbit (the mutual-information minimum at {} samples "
                         "lies an orbit of {:.0f} or more away)",
                         c.delay, orbit_samples);
  c.delay = static_cast<std::size_t>(std::lround(kDelayShareOfOrbit * orbit_samples));
  return c;
}

}  // namespace pneumachaos
