#include "pneumachaos/analysis/autocorrelation.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numbers>
#include <numeric>

#include "analysis/fft.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// Fewest samples accepted (the header's contract).
constexpr std::size_t kMinSamples = 16;

// Lags computed by default: up to N / kLagShare (the header's "default N/4"); the biased
// estimator shrinks r at lag k by (N - k) / N, a quarter at most there.
constexpr std::size_t kLagShare = 4;

// The envelope's maxima are kept while they exceed kNoiseBandWidth / sqrt(N), the approximate
// 95 % band of a white-noise autocorrelation (Bartlett 1946: sd 1/sqrt(N)).
constexpr double kNoiseBandWidth = 2.0;

// Fewest envelope maxima a decay rate is fitted to: two points always fit a line.
constexpr double kMinEnvelopePoints = 3.0;

// The late envelope averages |r| over lags N / kLateStartShare .. N / kLagShare
// (Autocorrelation::late_envelope: "lags N/8 .. N/4").
constexpr std::size_t kLateStartShare = 8;

}  // namespace

std::vector<double> centred_lag_products(std::span<const double> x) {
  const std::size_t n = x.size();
  const double mean = std::accumulate(x.begin(), x.end(), 0.0) / static_cast<double>(n);
  std::vector<double> centred(n);
  for (std::size_t i = 0; i < n; ++i) centred[i] = x[i] - mean;
  // Zero padding to >= 2N makes the circular correlation equal the linear one.
  auto X = forward_dft(centred, fast_fft_size(2 * n));
  for (auto& c : X) c = std::norm(c);
  std::vector<double> raw = inverse_dft_real(X);
  const double scale = 1.0 / static_cast<double>(X.size());  // the inverse's missing 1/size
  raw.resize(n);
  for (double& v : raw) v *= scale;
  return raw;
}

Autocorrelation autocorrelation(std::span<const double> x, double rate_Hz, std::size_t max_lag) {
  const std::size_t n = x.size();
  if (n < kMinSamples) {
    throw Error("autocorrelation",
                fmt::format("{} samples: at least {} are needed", n, kMinSamples));
  }
  if (max_lag == 0 || max_lag >= n) max_lag = n / kLagShare;
  Autocorrelation a;
  a.lag_products = centred_lag_products(x);
  const std::vector<double>& raw = a.lag_products;
  if (!(raw[0] > 0.0)) throw Error("autocorrelation", "the series is constant");
  a.rate_Hz = rate_Hz;
  a.r.resize(max_lag + 1);
  for (std::size_t k = 0; k <= max_lag; ++k) a.r[k] = raw[k] / raw[0];

  for (std::size_t k = 1; k <= max_lag; ++k) {
    if (a.one_over_e_s < 0 && a.r[k] < std::exp(-1.0)) a.one_over_e_s = k / rate_Hz;
    if (a.first_zero_s < 0 && a.r[k] <= 0.0) a.first_zero_s = k / rate_Hz;
  }
  // Envelope: local maxima of |r|.
  std::vector<double> lag, env;
  for (std::size_t k = 1; k + 1 <= max_lag; ++k) {
    const double m = std::abs(a.r[k]);
    if (m >= std::abs(a.r[k - 1]) && m > std::abs(a.r[k + 1])) {
      lag.push_back(k / rate_Hz);
      env.push_back(m);
    }
  }
  const double noise = kNoiseBandWidth / std::sqrt(static_cast<double>(n));
  double st = 0, sl = 0, stt = 0, stl = 0, count = 0;
  for (std::size_t i = 0; i < env.size() && env[i] > noise; ++i) {
    const double l = std::log(env[i]);
    st += lag[i];
    sl += l;
    stt += lag[i] * lag[i];
    stl += lag[i] * l;
    ++count;
  }
  if (count >= kMinEnvelopePoints && count * stt - st * st > 0) {
    a.envelope_decay_per_s = std::max(0.0, -(count * stl - st * sl) / (count * stt - st * st));
  }
  double late = 0.0;
  std::size_t late_count = 0;
  for (std::size_t k = n / kLateStartShare; k <= std::min(max_lag, n / kLagShare); ++k) {
    late += std::abs(a.r[k]);
    ++late_count;
  }
  // The mean of |r| over a window is about 2/pi of its envelope for an oscillation.
  a.late_envelope = late_count ? late / late_count * (std::numbers::pi / 2.0) : 0.0;
  return a;
}

}  // namespace pneumachaos
