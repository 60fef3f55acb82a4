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

// Odeint's Rosenbrock 4 loses its order on non-autonomous systems even with an exact df/dt
// (seen on x'' = -100 x + 5 t: the step count grows like 1/tol). So the engine integrates the
// autonomous system (x, tau) with dtau/dt = 1, where df/dt is an ordinary Jacobian column.
struct Rosenbrock4Engine::Impl {
  RhsFunction rhs;
  JacobianFunction exact_jacobian;
  odeint::rosenbrock4_controller<odeint::rosenbrock4<double>> controlled;
  UVec x_old, x_new, x_tmp, x_interp;  // augmented: n states, then time
  State state, a, f0, f1, dfdx, dfdt_exact;
  std::size_t n = 0;
  double t_old = 0.0, t_new = 0.0;
  // Below this magnitude a component counts as small (the error control's own view of it),
  // which bounds the difference step away from zero; a step at rounding level makes the
  // Jacobian noise and Rosenbrock's order collapses.
  double typical_magnitude;

  Impl(RhsFunction f, JacobianFunction j, double atol, double rtol)
      : rhs(std::move(f)),
        exact_jacobian(std::move(j)),
        controlled(atol, rtol),
        typical_magnitude(atol / rtol) {}

  void eval(const UVec& xa, UVec& dxa) {
    a.resize(n);
    for (std::size_t i = 0; i < n; ++i) a[i] = xa[i];
    f0.resize(n);
    rhs(a, f0, xa[n]);
    dxa.resize(n + 1, false);
    for (std::size_t i = 0; i < n; ++i) dxa[i] = f0[i];
    dxa[n] = 1.0;
  }

  // The system's exact Jacobian in the augmented form: d(f, 1)/d(x, tau).
  bool exact(const UVec& xa, UMat& J) {
    if (!exact_jacobian) return false;
    a.resize(n);
    for (std::size_t i = 0; i < n; ++i) a[i] = xa[i];
    dfdx.resize(n * n);
    dfdt_exact.resize(n);
    if (!exact_jacobian(a, xa[n], dfdx, dfdt_exact)) return false;
    J.resize(n + 1, n + 1, false);
    for (std::size_t i = 0; i <= n; ++i) {
      for (std::size_t j = 0; j <= n; ++j) {
        J(i, j) = i == n ? 0.0 : (j == n ? dfdt_exact[i] : dfdx[i * n + j]);
      }
    }
    return true;
  }

  // Without an exact one, the Jacobian by forward differences of the same right-hand side;
  // the step is ~sqrt(machine epsilon) relative to each component.
  void jacobian(const UVec& xa, UMat& J, UVec& dfdt) {
    const std::size_t m = n + 1;
    dfdt.resize(m, false);
    for (std::size_t i = 0; i < m; ++i) dfdt[i] = 0.0;  // autonomous by construction
    if (exact(xa, J)) return;
    UVec base(m), probe(m), f_probe(m);
    eval(xa, base);
    probe = xa;
    J.resize(m, m, false);
    for (std::size_t j = 0; j < m; ++j) {
      const double xj = xa[j];
      const double h = 1.5e-8 * std::max(std::abs(xj), typical_magnitude);
      probe[j] = xj + h;
      eval(probe, f_probe);
      probe[j] = xj;
      for (std::size_t i = 0; i < m; ++i) J(i, j) = (f_probe[i] - base[i]) / h;
    }
  }
};

Rosenbrock4Engine::Rosenbrock4Engine(RhsFunction rhs, JacobianFunction jacobian, double atol,
                                     double rtol)
    : impl_(std::make_unique<Impl>(std::move(rhs), std::move(jacobian), atol, rtol)) {}
Rosenbrock4Engine::~Rosenbrock4Engine() = default;

void Rosenbrock4Engine::initialize(const State& x, double t) {
  Impl& m = *impl_;
  m.n = x.size();
  m.x_new.resize(m.n + 1, false);
  for (std::size_t i = 0; i < m.n; ++i) m.x_new[i] = x[i];
  m.x_new[m.n] = t;
  m.x_old = m.x_new;
  m.x_tmp.resize(m.n + 1, false);  // odeint writes into caller-sized outputs
  m.x_interp.resize(m.n + 1, false);
  m.state = x;
  m.t_new = m.t_old = t;
}

bool Rosenbrock4Engine::try_step(double& dt) {
  Impl& m = *impl_;
  double t = m.t_new;
  auto rhs = [&m](const UVec& x, UVec& dxdt, double) { m.eval(x, dxdt); };
  auto jac = [&m](const UVec& x, UMat& J, double, UVec& dfdt) { m.jacobian(x, J, dfdt); };
  const auto res = m.controlled.try_step(std::make_pair(rhs, jac), m.x_new, t, m.x_tmp, dt);
  if (res == odeint::fail) return false;
  m.controlled.stepper().prepare_dense_output();
  std::swap(m.x_old, m.x_new);
  std::swap(m.x_new, m.x_tmp);
  m.t_old = m.t_new;
  m.t_new = t;
  m.state.assign(m.x_new.begin(), m.x_new.begin() + static_cast<std::ptrdiff_t>(m.n));
  return true;
}

void Rosenbrock4Engine::calc_state(double t, State& out) {
  Impl& m = *impl_;
  m.controlled.stepper().calc_state(t, m.x_interp, m.x_old, m.t_old, m.x_new, m.t_new);
  out.assign(m.x_interp.begin(), m.x_interp.begin() + static_cast<std::ptrdiff_t>(m.n));
}

const State& Rosenbrock4Engine::state() const { return impl_->state; }
double Rosenbrock4Engine::t_old() const { return impl_->t_old; }
double Rosenbrock4Engine::t_new() const { return impl_->t_new; }

}  // namespace pneumachaos::detail
