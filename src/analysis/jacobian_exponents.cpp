#include "pneumachaos/analysis/jacobian_exponents.hpp"

#include <fmt/format.h>

#include <Eigen/Dense>
#include <algorithm>
#include <cmath>
#include <functional>
#include <limits>

#include "analysis/delay_embedding.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {
namespace {

// Neighbours per fit by default: at least this many, and this many per coordinate, so that
// the affine fit (dimension + 1 unknowns per image coordinate) is over-determined about four
// times and one stray neighbour does not set the map.
constexpr std::size_t kMinNeighbours = 12;
constexpr std::size_t kNeighboursPerDimension = 4;

// Relative size of a neighbourhood's smallest extent (QR pivot) below which it counts as flat:
// far below a flow's thin but real spread across its attractor (1e-3 of the largest extent
// and more), far above the rounding of a computed record (1e-16).
constexpr double kRankTolerance = 1e-8;

std::size_t neighbours_of(const JacobianOptions& o) {
  return o.neighbours > 0 ? o.neighbours
                          : std::max(kMinNeighbours, kNeighboursPerDimension * o.dimension);
}

// The delay used: the option's, capped at half an orbit over the vector's m - 1 delays.
std::size_t delay_of(const JacobianOptions& o) {
  if (o.typical_period == 0 || o.dimension < 2) return o.delay;
  const std::size_t half_orbit = std::max<std::size_t>(1, o.typical_period / (2 * (o.dimension - 1)));
  return std::min(o.delay, half_orbit);
}

// The coordinates a map is fitted in (Eckmann, Kamphorst, Ruelle & Ciliberto 1986): the
// neighbours are found in all m delay coordinates, where the reconstruction is unfolded, but
// the map is fitted in at most three, spread over the same window. A flow needs three
// coordinates to be chaotic (the flow's direction, a stretching one, a contracting one
// across the folds); an attractor about two-dimensional fills no more of a neighbourhood, and
// in the coordinates beyond it the neighbourhood is so thin that the fit's coefficients along
// them are set by the curvature of the others, not by the dynamics: their spurious stretching
// then feeds the largest exponent.
constexpr std::size_t kMaxLocalDimension = 3;

std::size_t local_dimension_of(const JacobianOptions& o) {
  return o.local_dimension > 0 ? std::min(o.local_dimension, o.dimension)
                               : std::min(o.dimension, kMaxLocalDimension);
}

// The local coordinates' delay: theirs span the delay vector's window, (m - 1) delays.
std::size_t local_delay_of(const JacobianOptions& o) {
  const std::size_t l = local_dimension_of(o);
  if (l < 2 || l == o.dimension) return delay_of(o);
  const std::size_t window = (o.dimension - 1) * delay_of(o);
  return std::max<std::size_t>(1, (window + (l - 1) / 2) / (l - 1));
}

// A map spans one delay of the local coordinates by default (Eckmann, Kamphorst, Ruelle &
// Ciliberto 1986). Its image (x[i + d], ..., x[i + l d]) repeats l - 1 of the point's own
// coordinates, so least squares finds those rows exactly and only the last row carries fit
// error; and the true stretch per map is a whole delay's. A shorter map (a fraction of the
// delay) is near the identity with every row fitted: the fits' errors, which raise the
// largest exponent of a product of matrices by about their variance per map whatever the
// true stretch, then weigh several times more against a stretch several times smaller. A
// longer one (two delays) reads higher again on flows: the neighbourhood's images no longer
// follow a linear map (docs/notes/analysis.md).
std::size_t evolve_of(const JacobianOptions& o) {
  return o.evolve > 0 ? o.evolve : local_delay_of(o);
}

// Delay vectors that have an image `evolve` steps on: the points fitted and followed.
std::size_t fitted_points(std::size_t n, const JacobianOptions& o) {
  const std::size_t span = std::max((o.dimension - 1) * delay_of(o),
                                    (local_dimension_of(o) - 1) * local_delay_of(o)) +
                           evolve_of(o);
  return n > span ? n - span : 0;
}

// A Jacobian on one neighbourhood, and the share of its images' variance it leaves
// unexplained (the worst image coordinate's 1 - R^2).
struct LocalMap {
  Eigen::MatrixXd jacobian;
  double unexplained = 0.0;
  bool spans = false;  ///< false: the neighbourhood is flat in some direction; no map
};

// Affine least squares: points and images are centred on their neighbourhood's means, so the
// fit's constant term drops out and the reference point carries no more weight than its
// neighbours (a noisy reference would otherwise bias every map it anchors).
LocalMap fit_local_map(const DelayEmbedding& e, std::size_t reference,
                       std::span<const Neighbour> neighbours, std::size_t evolve) {
  const auto m = static_cast<Eigen::Index>(e.dimension());
  const auto rows = static_cast<Eigen::Index>(neighbours.size() + 1);
  Eigen::MatrixXd points(rows, m), images(rows, m);
  const auto fill = [&](Eigen::Index row, std::size_t j) {
    for (Eigen::Index d = 0; d < m; ++d) {
      points(row, d) = e.coordinate(j, static_cast<std::size_t>(d));
      images(row, d) = e.coordinate(j + evolve, static_cast<std::size_t>(d));
    }
  };
  fill(0, reference);
  for (std::size_t k = 0; k < neighbours.size(); ++k) {
    fill(static_cast<Eigen::Index>(k + 1), neighbours[k].index);
  }
  points.rowwise() -= points.colwise().mean();
  images.rowwise() -= images.colwise().mean();
  // Column-pivoting Householder QR, which also tells whether the neighbourhood spans every
  // coordinate: one that does not (a strictly periodic record, whose nearest non-repeating
  // neighbours all sit one sample along the orbit) determines no map across it.
  Eigen::ColPivHouseholderQR<Eigen::MatrixXd> qr(points);
  qr.setThreshold(kRankTolerance);
  if (qr.rank() < m) return {};
  const Eigen::MatrixXd transposed = qr.solve(images);
  const Eigen::MatrixXd residual = images - points * transposed;
  double worst = 0.0;
  for (Eigen::Index d = 0; d < m; ++d) {
    const double total = images.col(d).squaredNorm();
    if (total > 0.0) worst = std::max(worst, residual.col(d).squaredNorm() / total);
  }
  return {transposed.transpose(), worst, true};
}

// What following the trajectory accumulates.
struct Stretching {
  std::vector<double> log_sum;      ///< per exponent, in the QR's column order
  std::vector<double> largest_log;  ///< each map's log |R_00|, in trajectory order
  std::vector<double> unexplained;  ///< each map's
  std::size_t skipped = 0;
};

// The Jacobians multiplied along the trajectory, re-orthonormalised after each by Householder
// QR (Eckmann & Ruelle 1985): log |R_jj| is the stretching of the j-th direction of the frame.
Stretching follow(const DelayEmbedding& local, const NeighbourIndex& index,
                  const JacobianOptions& o) {
  const std::size_t m = local.dimension(), evolve = evolve_of(o);
  std::vector<std::size_t> references;
  for (std::size_t i = 0; i < index.size(); i += evolve) references.push_back(i);
  const auto neighbourhoods = index.k_nearest_each(references, neighbours_of(o), o.theiler);
  Stretching s;
  s.log_sum.assign(m, 0.0);
  Eigen::MatrixXd frame = Eigen::MatrixXd::Identity(static_cast<Eigen::Index>(m),
                                                    static_cast<Eigen::Index>(m));
  for (std::size_t r = 0; r < references.size(); ++r) {
    // Too few neighbours (exact repeats skipped, a sparse corner) or a flat neighbourhood: no
    // map; the frame is carried to the next point unchanged and this step's time not counted.
    if (neighbourhoods[r].size() < m + 1) {
      ++s.skipped;
      continue;
    }
    const LocalMap map = fit_local_map(local, references[r], neighbourhoods[r], evolve);
    if (!map.spans) {
      ++s.skipped;
      continue;
    }
    s.unexplained.push_back(map.unexplained);
    const Eigen::HouseholderQR<Eigen::MatrixXd> qr(map.jacobian * frame);
    frame = qr.householderQ();
    for (std::size_t j = 0; j < m; ++j) {
      const auto jj = static_cast<Eigen::Index>(j);
      // A direction the map collapses exactly: the smallest normal stretching, not -inf.
      const double stretch =
          std::max(std::abs(qr.matrixQR()(jj, jj)), std::numeric_limits<double>::min());
      s.log_sum[j] += std::log(stretch);
      if (j == 0) s.largest_log.push_back(std::log(stretch));
    }
  }
  return s;
}

// Standard error of the largest exponent from `batches` contiguous, equally long runs of maps.
double batch_standard_error(const std::vector<double>& logs, std::size_t batches,
                            double per_map_s) {
  const std::size_t per_batch = logs.size() / batches;
  if (per_batch == 0) return 0.0;
  std::vector<double> values;
  for (std::size_t b = 0; b < batches; ++b) {
    double sum = 0.0;
    for (std::size_t k = b * per_batch; k < (b + 1) * per_batch; ++k) sum += logs[k];
    values.push_back(sum / (static_cast<double>(per_batch) * per_map_s));
  }
  double mean = 0.0;
  for (double v : values) mean += v / static_cast<double>(batches);
  double var = 0.0;
  for (double v : values) var += (v - mean) * (v - mean);
  return std::sqrt(var / static_cast<double>(batches - 1) / static_cast<double>(batches));
}

// One run of the estimator: the delay vectors' neighbours indexed, the trajectory followed in
// the local coordinates.
Stretching stretching(std::span<const double> x, const JacobianOptions& o) {
  const DelayEmbedding e(x, o.dimension, delay_of(o));
  const DelayEmbedding local(x, local_dimension_of(o), local_delay_of(o));
  const NeighbourIndex index(e, fitted_points(x.size(), o), repeat_resolution(x));
  return follow(local, index, o);
}

double largest_per_s(const Stretching& s, const JacobianOptions& o, double rate_Hz) {
  const double measured_s =
      static_cast<double>(s.largest_log.size() * evolve_of(o)) / rate_Hz;
  return *std::max_element(s.log_sum.begin(), s.log_sum.end()) / measured_s;
}

// What the value depends on beyond the record's stretches, as the divergence exponent's
// uncertainty includes its fit window: the largest change when the neighbourhoods hold twice
// the neighbours, or the maps span twice the steps. A variant the record is too short for is
// left out.
double choice_spread(std::span<const double> x, double rate_Hz, const JacobianOptions& o,
                     double value) {
  JacobianOptions wider = o, longer = o;
  wider.neighbours = 2 * neighbours_of(o);
  longer.evolve = 2 * evolve_of(o);
  double spread = 0.0;
  for (const JacobianOptions& variant : {wider, longer}) {
    try {
      variant.validate(x.size());
    } catch (const Error&) {
      continue;
    }
    const Stretching s = stretching(x, variant);
    if (s.largest_log.size() < 2 * variant.batches) continue;
    spread = std::max(spread, std::abs(largest_per_s(s, variant, rate_Hz) - value));
  }
  return spread;
}

double median(std::vector<double> v) {
  if (v.empty()) return 1.0;
  const auto mid = v.begin() + static_cast<std::ptrdiff_t>(v.size() / 2);
  std::nth_element(v.begin(), mid, v.end());
  return *mid;
}

}  // namespace

void JacobianOptions::validate(std::size_t n) const {
  using namespace validation;
  require_ge(field("jacobian.dimension"), static_cast<double>(dimension), 1);
  require_ge(field("jacobian.delay"), static_cast<double>(delay), 1);
  require(neighbours == 0 || neighbours >= dimension + 1, field("jacobian.neighbours"),
          static_cast<double>(neighbours),
          fmt::format("0 (automatic) or >= {} (an affine map in {} coordinates)", dimension + 1,
                      dimension));
  require_ge(field("jacobian.batches"), static_cast<double>(batches), 2);
  require_gt_le(field("jacobian.max_unexplained"), max_unexplained, 0, 1);
  const std::size_t points = fitted_points(n, *this), evolve = evolve_of(*this);
  const std::size_t maps = points == 0 ? 0 : (points - 1) / evolve + 1;
  const std::size_t needed = std::max(kMinExponentSamples, neighbours_of(*this) + 2 * theiler + 1);
  if (points < needed || maps < 2 * batches) {
    throw Error("jacobian",
                fmt::format("{} samples give {} delay vectors with an image {} steps on ({} local "
                            "maps) at dimension {}, delay {}; at least {} vectors and {} maps "
                            "are needed (Theiler window {}, {} neighbours per map)",
                            n, points, evolve, maps, dimension, delay_of(*this), needed,
                            2 * batches,
                            theiler, neighbours_of(*this)));
  }
}

JacobianResult jacobian_exponents(std::span<const double> x, double rate_Hz,
                                  const JacobianOptions& o) {
  o.validate(x.size());
  if (!(rate_Hz > 0.0)) throw Error("jacobian", "the sample rate must be positive");
  JacobianResult r;
  r.delay = delay_of(o);
  r.evolve = evolve_of(o);
  r.neighbours = neighbours_of(o);
  const Stretching s = stretching(x, o);
  r.maps = s.largest_log.size();
  r.skipped = s.skipped;
  if (r.maps < 2 * o.batches) {
    throw Error("jacobian", fmt::format("only {} of {} reference points had {} neighbours "
                                        "outside the Theiler window spanning all {} "
                                        "coordinates: too few local maps (a strictly periodic "
                                        "or coarsely quantised record)",
                                        r.maps, r.maps + r.skipped,
                                        local_dimension_of(o) + 1, local_dimension_of(o)));
  }
  const double per_map_s = static_cast<double>(r.evolve) / rate_Hz;
  const double measured_s = static_cast<double>(r.maps) * per_map_s;
  for (double l : s.log_sum) r.exponents_per_s.push_back(l / measured_s);
  std::sort(r.exponents_per_s.begin(), r.exponents_per_s.end(), std::greater<>());
  r.lambda_per_s = r.exponents_per_s.front();
  for (double l : r.exponents_per_s) r.sum_per_s += l;
  r.statistical_uncertainty_per_s = batch_standard_error(s.largest_log, o.batches, per_map_s);
  r.choice_spread_per_s = choice_spread(x, rate_Hz, o, r.lambda_per_s);
  r.uncertainty_per_s = std::hypot(r.statistical_uncertainty_per_s, r.choice_spread_per_s);
  r.unexplained = median(s.unexplained);
  r.reliable = r.unexplained <= o.max_unexplained;
  return r;
}

}  // namespace pneumachaos
