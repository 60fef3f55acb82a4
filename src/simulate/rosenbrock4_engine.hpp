#pragma once
// Boost.Odeint's Rosenbrock 4 stepper, behind an interface free of Boost and of C++20.
// Why a separate engine: Rosenbrock 4 works on Boost.uBLAS, and Boost 1.74's uBLAS does not
// compile as C++20 (it calls std::allocator::construct, removed in C++20), so its one
// translation unit is built as C++17 (see CMakeLists.txt).

#include <functional>
#include <memory>
#include <vector>

namespace pneumachaos::detail {

using State = std::vector<double>;
using RhsFunction = std::function<void(const State& x, State& dxdt, double t)>;
/// Exact df/dx (row-major, n x n) and df/dt; returns false when the system has none.
using JacobianFunction = std::function<bool(const State& x, double t, State& dfdx, State& dfdt)>;

class Rosenbrock4Engine {
 public:
  /// jacobian may be empty: the engine then differentiates rhs numerically.
  Rosenbrock4Engine(RhsFunction rhs, JacobianFunction jacobian, double atol, double rtol);
  ~Rosenbrock4Engine();
  Rosenbrock4Engine(const Rosenbrock4Engine&) = delete;
  Rosenbrock4Engine& operator=(const Rosenbrock4Engine&) = delete;

  void initialize(const State& x, double t);
  /// One controlled step; false (with dt reduced) when the step was rejected.
  bool try_step(double& dt);
  /// Dense output inside the last accepted step.
  void calc_state(double t, State& out);
  const State& state() const;
  double t_old() const;
  double t_new() const;

 private:
  struct Impl;
  std::unique_ptr<Impl> impl_;
};

}  // namespace pneumachaos::detail
