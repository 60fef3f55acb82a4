#pragma once
// Thin adapters that give two Boost.Odeint steppers one interface for the event integrator:
// try one controlled step, then interpolate anywhere inside the last accepted step. The
// stepping loop is ours (not odeint's integrate functions) because events must be located
// and the mode switched between steps, and rejected steps must be counted.

#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <algorithm>
#include <cmath>
#include <vector>

#include "rosenbrock4_engine.hpp"

namespace pneumachaos::detail {

/// The step-size controller of Hairer & Wanner's DOPRI5 code (a PI controller,
/// docs/notes/performance.md), in the interface Boost.Odeint's controlled stepper asks of a
/// step adjuster: the new step is h * 0.9 * err^-(0.2 - 0.75 beta) * err_prev^beta with
/// beta = 0.04, the factor within
/// [0.2, 10], and no growth right after a rejection. err is the largest error relative to the
/// tolerance (accept when <= 1). Odeint's default grows only when err < 1/2 and shrinks with
/// err^-1/3, which rejects one step in five on the default rig; this one, one in twelve.
class PiStepAdjuster {
 public:
  double decrease_step(double dt, double err, int /*error_order*/) {
    rejected_ = true;
    return dt * std::max(kMinFactor, kSafety * std::pow(err, -kAlpha));
  }
  double increase_step(double dt, double err, int /*stepper_order*/) {
    const double e = std::max(err, kMinError);
    const double factor = kSafety * std::pow(e, -kAlpha) * std::pow(previous_error_, kBeta);
    previous_error_ = e;
    const double max_factor = rejected_ ? 1.0 : kMaxFactor;
    rejected_ = false;
    return dt * std::clamp(factor, kMinFactor, max_factor);
  }
  static bool check_step_size_limit(double /*dt*/) { return true; }  // HybridRun caps the step
  static double get_max_dt() { return 0.0; }

 private:
  static constexpr double kBeta = 0.04;
  static constexpr double kAlpha = 0.2 - 0.75 * kBeta;
  static constexpr double kSafety = 0.9;
  static constexpr double kMinFactor = 0.2;
  static constexpr double kMaxFactor = 10.0;
  static constexpr double kMinError = 1e-4;
  double previous_error_ = kMinError;
  bool rejected_ = false;
};

/// System callable: f(x, dxdt, t) on std::vector states. Adjuster: PiStepAdjuster, or
/// Boost.Odeint's default_step_adjuster<double, double>.
template <typename Rhs, typename Adjuster>
class Dopri5Stepper {
 public:
  Dopri5Stepper(Rhs rhs, double atol, double rtol)
      : rhs_(std::move(rhs)),
        controlled_(boost::numeric::odeint::default_error_checker<
                    double, boost::numeric::odeint::range_algebra,
                    boost::numeric::odeint::default_operations>(atol, rtol, 1, 1)) {}

  void initialize(const State& x, double t) {
    x_new_ = x;
    dxdt_new_.resize(x.size());
    rhs_(x_new_, dxdt_new_, t);
    t_new_ = t;
    x_old_ = x_new_;
    dxdt_old_ = dxdt_new_;
    x_tmp_.resize(x.size());  // odeint's FSAL try_step writes into caller-sized outputs
    dxdt_tmp_.resize(x.size());
    t_old_ = t;
  }

  /// One controlled step of at most dt from the current state; on success the step is the
  /// new interpolation interval and dt holds the suggested next step; on rejection dt shrinks.
  bool try_step(double& dt) {
    double t = t_new_;
    const auto res = controlled_.try_step(rhs_, x_new_, dxdt_new_, t, x_tmp_, dxdt_tmp_, dt);
    if (res == boost::numeric::odeint::fail) return false;
    std::swap(x_old_, x_new_);
    std::swap(dxdt_old_, dxdt_new_);
    std::swap(x_new_, x_tmp_);
    std::swap(dxdt_new_, dxdt_tmp_);
    t_old_ = t_new_;
    t_new_ = t;
    return true;
  }

  void calc_state(double t, State& out) {
    out.resize(x_new_.size());
    controlled_.stepper().calc_state(t, out, x_old_, dxdt_old_, t_old_, x_new_, dxdt_new_, t_new_);
  }

  [[nodiscard]] const State& state() const { return x_new_; }
  [[nodiscard]] double t_old() const { return t_old_; }
  [[nodiscard]] double t_new() const { return t_new_; }

 private:
  using Base = boost::numeric::odeint::runge_kutta_dopri5<State>;
  using Checker =
      boost::numeric::odeint::default_error_checker<double, boost::numeric::odeint::range_algebra,
                                                    boost::numeric::odeint::default_operations>;
  Rhs rhs_;
  boost::numeric::odeint::controlled_runge_kutta<Base, Checker, Adjuster> controlled_;
  State x_old_, dxdt_old_, x_new_, dxdt_new_, x_tmp_, dxdt_tmp_;
  double t_old_ = 0.0, t_new_ = 0.0;
};

/// Adapts the C++17-compiled Rosenbrock4Engine to the stepper interface of the integrator.
template <typename Rhs>
class Rosenbrock4Stepper {
 public:
  /// Rhs also offers jacobian(x, t, dfdx, dfdt) -> bool (the system's exact Jacobian).
  Rosenbrock4Stepper(Rhs rhs, double atol, double rtol)
      : engine_([rhs](const State& x, State& dxdt, double t) { rhs(x, dxdt, t); },
                [rhs](const State& x, double t, State& dfdx, State& dfdt) {
                  return rhs.jacobian(x, t, dfdx, dfdt);
                },
                atol, rtol) {}
  void initialize(const State& x, double t) { engine_.initialize(x, t); }
  bool try_step(double& dt) { return engine_.try_step(dt); }
  void calc_state(double t, State& out) { engine_.calc_state(t, out); }
  [[nodiscard]] const State& state() const { return engine_.state(); }
  [[nodiscard]] double t_old() const { return engine_.t_old(); }
  [[nodiscard]] double t_new() const { return engine_.t_new(); }

 private:
  Rosenbrock4Engine engine_;
};

}  // namespace pneumachaos::detail
