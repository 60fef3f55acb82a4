#include "pneumachaos/analysis/prediction_error.hpp"

#include <Eigen/Dense>

#include <array>
#include <cmath>
#include <vector>

#include "analysis/delay_embedding.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// The errors are computed only on records with 2 theiler + kNeighbourSlack x neighbours +
// kMinSpareVectors usable delay vectors: room outside the Theiler window for several times
// the neighbours averaged, and rows to spare for the linear predictor's least squares.
constexpr std::size_t kNeighbourSlack = 4;
constexpr std::size_t kMinSpareVectors = 50;

// The linear predictor uses at most this many delay coordinates: Cao's method searches
// dimensions up to 8 (choose_dimension's default max_dimension).
constexpr std::size_t kMaxCoordinates = 8;

std::size_t horizon_of(const PredictionOptions& o) {
  return o.horizon > 0 ? o.horizon : std::max<std::size_t>(1, o.delay);
}

// Delay vectors whose target x[i + (m-1) tau + h] exists; 0 when there are too few.
std::size_t usable_vectors(std::size_t n, const PredictionOptions& o) {
  const std::size_t reach = (o.dimension - 1) * o.delay + horizon_of(o);
  const std::size_t needed = 2 * o.theiler + kNeighbourSlack * o.neighbours + kMinSpareVectors;
  return n > reach + needed ? n - reach : 0;
}

// Least-squares linear predictor on (1, the first `used` delay coordinates); the RMS of its
// in-sample residual. In-sample favours the linear rule, so the ratio errs towards "noise".
// Solved by Eigen's column-pivoting QR of the design matrix (not the normal equations, which
// square its condition number); a direction the data do not span gets no weight.
double linear_error(std::span<const double> x, const PredictionOptions& o, std::size_t usable) {
  const std::size_t used = std::min(o.dimension, kMaxCoordinates);
  const std::size_t h = horizon_of(o), last = (o.dimension - 1) * o.delay;
  const auto rows = static_cast<Eigen::Index>(usable);
  Eigen::MatrixXd design(rows, static_cast<Eigen::Index>(used + 1));
  Eigen::VectorXd target(rows);
  for (Eigen::Index i = 0; i < rows; ++i) {
    const auto k = static_cast<std::size_t>(i);
    design(i, 0) = 1.0;
    for (std::size_t d = 0; d < used; ++d) {
      design(i, static_cast<Eigen::Index>(d + 1)) = x[k + last - d * o.delay];
    }
    target(i) = x[k + last + h];
  }
  const Eigen::VectorXd beta = design.colPivHouseholderQr().solve(target);
  return (design * beta - target).norm() / std::sqrt(static_cast<double>(usable));
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
  std::vector<std::size_t> references;
  for (std::size_t i = 0; i < usable; i += stride) references.push_back(i);
  const auto neighbours = index.k_nearest_each(references, o.neighbours, o.theiler);
  double sse = 0.0;
  std::size_t count = 0;
  for (std::size_t r = 0; r < references.size(); ++r) {
    const std::size_t i = references[r];
    const std::vector<Neighbour>& nbs = neighbours[r];
    if (nbs.empty()) continue;
    double p = 0.0;
    for (const Neighbour& nb : nbs) p += x[nb.index + last + h];
    const double err = x[i + last + h] - p / static_cast<double>(nbs.size());
    sse += err * err;
    ++count;
  }
  return count > 0 ? std::sqrt(sse / static_cast<double>(count)) / sd : -1.0;
}

void PredictionOptions::validate() const {
  using namespace validation;
  require_ge(field("prediction.dimension"), static_cast<double>(dimension), 1);
  require_ge(field("prediction.delay"), static_cast<double>(delay), 1);
  require_ge(field("prediction.neighbours"), static_cast<double>(neighbours), 1);
  require_ge(field("prediction.max_references"), static_cast<double>(max_references), 1);
}

PredictionErrors prediction_errors(std::span<const double> x, const PredictionOptions& o) {
  o.validate();
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
