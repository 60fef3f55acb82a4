#include "pneumachaos/analysis/lyapunov_wolf.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "analysis/continuous_alignment.hpp"
#include "analysis/delay_embedding.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"

namespace pneumachaos {
namespace {

// Evolution interval's default: a quarter of the orbital period (WolfOptions::evolve;
// docs/notes/analysis.md "evolution 1/4 period").
constexpr std::size_t kEvolvesPerPeriod = 4;

// Smallest separation's default, as a share of the attractor's diameter (WolfOptions::
// min_scale): pairs closer than this have collapsed onto one state and carry no direction.
constexpr double kMinScaleShareOfDiameter = 1e-4;

// A candidate exactly at the search radius must not be lost to the rounding of the tree's
// squared distances against the separation's square root: the bounded search reaches this
// far beyond the radius.
constexpr double kRadiusRounding = 1e-9;

// Without a candidate within the radius, it is widened by doubling up to this factor; beyond
// it the nearest candidate is taken whatever its orientation, so a replacement stays close.
constexpr double kMaxRadiusWidening = 8.0;

// Delay vectors a record must have beyond one evolution and the Theiler window.
constexpr std::size_t kMinSpareVectors = 20;

// The median nearest-neighbour distance that sets the scales is read on about this many
// reference points spread over the record, not on every sample: a median, not a census.
constexpr std::size_t kScaleSamples = 300;

// Replacement candidates judged per search: the few dozen nearest points around the fiducial
// one, among which the best-oriented is chosen.
constexpr std::size_t kCandidates = 40;

}  // namespace

void WolfOptions::validate(std::size_t n) const {
  using namespace validation;
  require_ge(field("wolf.dimension"), static_cast<double>(dimension), 1);
  require_ge(field("wolf.delay"), static_cast<double>(delay), 1);
  if (n < kMinExponentSamples) {
    throw Error("wolf", fmt::format("{} samples: at least {} are needed", n, kMinExponentSamples));
  }
  require_ge(field("wolf.max_scale"), max_scale, 0);
  require_ge(field("wolf.candidate_scale"), candidate_scale, 0);
  require_ge(field("wolf.min_scale"), min_scale, 0);
  require_gt(field("wolf.scale_factor"), scale_factor, 0);
}

namespace {

struct Candidate {
  double time, distance;
  double misalignment;  ///< lower is better: the distance (first neighbour) or minus the cosine
};

// A neighbour followed along the fiducial trajectory.
struct Pair {
  double time = -1.0;  ///< (fractional) index of the neighbour; < 0: none
  std::size_t age = 0;
  [[nodiscard]] bool exists() const { return time >= 0.0; }
};

std::size_t typical_period(std::span<const double> x, const WolfOptions& o) {
  return o.typical_period > 0 ? o.typical_period
                              : static_cast<std::size_t>(std::lround(mean_maxima_spacing(x)));
}

double attractor_diameter(std::span<const double> x, const WolfOptions& o) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double diameter = (*hi - *lo) * std::sqrt(static_cast<double>(o.dimension));
  if (!(diameter > 0.0)) throw Error("wolf", "the series is constant");
  return diameter;
}

// The space Wolf's program works in: the embedded record, its neighbour index and the
// scales of replacement, with the two operations the program needs (measure a separation,
// choose a neighbour).
class WolfGeometry {
 public:
  WolfGeometry(std::span<const double> x, const WolfOptions& o)
      : o_(o),
        e_(x, o.dimension, o.delay),
        period_(typical_period(x, o)),
        evolve_(o.evolve > 0 ? o.evolve : std::max<std::size_t>(1, period_ / kEvolvesPerPeriod)),
        diameter_(attractor_diameter(x, o)),
        min_scale_(o.min_scale > 0.0 ? o.min_scale : kMinScaleShareOfDiameter * diameter_),
        aligned_(o.align && is_oversampled_flow(o.delay)),
        // One sample of margin on each side for the interpolation stencil of aligned neighbours.
        margin_(aligned_ ? 2 : 0),
        usable_(checked_usable()),
        index_(e_, usable_, std::max(repeat_resolution(x), min_scale_)),
        flow_(is_oversampled_flow(o.delay)),
        nn_scale_(o.max_scale > 0.0 && (o.candidate_scale > 0.0 || !flow_) ? 0.0 : median_nn()),
        // Replacement scale: as small as the data density allows (Wolf et al.: the smaller
        // the better while neighbours remain).
        max_scale_(o.max_scale > 0.0 ? o.max_scale : o.scale_factor * nn_scale_),
        // Replacement candidates: for flows the closest ones (a farther start leaves the
        // linear regime sooner, while the settling period aligns the orientation anyway); for
        // maps the best-oriented within max_scale.
        candidate_scale_(o.candidate_scale > 0.0 ? o.candidate_scale
                         : flow_                  ? nn_scale_
                                                  : max_scale_),
        cand_(o.dimension) {}

  [[nodiscard]] std::size_t period() const { return period_; }
  [[nodiscard]] std::size_t evolve() const { return evolve_; }
  [[nodiscard]] std::size_t margin() const { return margin_; }
  [[nodiscard]] std::size_t usable() const { return usable_; }
  [[nodiscard]] bool flow() const { return flow_; }
  [[nodiscard]] double min_scale() const { return min_scale_; }
  [[nodiscard]] double max_scale() const { return max_scale_; }
  [[nodiscard]] double candidate_scale() const { return candidate_scale_; }

  // Separation vector from fiducial point i to the neighbour at (fractional) time j.
  double separation(std::size_t i, double j, std::vector<double>& out) const {
    double d2 = 0.0;
    for (std::size_t d = 0; d < o_.dimension; ++d) {
      const double other = aligned_ ? interpolated_coordinate(e_, j, d)
                                    : e_.coordinate(static_cast<std::size_t>(j), d);
      out[d] = other - e_.coordinate(i, d);
      d2 += out[d] * out[d];
    }
    return std::sqrt(d2);
  }

  // A neighbour for fiducial point fid: the best-oriented (relative to old_sep; with none,
  // the nearest) within radius, widening it up to 8x; -1 when there is no candidate.
  double choose(std::size_t fid, const std::vector<double>* old_sep, double radius,
                double& d_out) {
    // Usually a candidate lies within the radius itself, and it is chosen from the candidates
    // there alone: those are the pool's entries that close (the separation is the tree's
    // distance when neighbours are not aligned in time), found by a search bounded by it.
    if (!aligned_) {
      collect_candidates(fid, old_sep, radius * (1.0 + kRadiusRounding));
      if (const Candidate* best = best_within(radius)) {
        d_out = best->distance;
        return best->time;
      }
    }
    collect_candidates(fid, old_sep, kOpen);
    if (pool_.empty()) {
      d_out = 0.0;
      return -1.0;
    }
    for (double scale = radius; scale <= kMaxRadiusWidening * radius; scale *= 2.0) {
      if (const Candidate* best = best_within(scale)) {
        d_out = best->distance;
        return best->time;
      }
    }
    const auto nearest =
        std::min_element(pool_.begin(), pool_.end(),
                         [](const auto& a, const auto& b) { return a.distance < b.distance; });
    d_out = nearest->distance;
    return nearest->time;
  }

 private:
  std::size_t checked_usable() const {
    if (e_.size() < evolve_ + o_.theiler + kMinSpareVectors) {
      throw Error("wolf", "the series is too short");
    }
    return e_.size() - evolve_ - margin_;
  }

  // Scales follow the data density: the median nearest-neighbour distance, sampled.
  double median_nn() const {
    std::vector<double> nn;
    const std::size_t stride = std::max<std::size_t>(1, usable_ / kScaleSamples);
    for (std::size_t i = margin_; i < usable_; i += stride) {
      const Neighbour nb = index_.nearest(i, o_.theiler);
      if (nb.index < usable_) nn.push_back(std::sqrt(nb.distance2));
    }
    if (nn.empty()) {
      throw Error("wolf", fmt::format("no neighbours outside the Theiler window ({} samples): a "
                                      "longer record, or a shorter --theiler",
                                      o_.theiler));
    }
    std::nth_element(nn.begin(), nn.begin() + nn.size() / 2, nn.end());
    return nn[nn.size() / 2];
  }

  double place(std::size_t i, std::size_t j) const {
    return static_cast<double>(j) + (aligned_ && j >= margin_ ? closest_offset(e_, i, j) : 0.0);
  }

  // The best-oriented candidate of the pool within distance `scale`, or null.
  const Candidate* best_within(double scale) const {
    const Candidate* best = nullptr;
    for (const Candidate& c : pool_) {
      if (c.distance <= scale && (best == nullptr || c.misalignment < best->misalignment))
        best = &c;
    }
    return best;
  }

  // The nearest few dozen around the fiducial point (those closer than `limit`), each placed
  // (aligned in time for flows) and measured once before its scale and orientation are judged.
  static constexpr double kOpen = std::numeric_limits<double>::infinity();
  void collect_candidates(std::size_t fid, const std::vector<double>* old_sep, double limit) {
    pool_.clear();
    double old_norm = 0.0;
    if (old_sep != nullptr) {
      for (double c : *old_sep) old_norm += c * c;
      old_norm = std::sqrt(old_norm);
    }
    const std::vector<Neighbour> near =
        limit == kOpen ? index_.k_nearest(fid, kCandidates, o_.theiler)
                       : index_.k_nearest_within(fid, kCandidates, o_.theiler, limit);
    for (const Neighbour& c : near) {
      if (c.index >= usable_ || c.index < margin_) continue;
      const double j = place(fid, c.index);
      const double d = separation(fid, j, cand_);
      if (d < min_scale_) continue;
      double misalignment = d;  // the first neighbour: simply the nearest
      if (old_sep != nullptr) {
        // The smallest angle to the old separation is the largest cosine: acos is decreasing,
        // and costs a fifth of a whole analysis of the Henon map, where replacements are frequent.
        double dot = 0.0;
        for (std::size_t k = 0; k < o_.dimension; ++k) dot += cand_[k] * (*old_sep)[k];
        misalignment = -std::clamp(dot / (d * old_norm), -1.0, 1.0);
      }
      pool_.push_back({j, d, misalignment});
    }
  }

  const WolfOptions& o_;
  const DelayEmbedding e_;
  const std::size_t period_, evolve_;
  const double diameter_, min_scale_;
  const bool aligned_;
  const std::size_t margin_, usable_;
  const NeighbourIndex index_;
  const bool flow_;
  const double nn_scale_, max_scale_, candidate_scale_;
  std::vector<double> cand_;
  std::vector<Candidate> pool_;
};

// Stretching summed per chain and, pooled over chains, per contiguous batch of the record:
// the chains share the record, so their spread misses how the estimate varies along it;
// contiguous batches see that.
struct Stretching {
  static constexpr std::size_t kBatches = 10;
  std::vector<double> chain_log, chain_time;
  std::vector<double> batch_log = std::vector<double>(kBatches, 0.0);
  std::vector<double> batch_time = std::vector<double>(kBatches, 0.0);
  explicit Stretching(std::size_t chains) : chain_log(chains, 0.0), chain_time(chains, 0.0) {}
};

// A freshly chosen neighbour is close partly by coincidence of the delay coordinates; its
// distance first grows faster than the Lyapunov rate (on Lorenz x about twice as fast for
// one orbital period: the initial transient of every divergence curve). For flows each
// pair is therefore measured only once it has evolved for one period. So that no stretch
// of the fiducial trajectory goes unmeasured (skipping the periods after replacements
// skips the contractions that follow strong stretching: +20-50 % on Lorenz), the
// replacement is chosen when the measured pair reaches max_scale and settles while the
// old pair is still measured; the old pair hands over once the new one has settled.
// Maps need no settling: a replacement takes over at once, as in Wolf's program.
class Chain {
 public:
  Chain(WolfGeometry& g, const WolfOptions& o, std::size_t c, std::size_t chains, double dt,
        Stretching& s, WolfResult& r)
      : g_(g), c_(c), dt_(dt), settle_(o.settle > 0 ? o.settle : g.flow() ? g.period() : 0),
        s_(s), r_(r), sep_(o.dimension),
        // Chains start at staggered points of the first orbit and pool their stretching: one
        // chain on a finite record rests on a few dozen replacements.
        fid_(g.margin() + (c * std::max<std::size_t>(g.period(), 1)) / chains) {}

  void follow() {
    // A chain staggered past the record's end (an orbit as long as the record) has nothing
    // to follow.
    if (fid_ + g_.evolve() >= g_.usable()) return;
    measured_ = Pair{g_.choose(fid_, nullptr, g_.candidate_scale(), d_prev_), 0};
    while (fid_ + g_.evolve() < g_.usable()) step();
  }

 private:
  void step() {
    fid_ += g_.evolve();
    age_pairs();
    if (!measured_.exists()) {  // hand over early, or start afresh
      if (incoming_.exists()) {
        hand_over();
      } else {
        measured_ = fresh();
      }
      return;
    }
    const double d = g_.separation(fid_, measured_.time, sep_);
    if (measured_.age >= settle_ && d_prev_ > 0.0 && d > 0.0) count(std::log(d / d_prev_));
    d_prev_ = d;
    // A pair that has collapsed (its contraction is counted above) carries no direction.
    if (d < g_.min_scale()) {
      measured_ = fresh();
      incoming_ = Pair{};
      return;
    }
    if (measured_.age < settle_) return;
    if (!incoming_.exists() && d > g_.max_scale()) {
      // Wolf's replacement: a close point whose separation best keeps the orientation.
      double d_new = 0.0;
      incoming_ = Pair{g_.choose(fid_, &sep_, g_.candidate_scale(), d_new), 0};
      if (incoming_.exists()) ++r_.replacements;
    }
    if (incoming_.exists() && incoming_.age >= settle_) hand_over();
  }

  void age_pairs() {
    const double end = static_cast<double>(g_.usable());
    for (Pair* p : {&measured_, &incoming_}) {
      if (!p->exists()) continue;
      p->time += static_cast<double>(g_.evolve());
      p->age += g_.evolve();
      if (p->time >= end) *p = Pair{};  // the neighbour's record ends
    }
  }

  Pair fresh() {
    ++r_.replacements;
    return Pair{g_.choose(fid_, nullptr, g_.candidate_scale(), d_prev_), 0};
  }

  void hand_over() {
    measured_ = std::exchange(incoming_, Pair{});
    d_prev_ = g_.separation(fid_, measured_.time, sep_);
  }

  void count(double log_stretch) {
    const double interval_s = static_cast<double>(g_.evolve()) * dt_;
    s_.chain_log[c_] += log_stretch;
    const std::size_t b = std::min(Stretching::kBatches - 1, fid_ * Stretching::kBatches / g_.usable());
    s_.batch_log[b] += log_stretch;
    s_.batch_time[b] += interval_s;
    s_.chain_time[c_] += interval_s;
    if (c_ == 0) {  // the running estimate shown is the first chain's, as in Wolf's paper
      ++r_.intervals;
      r_.running_time_s.push_back(static_cast<double>(fid_) * dt_);
      r_.running_per_s.push_back(s_.chain_log[0] / s_.chain_time[0]);
    }
  }

  WolfGeometry& g_;
  const std::size_t c_;
  const double dt_;
  const std::size_t settle_;
  Stretching& s_;
  WolfResult& r_;
  std::vector<double> sep_;
  std::size_t fid_;
  double d_prev_ = 0.0;
  Pair measured_, incoming_;
};

// The exponent over all chains, and its uncertainty from batch means (the record cut into
// 10 contiguous stretches, all chains pooled): the standard error of the time-weighted mean
// of the batches' exponents. No measured interval at all (every pair closer than min_scale:
// a strictly periodic record) is a result: no stretching was observed.
void summarize(const Stretching& s, WolfResult& r) {
  double log_sum = 0.0, measured_s = 0.0;
  for (std::size_t c = 0; c < s.chain_log.size(); ++c) {
    log_sum += s.chain_log[c];
    measured_s += s.chain_time[c];
  }
  r.measured_s = measured_s;
  r.lambda_per_s = measured_s > 0.0 ? log_sum / measured_s : 0.0;
  double var = 0.0, weight = 0.0;
  std::size_t used = 0;
  for (std::size_t b = 0; b < Stretching::kBatches; ++b) {
    if (s.batch_time[b] <= 0.0) continue;
    const double lb = s.batch_log[b] / s.batch_time[b];
    var += s.batch_time[b] * (lb - r.lambda_per_s) * (lb - r.lambda_per_s);
    weight += s.batch_time[b];
    ++used;
  }
  r.uncertainty_per_s = used > 1 && weight > 0.0 ? std::sqrt(var / weight / (used - 1.0)) : 0.0;
}

}  // namespace

WolfResult wolf_exponent(std::span<const double> x, double rate_Hz, const WolfOptions& o) {
  o.validate(x.size());
  WolfGeometry g(x, o);
  WolfResult r;
  const std::size_t chains = std::max<std::size_t>(1, o.chains);
  Stretching s(chains);
  for (std::size_t c = 0; c < chains; ++c) Chain(g, o, c, chains, 1.0 / rate_Hz, s, r).follow();
  summarize(s, r);
  return r;
}

}  // namespace pneumachaos
