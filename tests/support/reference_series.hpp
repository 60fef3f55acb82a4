#pragma once
// Series with known largest Lyapunov exponents (docs/validation.md, "The chaos analysis
// against known answers"), made by
// the tests themselves: the x coordinate only, transients discarded.

#include <array>
#include <boost/numeric/odeint.hpp>
#include <cmath>
#include <numbers>
#include <random>
#include <vector>

namespace pneumachaos::testing {

/// x_{n+1} = 4 x_n (1 - x_n); lambda = ln 2 per iteration (exact for r = 4).
inline std::vector<double> logistic_map(std::size_t n, double x0 = 0.3) {
  std::vector<double> x(n);
  double v = x0;
  for (int i = 0; i < 1000; ++i) v = 4.0 * v * (1.0 - v);
  for (auto& xi : x) {
    v = 4.0 * v * (1.0 - v);
    xi = v;
  }
  return x;
}

/// Henon map a = 1.4, b = 0.3; lambda ~ 0.419 per iteration (Henon 1976; Sprott, Chaos and
/// Time-Series Analysis, 2003, table A.1: 0.41922).
inline std::vector<double> henon_map(std::size_t n) {
  std::vector<double> x(n);
  double a = 0.1, b = 0.1;
  for (std::size_t i = 0; i < n + 1000; ++i) {
    const double an = 1.0 - 1.4 * a * a + b;
    b = 0.3 * a;
    a = an;
    if (i >= 1000) x[i - 1000] = a;
  }
  return x;
}

template <typename Rhs>
std::vector<double> flow_x(Rhs rhs, std::array<double, 3> s, double dt, std::size_t n,
                           std::size_t transient) {
  namespace odeint = boost::numeric::odeint;
  auto stepper =
      odeint::make_dense_output(1e-12, 1e-12, odeint::runge_kutta_dopri5<std::array<double, 3>>());
  std::vector<double> x;
  x.reserve(n);
  std::size_t k = 0;
  odeint::integrate_const(stepper, rhs, s, 0.0, dt * (n + transient - 1), dt,
                          [&](const std::array<double, 3>& st, double) {
                            if (k++ >= transient) x.push_back(st[0]);
                          });
  return x;
}

/// Lorenz sigma = 10, rho = 28, beta = 8/3; lambda ~ 0.906 per time unit (Sprott 2003, A.1).
inline std::vector<double> lorenz_x(std::size_t n, double dt = 0.01,
                                    std::array<double, 3> start = {1.0, 1.0, 20.0}) {
  return flow_x(
      [](const std::array<double, 3>& s, std::array<double, 3>& d, double) {
        d = {10.0 * (s[1] - s[0]), s[0] * (28.0 - s[2]) - s[1], s[0] * s[1] - 8.0 / 3.0 * s[2]};
      },
      start, dt, n, static_cast<std::size_t>(50.0 / dt));
}

/// Rossler a = b = 0.2, c = 5.7; lambda ~ 0.0714 per time unit (Sprott 2003, A.1).
inline std::vector<double> rossler_x(std::size_t n, double dt = 0.1,
                                     std::array<double, 3> start = {1.0, 1.0, 0.0}) {
  return flow_x(
      [](const std::array<double, 3>& s, std::array<double, 3>& d, double) {
        d = {-s[1] - s[2], s[0] + 0.2 * s[1], 0.2 + s[2] * (s[0] - 5.7)};
      },
      start, dt, n, static_cast<std::size_t>(200.0 / dt));
}

inline std::vector<double> sine(std::size_t n, double f_Hz, double rate_Hz, double noise = 0.0,
                                unsigned seed = 1) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    x[i] = std::sin(2.0 * std::numbers::pi * f_Hz * i / rate_Hz) + noise * g(rng);
  }
  return x;
}

inline std::vector<double> white_noise(std::size_t n, unsigned seed = 7) {
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> g(0.0, 1.0);
  std::vector<double> x(n);
  for (auto& v : x) v = g(rng);
  return x;
}

}  // namespace pneumachaos::testing
