#include "pneumachaos/analysis/prediction_error.hpp"

#include <array>
#include <cmath>
#include <vector>

#include "pneumachaos/analysis/delay_embedding.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"

namespace pneumachaos {
namespace {

std::size_t horizon_of(const PredictionOptions& o) {
  return o.horizon > 0 ? o.horizon : std::max<std::size_t>(1, o.delay);
}

// Delay vectors whose target x[i + (m-1) tau + h] exists; 0 when there are too few.
std::size_t usable_vectors(std::size_t n, const PredictionOptions& o) {
  const std::size_t reach = (o.dimension - 1) * o.delay + horizon_of(o);
  const std::size_t needed = 2 * o.theiler + 4 * o.neighbours + 50;
  return n > reach + needed ? n - reach : 0;
}

// Solves the (small, symmetric positive semi-definite) normal equations A b = y in place by
// Gaussian elimination with partial pivoting; a singular direction gets coefficient 0.
template <std::size_t M>
std::array<double, M> solve(std::array<std::array<double, M>, M> A, std::array<double, M> y) {
  for (std::size_t c = 0; c < M; ++c) {
    std::size_t p = c;
    for (std::size_t r = c + 1; r < M; ++r) {
      if (std::abs(A[r][c]) > std::abs(A[p][c])) p = r;
    }
    std::swap(A[c], A[p]);
    std::swap(y[c], y[p]);
    if (std::abs(A[c][c]) < 1e-300) continue;
    for (std::size_t r = c + 1; r < M; ++r) {
      const double f = A[r][c] / A[c][c];
      for (std::size_t k = c; k < M; ++k) A[r][k] -= f * A[c][k];
      y[r] -= f * y[c];
    }
  }
  std::array<double, M> b{};
  for (std::size_t c = M; c-- > 0;) {
    if (std::abs(A[c][c]) < 1e-300) continue;
    double s = y[c];
    for (std::size_t k = c + 1; k < M; ++k) s -= A[c][k] * b[k];
    b[c] = s / A[c][c];
  }
  return b;
}

// Least-squares linear predictor on (1, the first `used` delay coordinates); the RMS of its
// in-sample residual. In-sample favours the linear rule, so the ratio errs towards "noise".
double linear_error(std::span<const double> x, const PredictionOptions& o, std::size_t usable) {
  constexpr std::size_t kMax = 9;  // constant + up to 8 coordinates (Cao searches d <= 8)
  const std::size_t used = std::min(o.dimension, kMax - 1);
  const std::size_t h = horizon_of(o), last = (o.dimension - 1) * o.delay;
  std::array<std::array<double, kMax>, kMax> A{};
  std::array<double, kMax> y{};
  std::array<double, kMax> row{};
  const auto fill = [&](std::size_t i) {
    row.fill(0.0);
    row[0] = 1.0;
    for (std::size_t d = 0; d < used; ++d) row[d + 1] = x[i + last - d * o.delay];
  };
  for (std::size_t i = 0; i < usable; ++i) {
    fill(i);
    const double target = x[i + last + h];
    for (std::size_t a = 0; a < kMax; ++a) {
      y[a] += row[a] * target;
      for (std::size_t b = 0; b < kMax; ++b) A[a][b] += row[a] * row[b];
    }
  }
  for (std::size_t a = used + 1; a < kMax; ++a) A[a][a] = 1.0;  // unused coordinates
  const auto beta = solve<kMax>(A, y);
  double sse = 0.0;
  for (std::size_t i = 0; i < usable; ++i) {
    fill(i);
    double p = 0.0;
    for (std::size_t a = 0; a < kMax; ++a) p += beta[a] * row[a];
    const double e = x[i + last + h] - p;
    sse += e * e;
  }
  return std::sqrt(sse / static_cast<double>(usable));
}

}  // namespace

double nonlinear_prediction_error(std::span<const double> x, const PredictionOptions& o) {
  const std::size_t usable = usable_vectors(x.size(), o);
  const double sd = standard_deviation(x);
  if (usable == 0 || o.dimension == 0 || o.delay == 0 || !(sd > 0.0)) return -1.0;
  const std::size_t h = horizon_of(o), last = (o.dimension - 1) * o.delay;
  const DelayEmbedding e(x, o.dimension, o.delay);
  const NeighbourIndex index(e, usable, repeat_resolution(x));
  const std::size_t stride = std::max<std::size_t>(1, usable / o.max_references);
  double sse = 0.0;
  std::size_t count = 0;
  for (std::size_t i = 0; i < usable; i += stride) {
    const auto nbs = index.k_nearest(i, o.neighbours, o.theiler);
    if (nbs.empty()) continue;
    double p = 0.0;
    for (const Neighbour& nb : nbs) p += x[nb.index + last + h];
    const double err = x[i + last + h] - p / static_cast<double>(nbs.size());
    sse += err * err;
    ++count;
  }
  return count > 0 ? std::sqrt(sse / static_cast<double>(count)) / sd : -1.0;
}

PredictionErrors prediction_errors(std::span<const double> x, const PredictionOptions& o) {
  PredictionErrors r;
  r.horizon = horizon_of(o);
  const double nonlinear = nonlinear_prediction_error(x, o);
  if (nonlinear < 0.0) return r;
  r.nonlinear = nonlinear;
  r.linear = linear_error(x, o, usable_vectors(x.size(), o)) / standard_deviation(x);
  r.computed = true;
  return r;
}

}  // namespace pneumachaos
