#include "pneumachaos/simulate/model_lyapunov.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numeric>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/plant.hpp"

namespace pneumachaos {

void ModelLyapunovOptions::validate() const {
  const auto positive = [](double v, const char* name) {
    if (!(std::isfinite(v) && v > 0.0)) throw Error(name, "must be a positive number");
  };
  positive(measure_s, "lyapunov.measure_s");
  positive(renormalize_s, "lyapunov.renormalize_s");
  positive(separation, "lyapunov.separation");
  if (!(std::isfinite(transient_s) && transient_s >= 0.0))
    throw Error("lyapunov.transient_s", "must be a number >= 0");
  if (blocks < 2) throw Error("lyapunov.blocks", "must be at least 2");
  // The uncertainty is the spread between blocks: each block needs a renormalisation.
  if (measure_s < renormalize_s * static_cast<double>(blocks)) {
    throw Error("lyapunov.measure_s",
                fmt::format("{} s holds fewer than {} renormalisation intervals of {} s; the "
                            "exponent and its uncertainty need at least that many",
                            measure_s, blocks, renormalize_s));
  }
  // Every interval is a restart of two integrations and a stored running value: bound it.
  constexpr double kMaxIntervals = 1e7;
  if ((transient_s + measure_s) / renormalize_s > kMaxIntervals) {
    throw Error("lyapunov.renormalize_s",
                fmt::format("{} s over {} s is more than {:g} renormalisations; use a longer "
                            "interval (the default 0.02 s is far shorter than the motion)",
                            renormalize_s, transient_s + measure_s, kMaxIntervals));
  }
}

ModelLyapunovResult model_lyapunov(const HybridSystem& system, const std::vector<double>& x0,
                                   const ModelLyapunovOptions& o) {
  o.validate();
  const std::size_t n = system.state_size();
  std::vector<double> scale = o.scales.empty() ? std::vector<double>(n, 1.0) : o.scales;
  if (scale.size() != n || o.perturbed_state >= n || scale[o.perturbed_state] <= 0.0) {
    throw Error("lyapunov", "state scales or the perturbed state do not fit the system");
  }
  const auto distance = [&](const std::vector<double>& a, const std::vector<double>& b) {
    double d2 = 0.0;
    for (std::size_t i = 0; i < n; ++i) {
      if (scale[i] > 0.0) d2 += std::pow((a[i] - b[i]) / scale[i], 2);
    }
    return std::sqrt(d2);
  };
  IntegratorOptions io;
  io.relative_tolerance = o.relative_tolerance;
  io.absolute_tolerance = o.absolute_tolerance;
  io.max_step_s = o.max_step_s;
  io.stepper = o.stepper;
  io.sample_rate_Hz = 0.0;
  io.record_events = false;
  const auto advance = [&](std::vector<double>& x, Mode& mode, double from, double to) {
    io.t_start_s = from;
    io.t_end_s = to;
    return integrate_hybrid(system, x, mode, io);
  };

  ModelLyapunovResult r;
  std::vector<double> xr = x0;
  Mode mr = system.initial_mode(xr, 0.0);
  double t = 0.0;
  if (o.transient_s > 0.0) {
    const auto s = advance(xr, mr, 0.0, o.transient_s);
    if (s.termination != Termination::kDurationReached) {
      r.ok = false;
      r.message = fmt::format("the reference run ended in its transient: {}", s.message);
      return r;
    }
    t = o.transient_s;
  }
  std::vector<double> xp = xr;
  xp[o.perturbed_state] += o.separation * scale[o.perturbed_state];
  Mode mp = mr;
  const double t0 = t;
  const double t_end = t0 + o.measure_s;
  double log_sum = 0.0;
  std::vector<double> block_log(o.blocks, 0.0);
  while (t < t_end - 1e-12) {
    const double next = std::min(t + o.renormalize_s, t_end);
    const auto a = advance(xr, mr, t, next);
    const auto b = advance(xp, mp, t, next);
    if (a.termination != Termination::kDurationReached ||
        b.termination != Termination::kDurationReached) {
      r.ok = false;
      r.message =
          fmt::format("a trajectory ended at t = {:.4g} s before the measurement did: {}", next,
                      a.termination != Termination::kDurationReached ? a.message : b.message);
      break;
    }
    t = next;
    if (!(mr == mp) && t < t_end) {
      ++r.postponed;  // renormalise once both are in the same mode again
      continue;
    }
    const double d = distance(xr, xp);
    if (!(d > 0.0) || !std::isfinite(d)) {
      r.ok = false;
      r.message = "the two trajectories coincide or diverged to infinity";
      break;
    }
    const double gain = std::log(d / o.separation);
    log_sum += gain;
    const std::size_t block =
        std::min(o.blocks - 1, static_cast<std::size_t>((t - t0) / o.measure_s * o.blocks));
    block_log[block] += gain;
    for (std::size_t i = 0; i < n; ++i) xp[i] = xr[i] + (xp[i] - xr[i]) * (o.separation / d);
    mp = mr;
    ++r.renormalizations;
    r.running_time_s.push_back(t);
    r.running_per_s.push_back(log_sum / (t - t0));
  }
  if (r.running_per_s.empty()) {
    if (r.message.empty()) r.message = "no renormalisation took place";
    r.ok = false;
    return r;
  }
  const double measured = r.running_time_s.back() - t0;
  r.lambda_per_s = log_sum / measured;
  // Standard error from the spread of the per-block exponents.
  const double block_s = o.measure_s / o.blocks;
  double mean = 0.0, var = 0.0;
  for (double b : block_log) mean += b / block_s;
  mean /= o.blocks;
  for (double b : block_log) var += std::pow(b / block_s - mean, 2);
  r.uncertainty_per_s = std::sqrt(var / (o.blocks - 1) / o.blocks);
  return r;
}

ModelLyapunovResult plant_lyapunov(const Plant& plant, const RunParams& run,
                                   ModelLyapunovOptions o, double tolerance_factor) {
  o.scales = plant.state_scales();
  o.perturbed_state = plant.layout().P1;
  o.relative_tolerance = 1e-9 * tolerance_factor;
  o.absolute_tolerance = 1e-12 * tolerance_factor;
  o.max_step_s = run.max_step_s;
  o.stepper = run.stepper;
  return model_lyapunov(plant, plant.initial_state(), o);
}

}  // namespace pneumachaos
