#include "pneumachaos/analysis/zero_one_test.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

double correlation(const std::vector<double>& a, const std::vector<double>& b) {
  const double n = static_cast<double>(a.size());
  double ma = 0, mb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    ma += a[i];
    mb += b[i];
  }
  ma /= n;
  mb /= n;
  double sab = 0, saa = 0, sbb = 0;
  for (std::size_t i = 0; i < a.size(); ++i) {
    sab += (a[i] - ma) * (b[i] - mb);
    saa += (a[i] - ma) * (a[i] - ma);
    sbb += (b[i] - mb) * (b[i] - mb);
  }
  return saa > 0 && sbb > 0 ? sab / std::sqrt(saa * sbb) : 0.0;
}

// K_c for one frequency c: the walk, its mean square displacement M(n) for n <= N/10 averaged
// over the first N - N/10 starting points, minus the oscillatory term of the 2009 paper
// (eq. 3.4: (E phi)^2 (1 - cos nc) / (1 - cos c)), correlated with n.
double k_of_c(const std::vector<double>& phi, double mean, double c) {
  const std::size_t N = phi.size(), ncut = N / 10;
  std::vector<double> p(N + 1, 0.0), q(N + 1, 0.0);
  for (std::size_t j = 0; j < N; ++j) {
    p[j + 1] = p[j] + phi[j] * std::cos(static_cast<double>(j + 1) * c);
    q[j + 1] = q[j] + phi[j] * std::sin(static_cast<double>(j + 1) * c);
  }
  std::vector<double> xi(ncut), D(ncut);
  const std::size_t starts = N - ncut;
  for (std::size_t n = 1; n <= ncut; ++n) {
    double m = 0.0;
    for (std::size_t j = 1; j <= starts; ++j) {
      const double dp = p[j + n] - p[j], dq = q[j + n] - q[j];
      m += dp * dp + dq * dq;
    }
    const double nd = static_cast<double>(n);
    xi[n - 1] = nd;
    D[n - 1] = m / static_cast<double>(starts) -
               mean * mean * (1.0 - std::cos(nd * c)) / (1.0 - std::cos(c));
  }
  return correlation(xi, D);
}

double quantile(std::vector<double> v, double q) {
  std::sort(v.begin(), v.end());
  const double pos = q * static_cast<double>(v.size() - 1);
  const auto lo = static_cast<std::size_t>(std::floor(pos));
  const std::size_t hi = std::min(lo + 1, v.size() - 1);
  return v[lo] + (pos - static_cast<double>(lo)) * (v[hi] - v[lo]);
}

}  // namespace

void ZeroOneOptions::validate() const {
  if (frequencies == 0) throw Error("zero_one.frequencies", "must be at least 1");
  if (min_points < 20) throw Error("zero_one.min_points", "must be at least 20");
  if (max_points < min_points) throw Error("zero_one.max_points", "must be >= min_points");
}

ZeroOneResult zero_one_test(std::span<const double> x, std::size_t step,
                            const ZeroOneOptions& o) {
  o.validate();
  ZeroOneResult r;
  r.step = std::max<std::size_t>(1, step);
  std::vector<double> phi;
  for (std::size_t i = 0; i < x.size() && phi.size() < o.max_points; i += r.step) {
    phi.push_back(x[i]);
  }
  r.points = phi.size();
  if (r.points < o.min_points) {
    r.reason = fmt::format("not run: {} points after down-sampling by {}, at least {} needed",
                           r.points, r.step, o.min_points);
    return r;
  }
  double mean = 0.0;
  for (double v : phi) mean += v;
  mean /= static_cast<double>(phi.size());
  // Our own uniform draw from mt19937_64's 53 top bits: portable between standard libraries.
  std::mt19937_64 rng(o.seed);
  std::vector<double> K;
  for (std::size_t k = 0; k < o.frequencies; ++k) {
    const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
    const double c = std::numbers::pi / 5.0 + u * (3.0 * std::numbers::pi / 5.0);
    K.push_back(k_of_c(phi, mean, c));
  }
  r.K = quantile(K, 0.5);
  r.K_q25 = quantile(K, 0.25);
  r.K_q75 = quantile(K, 0.75);
  r.run = true;
  return r;
}

}  // namespace pneumachaos
