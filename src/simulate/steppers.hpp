#pragma once
// Thin adapters that give two Boost.Odeint steppers one interface for the event integrator:
// try one controlled step, then interpolate anywhere inside the last accepted step. The
// stepping loop is ours (not odeint's integrate functions) because events must be located
// and the mode switched between steps, and rejected steps must be counted.

#include <boost/numeric/odeint/stepper/controlled_runge_kutta.hpp>
#include <boost/numeric/odeint/stepper/runge_kutta_dopri5.hpp>
#include <cmath>
#include <vector>

#include "rosenbrock4_engine.hpp"

namespace pneumachaos::detail {

/// System callable: f(x, dxdt, t) on std::vector states.
template <typename Rhs>
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
  Rhs rhs_;
  boost::numeric::odeint::controlled_runge_kutta<Base> controlled_;
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
