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

std::size_t default_bins(std::size_t n) {
  return std::clamp<std::size_t>(static_cast<std::size_t>(std::sqrt(n / 10.0)), 8, 64);
}

}  // namespace

std::vector<double> mutual_information(std::span<const double> x, std::size_t max_lag,
                                       std::size_t bins) {
  if (x.size() < 32) throw Error("mutual information", "at least 32 samples are needed");
  if (bins == 0) bins = default_bins(x.size());
  max_lag = std::min(max_lag, x.size() / 2);
  detail::LaggedMutualInformation mi(x, bins);
  std::vector<double> I(max_lag + 1);
  for (std::size_t lag = 0; lag <= max_lag; ++lag) I[lag] = mi.at(lag);
  return I;
}

DelayChoice choose_delay(std::span<const double> x, std::size_t max_lag, double noise_sd) {
  if (x.size() < 32) throw Error("embedding delay", "at least 32 samples are needed");
  if (max_lag == 0) max_lag = std::max<std::size_t>(8, x.size() / 10);
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
  // Smoothed over +-2 lags: binning makes the estimate jitter from lag to lag.
  const auto S = [&](std::size_t lag) {
    double sum = 0.0;
    const std::size_t lo = lag >= 2 ? lag - 2 : 0;
    for (std::size_t k = lo; k <= lag + 2; ++k) sum += I(k);
    return sum / static_cast<double>(lag + 3 - lo);
  };
  const double deep_enough = I(1) - 0.25 * (I(1) - floor);
  bool fallback = false;
  for (std::size_t lag = 2; lag + 2 <= max_lag && !fallback; ++lag) {
    if (I(lag) < 3.0 * floor) {
      fallback = true;  // decorrelated without a minimum: maps, noise
      break;
    }
    const std::size_t w = std::max<std::size_t>(2, lag / 4);
    if (lag + w + 2 > max_lag) break;
    const double here = S(lag);
    if (here > deep_enough) continue;
    bool is_min = true;
    for (std::size_t k = lag - std::min(lag - 1, w); k <= lag + w; ++k) {
      if (S(k) < here) is_min = false;
    }
    if (!is_min) continue;
    // A real minimum is followed by a rise above the estimator's noise within one more delay.
    double rise = 0.0;
    for (std::size_t k = lag + 1; k <= std::min(2 * lag, max_lag - 2); ++k) {
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
    // 1500 reference points (spread over the record) keep the cost near N log N.
    const DelayEmbedding emb(x, d + 1, delay);
    const DelayEmbedding low(x, d, delay);
    const NeighbourIndex index(low, emb.size(), resolution);
    const std::size_t stride = std::max<std::size_t>(1, emb.size() / 1500);
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
  // first d with E1(d) >= saturation * plateau, once two successive E1 exceed 0.8.
  for (std::size_t d = 1; d <= max_dimension; ++d) {
    compute(d + 1);
    c.E1.push_back(E[d] / E[d - 1]);
    c.E2.push_back(Es[d] / Es[d - 1]);
    const std::size_t n = c.E1.size();
    if (n >= 2 && c.E1[n - 1] > 0.8 && c.E1[n - 2] > 0.8) break;
  }
  const double plateau = *std::max_element(c.E1.begin(), c.E1.end());
  c.dimension = 0;
  for (std::size_t d = 1; d <= c.E1.size() && c.dimension == 0; ++d) {
    if (plateau > 0.8 && c.E1[d - 1] >= saturation * plateau) c.dimension = d;
  }
  // No plateau (noise, or noise-dominated small scales): the first flattening of E1.
  for (std::size_t d = 2; c.dimension == 0 && d <= c.E1.size(); ++d) {
    if (c.E1[d - 1] - c.E1[d - 2] < 0.05) c.dimension = d - 1;
  }
  if (c.dimension == 0) c.dimension = max_dimension;
  return c;
}

// On an oscillating record the first minimum of I lies near a quarter of the orbit. A minimum
// a whole orbit or more away (dysts's ShimizuMorioka: three orbits, Thomas: two) is a later
// minimum or an artefact of the binning, and with it x(t + tau) nearly repeats x(t): the
// reconstruction folds onto itself.
DelayChoice delay_within_an_orbit(DelayChoice c, double orbit_samples) {
  if (!(orbit_samples >= 8.0) || static_cast<double>(c.delay) < orbit_samples) return c;
  c.method = fmt::format("a quarter of the orbit (the mutual-information minimum at {} samples "
                         "lies an orbit of {:.0f} or more away)",
                         c.delay, orbit_samples);
  c.delay = static_cast<std::size_t>(std::lround(0.25 * orbit_samples));
  return c;
}

}  // namespace pneumachaos
