#include "pneumachaos/simulate/event_integrator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <chrono>
#include <cmath>
#include <limits>
#include <string>
#include <utility>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "steppers.hpp"

namespace pneumachaos {
namespace {

using detail::State;

// Right-hand side in a fixed mode, counting evaluations for the summary.
struct ModeRhs {
  const HybridSystem* system;
  const Mode* mode;
  std::size_t* evaluations;
  void operator()(const State& x, State& dxdt, double t) const {
    ++*evaluations;
    dxdt.resize(x.size());
    system->derivative(*mode, x, dxdt, t);
  }
  bool jacobian(const State& x, double t, State& dfdx, State& dfdt) const {
    return system->jacobian(*mode, x, t, dfdx, dfdt);
  }
};

bool all_finite(std::span<const double> x) {
  return std::all_of(x.begin(), x.end(), [](double v) { return std::isfinite(v); });
}

void count_event(EventCounts& c, EventKind kind) {
  switch (kind) {
    case EventKind::kStick:
      ++c.stick;
      break;
    case EventKind::kSlip:
      ++c.slip;
      break;
    case EventKind::kReversal:
      ++c.reversal;
      break;
    case EventKind::kStopHit:
      ++c.stop_hit;
      break;
    case EventKind::kStopRelease:
      ++c.stop_release;
      break;
    case EventKind::kTerminal:
    case EventKind::kModeSwitch:
      break;
  }
}

// Emits the samples t_k in (after, until] from an interpolant.
class Sampler {
 public:
  Sampler(const IntegratorOptions& o, const SampleObserver& obs)
      : t0_(o.t_start_s), rate_(o.sample_rate_Hz), t_end_(o.t_end_s), observer_(obs) {}

  [[nodiscard]] bool active() const { return observer_ && rate_ > 0.0; }
  [[nodiscard]] double next_time() const { return t0_ + static_cast<double>(k_) / rate_; }

  template <typename Interp>
  void emit_until(double until, const Mode& mode, Interp&& interp) {
    if (!active()) return;
    // Half a sample of slack absorbs rounding in t_end so the last sample is not lost.
    const double slack = 1e-9 / rate_;
    const double limit = std::min(until, t_end_) + slack;
    while (next_time() <= limit) {
      const double t = std::min(next_time(), until);
      interp(t, buffer_);
      observer_(next_time(), buffer_, mode);
      ++k_;
    }
  }

 private:
  double t0_, rate_, t_end_;
  const SampleObserver& observer_;
  std::size_t k_ = 0;
  State buffer_;
};

// One integration of a hybrid system: smooth steps of `Stepper`, each checked for events; the
// earliest event in a step is located on the dense output, the samples up to it are emitted,
// and the system's transition is applied before the stepper restarts from there.
template <typename Stepper>
class HybridRun {
 public:
  HybridRun(const HybridSystem& system, State& x, Mode& mode, const IntegratorOptions& o,
            const SampleObserver& observer)
      : system_(system),
        x_(x),
        mode_(mode),
        o_(o),
        stepper_(ModeRhs{&system, &mode, &s_.rhs_evaluations}, o.absolute_tolerance,
                 o.relative_tolerance),
        sampler_(o, observer),
        t_(o.t_start_s),
        dt_(std::min(o.initial_step_s, o.max_step_s)) {}

  IntegrationSummary run() {
    stepper_.initialize(x_, t_);
    sampler_.emit_until(t_, mode_, [&](double, State& out) { out = x_; });
    events(x_, t_, g_old_);
    while (t_ < o_.t_end_s) {
      const StepResult step = try_one_step();
      if (step == StepResult::kFailed) break;
      if (step == StepResult::kRejected) continue;
      events(stepper_.state(), stepper_.t_new(), g_new_);
      const Located event = earliest_event();
      if (event.which == g_new_.size()) {
        accept_smooth_step();
      } else if (!cross_event(event)) {
        break;
      }
    }
    s_.t_final_s = t_;
    if (s_.termination == Termination::kDurationReached && s_.message.empty()) {
      s_.message = "duration reached";
    }
    return s_;
  }

 private:
  enum class StepResult { kAccepted, kRejected, kFailed };
  struct Located {
    std::size_t which;  // index of the event function; g_new_.size() when none fired
    double t;
  };

  [[nodiscard]] double tiny(double t) const { return kTiny * std::max(1.0, std::abs(t)); }

  StepResult fail(std::string message) {
    s_.termination = Termination::kSolverFailure;
    s_.message = std::move(message);
    return StepResult::kFailed;
  }

  void events(const State& state, double time, State& g) const {
    g.resize(system_.event_count(mode_));
    system_.event_functions(mode_, state, time, g);
  }

  // One controlled step from t_, bounded by the largest step and the end of the run.
  StepResult try_one_step() {
    if (s_.steps_accepted + s_.steps_rejected >= o_.max_steps) {
      return fail(fmt::format(
          "step limit of {} reached at t = {} s: the model needs far smaller steps than a "
          "pneumatic drive should (check run.max_step_ms, friction stiffness sigma0 and the "
          "forces), or try run.stepper = \"rosenbrock4\"",
          o_.max_steps, t_));
    }
    dt_ = std::min({dt_, o_.max_step_s, o_.t_end_s - t_});
    // Land exactly on t_end instead of leaving a sliver step.
    if (o_.t_end_s - (t_ + dt_) < tiny(t_)) dt_ = o_.t_end_s - t_;
    if (!stepper_.try_step(dt_)) {
      ++s_.steps_rejected;
      if (dt_ < tiny(t_)) return fail(fmt::format("step size underflow at t = {} s", t_));
      return StepResult::kRejected;
    }
    ++s_.steps_accepted;
    if (!all_finite(stepper_.state())) {
      return fail(fmt::format("non-finite state at t = {} s", stepper_.t_new()));
    }
    return StepResult::kAccepted;
  }

  // Where event function i, negative at the end of the step, first becomes negative.
  double event_time(std::size_t i) {
    const double t_new = stepper_.t_new();
    const auto g_at = [&](double tau) {
      stepper_.calc_state(tau, scratch_);
      events(scratch_, tau, g_new_);
      return g_new_[i];
    };
    // The transition is applied where g is strictly negative: at a point where g is still
    // exactly zero (e.g. a drive force of exactly 0 at rest) the new mode is undecidable.
    double lower = stepper_.t_old();
    double upper = t_new;
    if (g_old_[i] > 0.0) {
      std::uintmax_t iterations = 64;
      const auto bracket = boost::math::tools::toms748_solve(
          g_at, lower, upper, g_old_[i], g_at(upper), boost::math::tools::eps_tolerance<double>(50),
          iterations);
      lower = bracket.first;
      upper = bracket.second;
    }
    if (!(g_at(upper) < 0.0)) upper = t_new;
    // Bisection on "g < 0" narrows a degenerate start (g = 0 at t_old) or an exact root.
    while (upper - lower > tiny(upper)) {
      const double mid = 0.5 * (lower + upper);
      if (mid <= lower || mid >= upper) break;
      (g_at(mid) < 0.0 ? upper : lower) = mid;
    }
    events(stepper_.state(), t_new, g_new_);  // restore for the remaining comparisons
    return upper;
  }

  // The earliest event that fired in the last step (g went from >= 0 to < 0).
  Located earliest_event() {
    Located first{g_new_.size(), stepper_.t_new()};
    for (std::size_t i = 0; i < g_new_.size(); ++i) {
      if (!(g_new_[i] < 0.0)) continue;
      const double t = event_time(i);
      if (t < first.t || first.which == g_new_.size()) first = {i, t};
    }
    return first;
  }

  void interpolate(double tau, State& out) {
    if (tau >= stepper_.t_new()) {
      out = stepper_.state();
    } else {
      stepper_.calc_state(tau, out);
    }
  }

  void accept_smooth_step() {
    const auto interp = [&](double tau, State& out) { interpolate(tau, out); };
    sampler_.emit_until(stepper_.t_new(), mode_, interp);
    t_ = stepper_.t_new();
    x_ = stepper_.state();
    std::swap(g_old_, g_new_);
  }

  // Moves to the event, applies the system's transition and restarts the stepper there;
  // false when the run ends (terminal event or chattering).
  bool cross_event(const Located& event) {
    const auto interp = [&](double tau, State& out) { interpolate(tau, out); };
    sampler_.emit_until(event.t, mode_, interp);
    interpolate(event.t, x_);
    events_here_ = (event.t - last_event_t_ <= tiny(event.t)) ? events_here_ + 1 : 1;
    last_event_t_ = event.t;
    if (events_here_ > o_.max_events_at_one_instant) {
      s_.termination = Termination::kChattering;
      s_.message = fmt::format("more than {} events at t = {} s (chattering)",
                               o_.max_events_at_one_instant, event.t);
      t_ = event.t;
      return false;
    }
    const EventOutcome outcome = system_.apply_event(event.which, mode_, x_, event.t);
    count_event(s_.events, outcome.kind);
    if (o_.record_events) s_.event_log.push_back({event.t, outcome.kind});
    t_ = event.t;
    if (outcome.terminate) {
      s_.termination = Termination::kTerminalEvent;
      s_.message = outcome.message;
      return false;
    }
    stepper_.initialize(x_, t_);
    events(x_, t_, g_old_);
    return true;
  }

  static constexpr double kTiny = 64 * std::numeric_limits<double>::epsilon();

  const HybridSystem& system_;
  State& x_;
  Mode& mode_;
  const IntegratorOptions& o_;
  IntegrationSummary s_;  // before stepper_: the stepper counts into it
  Stepper stepper_;
  Sampler sampler_;
  double t_;
  double dt_;
  double last_event_t_ = -std::numeric_limits<double>::infinity();
  std::size_t events_here_ = 0;
  State g_old_, g_new_, scratch_;
};

template <typename Stepper>
IntegrationSummary run(const HybridSystem& system, State& x, Mode& mode, const IntegratorOptions& o,
                       const SampleObserver& observer) {
  return HybridRun<Stepper>(system, x, mode, o, observer).run();
}

}  // namespace

void IntegratorOptions::validate() const {
  using namespace validation;
  require_finite(field("integrator.t_start_s"), t_start_s);
  require_finite_gt(field("integrator.t_end_s"), t_end_s, t_start_s, "after t_start_s");
  // The tolerances carry their fields: the lyapunov command scales them by a flag.
  require_finite_gt(kRelativeToleranceField, relative_tolerance, 0);
  require_finite_gt(kAbsoluteToleranceField, absolute_tolerance, 0);
  require_finite_gt(field("integrator.max_step_s"), max_step_s, 0);
  require_finite_gt(field("integrator.initial_step_s"), initial_step_s, 0);
  require_finite_ge(field("integrator.sample_rate_Hz"), sample_rate_Hz, 0, "0: no samples");
}

const char* termination_name(Termination t) {
  switch (t) {
    case Termination::kDurationReached:
      return "duration_reached";
    case Termination::kTerminalEvent:
      return "terminal_event";
    case Termination::kSolverFailure:
      return "solver_failure";
    case Termination::kChattering:
      return "chattering";
  }
  return "?";
}

IntegrationSummary integrate_hybrid(const HybridSystem& system, std::vector<double>& x, Mode& mode,
                                    const IntegratorOptions& options,
                                    const SampleObserver& observer) {
  options.validate();
  if (x.size() != system.state_size()) {
    throw Error("initial state",
                fmt::format("has {} values, the system {}", x.size(), system.state_size()));
  }
  const auto started = std::chrono::steady_clock::now();
  IntegrationSummary s;
  try {
    if (options.stepper == StepperKind::kRosenbrock4) {
      s = run<detail::Rosenbrock4Stepper<ModeRhs>>(system, x, mode, options, observer);
    } else if (options.step_control == StepControl::kOdeint) {
      using Odeint = boost::numeric::odeint::default_step_adjuster<double, double>;
      s = run<detail::Dopri5Stepper<ModeRhs, Odeint>>(system, x, mode, options, observer);
    } else {
      s = run<detail::Dopri5Stepper<ModeRhs, detail::PiStepAdjuster>>(system, x, mode, options,
                                                                     observer);
    }
  } catch (const Error&) {
    throw;
  } catch (const std::exception& e) {
    // Odeint and Boost.Math report numerical breakdown by exception; a run reports it.
    s.termination = Termination::kSolverFailure;
    s.message = e.what();
  }
  s.wall_time_s = std::chrono::duration<double>(std::chrono::steady_clock::now() - started).count();
  return s;
}

}  // namespace pneumachaos
