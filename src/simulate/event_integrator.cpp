#include "pneumachaos/simulate/event_integrator.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <boost/math/tools/toms748_solve.hpp>
#include <chrono>
#include <cmath>
#include <limits>

#include "pneumachaos/core/error.hpp"
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

template <typename Stepper>
IntegrationSummary run(const HybridSystem& system, State& x, Mode& mode, const IntegratorOptions& o,
                       const SampleObserver& observer) {
  IntegrationSummary s;
  Stepper stepper(ModeRhs{&system, &mode, &s.rhs_evaluations}, o.absolute_tolerance,
                  o.relative_tolerance);
  Sampler sampler(o, observer);
  double t = o.t_start_s;
  stepper.initialize(x, t);
  sampler.emit_until(t, mode, [&](double, State& out) { out = x; });

  State g_old, g_new, scratch;
  const auto events = [&](const State& state, double time, State& g) {
    g.resize(system.event_count(mode));
    system.event_functions(mode, state, time, g);
  };
  events(x, t, g_old);

  double dt = std::min(o.initial_step_s, o.max_step_s);
  double last_event_t = -std::numeric_limits<double>::infinity();
  std::size_t events_here = 0;
  const double t_tiny = 64 * std::numeric_limits<double>::epsilon();

  while (t < o.t_end_s) {
    if (s.steps_accepted + s.steps_rejected >= o.max_steps) {
      s.termination = Termination::kSolverFailure;
      s.message = fmt::format(
          "step limit of {} reached at t = {} s: the model needs far smaller steps than a "
          "pneumatic drive should (check run.max_step_ms, friction stiffness sigma0 and the "
          "forces), or try run.stepper = \"rosenbrock4\"",
          o.max_steps, t);
      break;
    }
    dt = std::min({dt, o.max_step_s, o.t_end_s - t});
    // Land exactly on t_end instead of leaving a sliver step.
    if (o.t_end_s - (t + dt) < t_tiny * std::max(1.0, std::abs(t))) dt = o.t_end_s - t;
    if (!stepper.try_step(dt)) {
      ++s.steps_rejected;
      if (dt < t_tiny * std::max(1.0, std::abs(t))) {
        s.termination = Termination::kSolverFailure;
        s.message = fmt::format("step size underflow at t = {} s", t);
        break;
      }
      continue;
    }
    ++s.steps_accepted;
    const State& x_new = stepper.state();
    const double t_new = stepper.t_new();
    if (!all_finite(x_new)) {
      s.termination = Termination::kSolverFailure;
      s.message = fmt::format("non-finite state at t = {} s", t_new);
      break;
    }
    events(x_new, t_new, g_new);

    // Earliest event that fired in this step (g went from >= 0 to < 0).
    std::size_t which = g_new.size();
    double t_event = t_new;
    for (std::size_t i = 0; i < g_new.size(); ++i) {
      if (!(g_new[i] < 0.0)) continue;
      const auto g_at = [&](double tau) {
        stepper.calc_state(tau, scratch);
        events(scratch, tau, g_new);
        return g_new[i];
      };
      // The transition is applied where g is strictly negative: at a point where g is still
      // exactly zero (e.g. a drive force of exactly 0 at rest) the new mode is undecidable.
      double lower = stepper.t_old();
      double upper = t_new;
      if (g_old[i] > 0.0) {
        std::uintmax_t iterations = 64;
        const auto bracket = boost::math::tools::toms748_solve(
            g_at, lower, upper, g_old[i], g_at(upper),
            boost::math::tools::eps_tolerance<double>(50), iterations);
        lower = bracket.first;
        upper = bracket.second;
      }
      if (!(g_at(upper) < 0.0)) upper = t_new;
      // Bisection on "g < 0" narrows a degenerate start (g = 0 at t_old) or an exact root.
      while (upper - lower > t_tiny * std::max(1.0, std::abs(upper))) {
        const double mid = 0.5 * (lower + upper);
        if (mid <= lower || mid >= upper) break;
        (g_at(mid) < 0.0 ? upper : lower) = mid;
      }
      if (upper < t_event || which == g_new.size()) {
        t_event = upper;
        which = i;
      }
      events(x_new, t_new, g_new);  // restore for the remaining comparisons
    }

    const auto interp = [&](double tau, State& out) {
      if (tau >= t_new) {
        out = x_new;
      } else {
        stepper.calc_state(tau, out);
      }
    };
    if (which == g_new.size()) {
      sampler.emit_until(t_new, mode, interp);
      t = t_new;
      x = x_new;
      std::swap(g_old, g_new);
      continue;
    }

    sampler.emit_until(t_event, mode, interp);
    interp(t_event, x);
    events_here =
        (t_event - last_event_t <= t_tiny * std::max(1.0, std::abs(t_event))) ? events_here + 1 : 1;
    last_event_t = t_event;
    if (events_here > o.max_events_at_one_instant) {
      s.termination = Termination::kChattering;
      s.message = fmt::format("more than {} events at t = {} s (chattering)",
                              o.max_events_at_one_instant, t_event);
      t = t_event;
      break;
    }
    const EventOutcome outcome = system.apply_event(which, mode, x, t_event);
    count_event(s.events, outcome.kind);
    if (o.record_events) s.event_log.push_back({t_event, outcome.kind});
    t = t_event;
    if (outcome.terminate) {
      s.termination = Termination::kTerminalEvent;
      s.message = outcome.message;
      break;
    }
    stepper.initialize(x, t);
    events(x, t, g_old);
  }
  s.t_final_s = t;
  if (s.termination == Termination::kDurationReached && s.message.empty()) {
    s.message = "duration reached";
  }
  return s;
}

}  // namespace

void IntegratorOptions::validate() const {
  const auto positive = [](double v, const char* name) {
    if (!(std::isfinite(v) && v > 0.0)) {
      throw Error(name, fmt::format("must be a positive finite number, got {}", v));
    }
  };
  if (!(std::isfinite(t_end_s) && std::isfinite(t_start_s) && t_end_s > t_start_s)) {
    throw Error("t_end_s",
                fmt::format("must be finite and after t_start_s = {}, got {}", t_start_s, t_end_s));
  }
  positive(relative_tolerance, "relative_tolerance");
  positive(absolute_tolerance, "absolute_tolerance");
  positive(max_step_s, "max_step_s");
  positive(initial_step_s, "initial_step_s");
  if (!(std::isfinite(sample_rate_Hz) && sample_rate_Hz >= 0.0)) {
    throw Error("sample_rate_Hz", fmt::format("must be >= 0, got {}", sample_rate_Hz));
  }
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
    } else {
      s = run<detail::Dopri5Stepper<ModeRhs>>(system, x, mode, options, observer);
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
