#include "pneumachaos/analysis/lyapunov_wolf.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>
#include <limits>
#include <utility>

#include "pneumachaos/analysis/continuous_alignment.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

void WolfOptions::validate(std::size_t n) const {
  if (dimension == 0 || delay == 0) throw Error("wolf", "dimension and delay must be >= 1");
  if (n < 100) throw Error("wolf", fmt::format("{} samples: at least 100 are needed", n));
  if (max_scale < 0.0 || candidate_scale < 0.0 || min_scale < 0.0 || !(scale_factor > 0.0)) {
    throw Error("wolf", "scales must be non-negative and scale_factor positive");
  }
}

WolfResult wolf_exponent(std::span<const double> x, double rate_Hz, const WolfOptions& o) {
  o.validate(x.size());
  const DelayEmbedding e(x, o.dimension, o.delay);
  const std::size_t period = o.typical_period > 0
                                 ? o.typical_period
                                 : static_cast<std::size_t>(std::lround(mean_maxima_spacing(x)));
  const std::size_t evolve = o.evolve > 0 ? o.evolve : std::max<std::size_t>(1, period / 4);
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double diameter = (*hi - *lo) * std::sqrt(static_cast<double>(o.dimension));
  const double min_scale = o.min_scale > 0.0 ? o.min_scale : 1e-4 * diameter;
  if (!(diameter > 0.0)) throw Error("wolf", "the series is constant");
  if (e.size() < evolve + o.theiler + 20) throw Error("wolf", "the series is too short");

  const bool aligned = o.align && is_oversampled_flow(o.delay);
  // One sample of margin on each side for the interpolation stencil of aligned neighbours.
  const std::size_t margin = aligned ? 2 : 0;
  const std::size_t usable = e.size() - evolve - margin;
  const NeighbourIndex index(e, usable, std::max(repeat_resolution(x), min_scale));
  const bool flow = is_oversampled_flow(o.delay);
  // Scales follow the data density: the median nearest-neighbour distance, sampled.
  const auto median_nn = [&] {
    std::vector<double> nn;
    for (std::size_t i = margin; i < usable; i += std::max<std::size_t>(1, usable / 300)) {
      const Neighbour nb = index.nearest(i, o.theiler);
      if (nb.index < usable) nn.push_back(std::sqrt(nb.distance2));
    }
    if (nn.empty()) throw Error("wolf", "no neighbours outside the Theiler window");
    std::nth_element(nn.begin(), nn.begin() + nn.size() / 2, nn.end());
    return nn[nn.size() / 2];
  };
  const double nn_scale =
      o.max_scale > 0.0 && (o.candidate_scale > 0.0 || !flow) ? 0.0 : median_nn();
  // Replacement scale: as small as the data density allows (Wolf et al.: the smaller the
  // better while neighbours remain).
  const double max_scale = o.max_scale > 0.0 ? o.max_scale : o.scale_factor * nn_scale;
  // Replacement candidates: for flows the closest ones (a farther start leaves the linear
  // regime sooner, while the settling period below aligns the orientation anyway); for maps
  // the best-oriented within max_scale.
  const double candidate_scale = o.candidate_scale > 0.0 ? o.candidate_scale
                                 : flow                  ? nn_scale
                                                         : max_scale;
  std::vector<double> sep(o.dimension), cand(o.dimension);
  // Separation vector from fiducial point i to the neighbour at (fractional) time j.
  const auto separation = [&](std::size_t i, double j, std::vector<double>& out) {
    double d2 = 0.0;
    for (std::size_t d = 0; d < o.dimension; ++d) {
      const double other =
          aligned ? interpolated_coordinate(e, j, d) : e.coordinate(static_cast<std::size_t>(j), d);
      out[d] = other - e.coordinate(i, d);
      d2 += out[d] * out[d];
    }
    return std::sqrt(d2);
  };
  const auto place = [&](std::size_t i, std::size_t j) {
    return static_cast<double>(j) + (aligned && j >= margin ? closest_offset(e, i, j) : 0.0);
  };

  WolfResult r;
  const double dt = 1.0 / rate_Hz;
  // Candidates for a neighbour: the nearest few dozen around the fiducial point, each placed
  // (aligned in time for flows) before its scale and orientation are judged.
  const std::size_t candidates = 40;
  struct Candidate {
    double time, distance, angle;
  };
  std::vector<Candidate> pool;
  const auto choose = [&](std::size_t fid, const std::vector<double>* old_sep, double radius,
                          double& d_out) {
    // Each candidate is placed (aligned in time for flows) and measured once.
    pool.clear();
    double old_norm = 0.0;
    if (old_sep != nullptr) {
      for (double c : *old_sep) old_norm += c * c;
      old_norm = std::sqrt(old_norm);
    }
    for (const Neighbour& c : index.k_nearest(fid, candidates, o.theiler)) {
      if (c.index >= usable || c.index < margin) continue;
      const double j = place(fid, c.index);
      const double d = separation(fid, j, cand);
      if (d < min_scale) continue;
      double angle = d;  // the first neighbour: simply the nearest
      if (old_sep != nullptr) {
        double dot = 0.0;
        for (std::size_t k = 0; k < o.dimension; ++k) dot += cand[k] * (*old_sep)[k];
        angle = std::acos(std::clamp(dot / (d * old_norm), -1.0, 1.0));
      }
      pool.push_back({j, d, angle});
    }
    if (pool.empty()) {
      d_out = 0.0;
      return -1.0;
    }
    // The best-oriented one within the radius, widening it up to 8x when none is.
    for (double scale = radius; scale <= 8.0 * radius; scale *= 2.0) {
      const Candidate* best = nullptr;
      for (const Candidate& c : pool) {
        if (c.distance <= scale && (best == nullptr || c.angle < best->angle)) best = &c;
      }
      if (best != nullptr) {
        d_out = best->distance;
        return best->time;
      }
    }
    const auto nearest =
        std::min_element(pool.begin(), pool.end(),
                         [](const auto& a, const auto& b) { return a.distance < b.distance; });
    d_out = nearest->distance;
    return nearest->time;
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
  const std::size_t settle = o.settle > 0 ? o.settle : flow ? period : 0;
  struct Pair {
    double time = -1.0;  ///< (fractional) index of the neighbour; < 0: none
    std::size_t age = 0;
    [[nodiscard]] bool exists() const { return time >= 0.0; }
  };
  const double end = static_cast<double>(usable);
  const std::size_t chains = std::max<std::size_t>(1, o.chains);
  double log_sum = 0.0, measured_s = 0.0;
  std::vector<double> chain_log(chains, 0.0), chain_time(chains, 0.0);
  // Stretching pooled by where along the record it was measured: the chains share the record,
  // so their spread misses how the estimate varies along it; contiguous batches see that.
  constexpr std::size_t kBatches = 10;
  std::vector<double> batch_log(kBatches, 0.0), batch_time(kBatches, 0.0);
  for (std::size_t c = 0; c < chains; ++c) {
    // Chains start at staggered points of the first orbit and pool their stretching: one
    // chain on a finite record rests on a few dozen replacements.
    std::size_t fid = margin + (c * std::max<std::size_t>(period, 1)) / chains;
    double d_prev = 0.0;
    const auto fresh = [&] {
      ++r.replacements;
      return Pair{choose(fid, nullptr, candidate_scale, d_prev), 0};
    };
    Pair measured{choose(fid, nullptr, candidate_scale, d_prev), 0}, incoming;
    while (fid + evolve < usable) {
      fid += evolve;
      for (Pair* p : {&measured, &incoming}) {
        if (!p->exists()) continue;
        p->time += static_cast<double>(evolve);
        p->age += evolve;
        if (p->time >= end) *p = Pair{};  // the neighbour's record ends
      }
      if (!measured.exists()) {  // hand over early, or start afresh
        if (incoming.exists()) {
          measured = std::exchange(incoming, Pair{});
          d_prev = separation(fid, measured.time, sep);
        } else {
          measured = fresh();
        }
        continue;
      }
      const double d = separation(fid, measured.time, sep);
      if (measured.age >= settle && d_prev > 0.0 && d > 0.0) {
        chain_log[c] += std::log(d / d_prev);
        const std::size_t b = std::min(kBatches - 1, fid * kBatches / usable);
        batch_log[b] += std::log(d / d_prev);
        batch_time[b] += static_cast<double>(evolve) * dt;
        chain_time[c] += static_cast<double>(evolve) * dt;
        if (c == 0) {  // the running estimate shown is the first chain's, as in Wolf's paper
          ++r.intervals;
          r.running_time_s.push_back(static_cast<double>(fid) * dt);
          r.running_per_s.push_back(chain_log[0] / chain_time[0]);
        }
      }
      d_prev = d;
      // A pair that has collapsed (its contraction is counted above) carries no direction.
      if (d < min_scale) {
        measured = fresh();
        incoming = Pair{};
        continue;
      }
      if (measured.age < settle) continue;
      if (!incoming.exists() && d > max_scale) {
        // Wolf's replacement: a close point whose separation best keeps the orientation.
        double d_new = 0.0;
        incoming = Pair{choose(fid, &sep, candidate_scale, d_new), 0};
        if (incoming.exists()) ++r.replacements;
      }
      if (incoming.exists() && incoming.age >= settle) {
        measured = std::exchange(incoming, Pair{});
        d_prev = separation(fid, measured.time, sep);
      }
    }
    log_sum += chain_log[c];
    measured_s += chain_time[c];
  }
  // No measured interval at all (every pair closer than min_scale: a strictly periodic
  // record) is a result: no stretching was observed.
  r.measured_s = measured_s;
  r.lambda_per_s = measured_s > 0.0 ? log_sum / measured_s : 0.0;
  // Batch means (the record cut into 10 contiguous stretches, all chains pooled): the
  // standard error of the time-weighted mean of the batches' exponents.
  double var = 0.0, weight = 0.0;
  std::size_t used = 0;
  for (std::size_t b = 0; b < kBatches; ++b) {
    if (batch_time[b] <= 0.0) continue;
    const double lb = batch_log[b] / batch_time[b];
    var += batch_time[b] * (lb - r.lambda_per_s) * (lb - r.lambda_per_s);
    weight += batch_time[b];
    ++used;
  }
  r.uncertainty_per_s = used > 1 && weight > 0.0 ? std::sqrt(var / weight / (used - 1.0)) : 0.0;
  return r;
}

}  // namespace pneumachaos
