#include "pneumachaos/analysis/zero_one_test.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <complex>
#include <numbers>
#include <random>
#include <vector>

#include "analysis/fft.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {
namespace {

// The mean square displacement is read up to n_cut = N / kDisplacementShare (Gottwald &
// Melbourne 2009 use n_cut = N / 10: n_cut << N keeps each displacement an average).
constexpr std::size_t kDisplacementShare = 10;

// Frequencies c are drawn from (pi / 5, 4 pi / 5), the interval Gottwald & Melbourne 2009 draw
// them from (docs/notes/analysis.md "The 0-1 test").
constexpr double kLowestFrequency = std::numbers::pi / 5.0;
constexpr double kFrequencyRange = 3.0 * std::numbers::pi / 5.0;

// Fewest points the validator accepts for min_points: at 20 points n_cut = N / 10 is 2, the
// fewest displacements a correlation with n can be computed on.
constexpr std::size_t kFewestPoints = 20;

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

// Mean square displacement of the walk z = p + i q for n = 1 .. ncut, averaged over the
// first S = N - ncut starts: |z_{j+n} - z_j|^2 = |z_{j+n}|^2 + |z_j|^2 - 2 Re conj(z_j) z_{j+n};
// the cross term for every n at once by one correlation through the FFT (N log N instead of
// N ncut per frequency; no wrap-around, since j + n < N <= the transform length).
std::vector<double> mean_square_displacement(const std::vector<std::complex<double>>& z,
                                             std::size_t ncut, const DftPlan& plan) {
  const std::size_t N = z.size(), S = N - ncut, L = plan.size();
  std::vector<std::complex<double>> a(L, 0.0), b(L, 0.0), A, B;
  for (std::size_t j = 0; j < N; ++j) {
    b[j] = z[j];
    if (j < S) a[j] = z[j];
  }
  plan.transform(a, A, false);
  plan.transform(b, B, false);
  for (std::size_t k = 0; k < L; ++k) A[k] = std::conj(A[k]) * B[k];
  plan.transform(A, B, true);
  std::vector<double> prefix(N + 1, 0.0);  // prefix sums of |z_j|^2
  for (std::size_t j = 0; j < N; ++j) prefix[j + 1] = prefix[j] + std::norm(z[j]);
  std::vector<double> M(ncut);
  for (std::size_t n = 1; n <= ncut; ++n) {
    const double cross = B[n].real() / static_cast<double>(L);
    M[n - 1] = (prefix[S + n] - prefix[n] + prefix[S] - 2.0 * cross) / static_cast<double>(S);
  }
  return M;
}

// e^{i k c} for k = 1 .. count: each from the one before by one rotation, and from the
// library's sine and cosine every kAnchor steps, so the rounding of the products cannot
// build up beyond ~kAnchor ulp (1e-14; one sine and cosine per sample and frequency cost a
// tenth of a 1e4 analysis: docs/notes/performance.md).
std::vector<std::complex<double>> unit_phases(std::size_t count, double c) {
  constexpr std::size_t kAnchor = 64;
  std::vector<std::complex<double>> e(count);
  const std::complex<double> step = std::polar(1.0, c);
  for (std::size_t k = 0; k < count; ++k) {
    e[k] = k % kAnchor == 0 ? std::polar(1.0, static_cast<double>(k + 1) * c) : e[k - 1] * step;
  }
  return e;
}

// K_c for one frequency c: the walk driven by phi, its mean square displacement minus the
// oscillatory term of the 2009 paper (eq. 3.4: (E phi)^2 (1 - cos nc) / (1 - cos c)),
// correlated with n.
double k_of_c(const std::vector<double>& phi, double mean, double c, const DftPlan& plan) {
  const std::size_t N = phi.size(), ncut = N / kDisplacementShare;
  const std::vector<std::complex<double>> e = unit_phases(N, c);
  std::vector<std::complex<double>> z(N);
  std::complex<double> walk = 0.0;
  for (std::size_t j = 0; j < N; ++j) {
    walk += phi[j] * e[j];
    z[j] = walk;
  }
  const std::vector<double> M = mean_square_displacement(z, ncut, plan);
  std::vector<double> xi(ncut), D(ncut);
  const double one_minus_cos_c = 1.0 - e[0].real();
  for (std::size_t n = 1; n <= ncut; ++n) {
    xi[n - 1] = static_cast<double>(n);
    D[n - 1] = M[n - 1] - mean * mean * (1.0 - e[n - 1].real()) / one_minus_cos_c;
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
  using namespace validation;
  require_ge(field("zero_one.frequencies"), static_cast<double>(frequencies), 1);
  require_ge(field("zero_one.min_points"), static_cast<double>(min_points),
             static_cast<double>(kFewestPoints));
  require_ge(field("zero_one.max_points"), static_cast<double>(max_points),
             static_cast<double>(min_points), "min_points");
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
  const DftPlan plan(fast_fft_size(phi.size()));
  for (std::size_t k = 0; k < o.frequencies; ++k) {
    const double u = static_cast<double>(rng() >> 11) * 0x1.0p-53;
    const double c = kLowestFrequency + u * kFrequencyRange;
    K.push_back(k_of_c(phi, mean, c, plan));
  }
  r.K = quantile(K, 0.5);
  r.K_q25 = quantile(K, 0.25);
  r.K_q75 = quantile(K, 0.75);
  r.run = true;
  return r;
}

}  // namespace pneumachaos
