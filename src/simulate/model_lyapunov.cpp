#include "pneumachaos/simulate/model_lyapunov.hpp"

#include <fmt/format.h>

#include <cmath>
#include <numeric>
#include <utility>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos {

namespace {

// Euclidean distance with each state divided by its scale; states of scale 0 are left out.
double scaled_distance(const std::vector<double>& scale, const std::vector<double>& a,
                       const std::vector<double>& b) {
  double d2 = 0.0;
  for (std::size_t i = 0; i < scale.size(); ++i) {
    if (scale[i] > 0.0) d2 += std::pow((a[i] - b[i]) / scale[i], 2);
  }
  return std::sqrt(d2);
}

// Integration settings of both trajectories: no samples, no event log.
IntegratorOptions trajectory_options(const ModelLyapunovOptions& o) {
  IntegratorOptions io;
  io.relative_tolerance = o.relative_tolerance;
  io.absolute_tolerance = o.absolute_tolerance;
  io.max_step_s = o.max_step_s;
  io.stepper = o.stepper;
  io.sample_rate_Hz = 0.0;
  io.record_events = false;
  return io;
}

// Standard error of the exponent from the spread of the per-block exponents, each block
// span_s / blocks long.
double block_standard_error(const std::vector<double>& block_log, double span_s) {
  const double blocks = static_cast<double>(block_log.size());
  const double block_s = span_s / blocks;
  double mean = 0.0, var = 0.0;
  for (double b : block_log) mean += b / block_s;
  mean /= blocks;
  for (double b : block_log) var += std::pow(b / block_s - mean, 2);
  return std::sqrt(var / (blocks - 1) / blocks);
}

// The stretching per block when the measurement ended early (a stroke end): the gains, at
// their renormalisation times, binned over the span actually measured.
std::vector<double> rebin(const std::vector<double>& gains, const std::vector<double>& times,
                          double t0, double span_s, std::size_t blocks) {
  std::vector<double> block_log(blocks, 0.0);
  for (std::size_t i = 0; i < gains.size(); ++i) {
    const double share = (times[i] - t0) / span_s * static_cast<double>(blocks);
    block_log[std::min(blocks - 1, static_cast<std::size_t>(share))] += gains[i];
  }
  return block_log;
}

// Two trajectories side by side, renormalised to the initial separation at fixed intervals
// (Benettin et al. 1980), each a full hybrid integration.
class TwoTrajectories {
 public:
  TwoTrajectories(const HybridSystem& system, const ModelLyapunovOptions& o,
                  std::vector<double> scale)
      : system_(system), o_(o), scale_(std::move(scale)), io_(trajectory_options(o)) {}

  // Integrates the reference through the transient; false (with the message) when it ends.
  bool settle(const std::vector<double>& x0, ModelLyapunovResult& r) {
    xr_ = x0;
    mr_ = system_.initial_mode(xr_, 0.0);
    if (o_.transient_s > 0.0) {
      const auto s = advance(xr_, mr_, 0.0, o_.transient_s);
      if (s.termination != Termination::kDurationReached) {
        r.ok = false;
        r.message = fmt::format("the reference run ended in its transient: {}", s.message);
        return false;
      }
      t_ = o_.transient_s;
    }
    return true;
  }

  // The measurement: stretching summed over renormalisations, per block and running.
  std::vector<double> measure(ModelLyapunovResult& r) {
    xp_ = xr_;
    xp_[o_.perturbed_state] += o_.separation * scale_[o_.perturbed_state];
    mp_ = mr_;
    t0_ = t_;
    const double t_end = t0_ + o_.measure_s;
    std::vector<double> block_log(o_.blocks, 0.0);
    while (t_ < t_end - 1e-12) {
      const double next = std::min(t_ + o_.renormalize_s, t_end);
      if (!advance_both(next, r)) {
        if (ended_) {  // measured up to the last renormalisation: a result, not a failure
          r.ok = true;
          r.message.clear();
        }
        break;
      }
      t_ = next;
      if (!(mr_ == mp_) && t_ < t_end) {
        ++r.postponed;  // renormalise once both are in the same mode again
        continue;
      }
      if (!renormalize(r, block_log)) break;
    }
    return block_log;
  }

  [[nodiscard]] double start_s() const { return t0_; }
  [[nodiscard]] double log_sum() const { return log_sum_; }  ///< of the stretching factors
  /// True when a terminal event ended the measurement early (until_terminal_event).
  [[nodiscard]] bool ended() const { return ended_; }
  [[nodiscard]] const std::vector<double>& gains() const { return gains_; }

 private:
  IntegrationSummary advance(std::vector<double>& x, Mode& mode, double from, double to) {
    io_.t_start_s = from;
    io_.t_end_s = to;
    return integrate_hybrid(system_, x, mode, io_);
  }

  bool advance_both(double next, ModelLyapunovResult& r) {
    const auto a = advance(xr_, mr_, t_, next);
    const auto b = advance(xp_, mp_, t_, next);
    if (a.termination == Termination::kDurationReached &&
        b.termination == Termination::kDurationReached) {
      return true;
    }
    ended_ = o_.until_terminal_event && (a.termination == Termination::kTerminalEvent ||
                                         b.termination == Termination::kTerminalEvent);
    r.ok = false;
    r.message =
        fmt::format("a trajectory ended at t = {:.4g} s before the measurement did: {}", next,
                    a.termination != Termination::kDurationReached ? a.message : b.message);
    return false;
  }

  // Records the stretching since the last renormalisation and pulls the perturbed trajectory
  // back to the initial separation along the same direction.
  bool renormalize(ModelLyapunovResult& r, std::vector<double>& block_log) {
    const double d = scaled_distance(scale_, xr_, xp_);
    if (!(d > 0.0) || !std::isfinite(d)) {
      r.ok = false;
      r.message = "the two trajectories coincide or diverged to infinity";
      return false;
    }
    const double gain = std::log(d / o_.separation);
    log_sum_ += gain;
    gains_.push_back(gain);
    const std::size_t block =
        std::min(o_.blocks - 1, static_cast<std::size_t>((t_ - t0_) / o_.measure_s * o_.blocks));
    block_log[block] += gain;
    for (std::size_t i = 0; i < xp_.size(); ++i) {
      xp_[i] = xr_[i] + (xp_[i] - xr_[i]) * (o_.separation / d);
    }
    mp_ = mr_;
    ++r.renormalizations;
    r.running_time_s.push_back(t_);
    r.running_per_s.push_back(log_sum_ / (t_ - t0_));
    return true;
  }

  const HybridSystem& system_;
  const ModelLyapunovOptions& o_;
  std::vector<double> scale_;
  IntegratorOptions io_;
  std::vector<double> xr_, xp_;  // reference and perturbed states
  Mode mr_, mp_;
  double t_ = 0.0, t0_ = 0.0;
  double log_sum_ = 0.0;
  std::vector<double> gains_;  // one per renormalisation, at r.running_time_s
  bool ended_ = false;
};

}  // namespace

void ModelLyapunovOptions::validate() const {
  using namespace validation;
  require_finite_gt(kMeasureField, measure_s, 0, "s");
  require_finite_gt(kRenormalizeField, renormalize_s, 0, "s");
  require_finite_gt(kSeparationField, separation, 0);
  require_finite_ge(kTransientField, transient_s, 0, "s");
  require_ge(kBlocksField, static_cast<double>(blocks), 2);
  // The uncertainty is the spread between blocks: each block needs a renormalisation.
  const double fewest_s = renormalize_s * static_cast<double>(blocks);
  require(!(measure_s < fewest_s), kMeasureField, measure_s,
          fmt::format(">= {} s ({} renormalisation intervals of {} s, as many as the exponent "
                      "and its uncertainty need)",
                      fewest_s, blocks, renormalize_s));
  // Every interval is a restart of two integrations and a stored running value: bound it.
  constexpr double kMaxIntervals = 1e7;
  const double run_s = transient_s + measure_s;
  require(!(run_s / renormalize_s > kMaxIntervals), kRenormalizeField, renormalize_s,
          fmt::format(">= {} s (the run's {} s in at most {:g} renormalisations; the default "
                      "0.02 s is far shorter than the motion)",
                      run_s / kMaxIntervals, run_s, kMaxIntervals));
}

ModelLyapunovResult model_lyapunov(const HybridSystem& system, const std::vector<double>& x0,
                                   const ModelLyapunovOptions& o) {
  o.validate();
  const std::size_t n = system.state_size();
  std::vector<double> scale = o.scales.empty() ? std::vector<double>(n, 1.0) : o.scales;
  if (scale.size() != n || o.perturbed_state >= n || scale[o.perturbed_state] <= 0.0) {
    throw Error("lyapunov", "state scales or the perturbed state do not fit the system");
  }
  ModelLyapunovResult r;
  TwoTrajectories pair(system, o, std::move(scale));
  if (!pair.settle(x0, r)) return r;
  std::vector<double> block_log = pair.measure(r);
  if (pair.ended() && r.running_per_s.size() < o.blocks) {
    r.ok = false;
    r.message = fmt::format(
        "the run reached its end after {} renormalisations; the {} blocks "
        "of the uncertainty need at least one each",
        r.running_per_s.size(), o.blocks);
    return r;
  }
  if (r.running_per_s.empty()) {
    if (r.message.empty()) r.message = "no renormalisation took place";
    r.ok = false;
    return r;
  }
  r.measured_s = r.running_time_s.back() - pair.start_s();
  r.lambda_per_s = pair.log_sum() / r.measured_s;
  if (pair.ended()) {
    block_log = rebin(pair.gains(), r.running_time_s, pair.start_s(), r.measured_s, o.blocks);
    r.uncertainty_per_s = block_standard_error(block_log, r.measured_s);
  } else {
    r.uncertainty_per_s = block_standard_error(block_log, o.measure_s);
  }
  return r;
}

ModelLyapunovResult plant_lyapunov(const Plant& plant, const RunParams& run, ModelLyapunovOptions o,
                                   double tolerance_factor) {
  return plant_lyapunov_from(plant, rest_start(plant, run), run, o, tolerance_factor);
}

ModelLyapunovResult plant_lyapunov_from(const Plant& plant, const std::vector<double>& x0,
                                        const RunParams& run, ModelLyapunovOptions o,
                                        double tolerance_factor) {
  o.scales = plant.state_scales();
  o.perturbed_state = plant.layout().P1;
  o.relative_tolerance = 1e-9 * tolerance_factor;
  o.absolute_tolerance = 1e-12 * tolerance_factor;
  // Below the floor the two trajectories' own integration errors are renormalised as if they
  // were divergence (kPlantSeparationPerTolerance).
  const double min_separation = kPlantSeparationPerTolerance * o.relative_tolerance;
  if (!(o.separation <= kPlantMaxSeparation)) {
    throw Error(ModelLyapunovOptions::kSeparationField,
                fmt::format("{:g} is not small against the motion: at most {:g} (10 kPa on P1); "
                            "the default is {:g}",
                            o.separation, kPlantMaxSeparation, ModelLyapunovOptions{}.separation));
  }
  // A separation that rounds to just below the floor is at the floor.
  if (o.separation < min_separation * (1.0 - 1e-9)) {
    throw Error(ModelLyapunovOptions::kSeparationField,
                fmt::format("{:g} is within {:g} x the integration's relative tolerance ({:g}): "
                            "the integration error would be measured as divergence; use at least "
                            "{:g}, or tighten the tolerances with --tolerance-factor",
                            o.separation, kPlantSeparationPerTolerance, o.relative_tolerance,
                            min_separation));
  }
  o.max_step_s = run.max_step_s;
  o.stepper = run.stepper;
  return model_lyapunov(plant, x0, o);
}

}  // namespace pneumachaos
