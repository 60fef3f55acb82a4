// Compiled as C++17: see rosenbrock4_engine.hpp.
#include "rosenbrock4_engine.hpp"

#include <algorithm>
#include <boost/numeric/odeint/stepper/rosenbrock4.hpp>
#include <boost/numeric/odeint/stepper/rosenbrock4_controller.hpp>
#include <cmath>
#include <utility>

namespace pneumachaos::detail {

namespace odeint = boost::numeric::odeint;
using UVec = boost::numeric::ublas::vector<double>;
using UMat = boost::numeric::ublas::matrix<double>;

namespace {
void to_u(const State& x, UVec& u) {
  u.resize(x.size(), false);
  for (std::size_t i = 0; i < x.size(); ++i) u[i] = x[i];
}
void from_u(const UVec& u, State& x) {
  x.resize(u.size());
  for (std::size_t i = 0; i < u.size(); ++i) x[i] = u[i];
}
}  // namespace

struct Rosenbrock4Engine::Impl {
  RhsFunction rhs;
  odeint::rosenbrock4_controller<odeint::rosenbrock4<double>> controlled;
  UVec x_old, x_new, x_tmp, x_interp;
  State state, a, f0, f1;
  double t_old = 0.0, t_new = 0.0;

  Impl(RhsFunction f, double atol, double rtol) : rhs(std::move(f)), controlled(atol, rtol) {}

  void eval(const UVec& x, UVec& dxdt, double t) {
    from_u(x, a);
    f0.resize(a.size());
    rhs(a, f0, t);
    to_u(f0, dxdt);
  }

  // The Jacobian by forward differences of the same right-hand side, so that no model has to
  // supply one by hand; the step is ~sqrt(machine epsilon) relative to each component.
  void jacobian(const UVec& x, UMat& J, double t, UVec& dfdt) {
    const std::size_t n = x.size();
    from_u(x, a);
    f0.resize(n);
    f1.resize(n);
    rhs(a, f0, t);
    J.resize(n, n, false);
    for (std::size_t j = 0; j < n; ++j) {
      const double xj = a[j];
      const double h = 1.5e-8 * std::max(std::abs(xj), 1e-6);
      a[j] = xj + h;
      rhs(a, f1, t);
      a[j] = xj;
      for (std::size_t i = 0; i < n; ++i) J(i, j) = (f1[i] - f0[i]) / h;
    }
    dfdt.resize(n, false);
    for (std::size_t i = 0; i < n; ++i) dfdt[i] = 0.0;  // autonomous within a mode
  }
};

Rosenbrock4Engine::Rosenbrock4Engine(RhsFunction rhs, double atol, double rtol)
    : impl_(std::make_unique<Impl>(std::move(rhs), atol, rtol)) {}
Rosenbrock4Engine::~Rosenbrock4Engine() = default;

void Rosenbrock4Engine::initialize(const State& x, double t) {
  to_u(x, impl_->x_new);
  impl_->x_old = impl_->x_new;
  impl_->x_tmp.resize(x.size(), false);  // odeint writes into caller-sized outputs
  impl_->x_interp.resize(x.size(), false);
  impl_->state = x;
  impl_->t_new = impl_->t_old = t;
}

bool Rosenbrock4Engine::try_step(double& dt) {
  Impl& m = *impl_;
  double t = m.t_new;
  auto rhs = [&m](const UVec& x, UVec& dxdt, double tt) { m.eval(x, dxdt, tt); };
  auto jac = [&m](const UVec& x, UMat& J, double tt, UVec& dfdt) { m.jacobian(x, J, tt, dfdt); };
  const auto res = m.controlled.try_step(std::make_pair(rhs, jac), m.x_new, t, m.x_tmp, dt);
  if (res == odeint::fail) return false;
  m.controlled.stepper().prepare_dense_output();
  std::swap(m.x_old, m.x_new);
  std::swap(m.x_new, m.x_tmp);
  m.t_old = m.t_new;
  m.t_new = t;
  from_u(m.x_new, m.state);
  return true;
}

void Rosenbrock4Engine::calc_state(double t, State& out) {
  Impl& m = *impl_;
  m.controlled.stepper().calc_state(t, m.x_interp, m.x_old, m.t_old, m.x_new, m.t_new);
  from_u(m.x_interp, out);
}

const State& Rosenbrock4Engine::state() const { return impl_->state; }
double Rosenbrock4Engine::t_old() const { return impl_->t_old; }
double Rosenbrock4Engine::t_new() const { return impl_->t_new; }

}  // namespace pneumachaos::detail
