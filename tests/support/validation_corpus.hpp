#pragma once
// The verdict's validation corpus (docs/validation.md, the corpus row): records of known
// regime, generated here, each with its source. Noise comes from our own Box-Muller on
// std::mt19937_64 (whose sequence the standard fixes), so every standard library sees the
// same records.

#include <cmath>
#include <functional>
#include <numbers>
#include <random>
#include <string>
#include <vector>

#include "pneumachaos/analysis/regime.hpp"
#include "reference_series.hpp"

namespace pneumachaos::testing {

/// Portable standard normal deviates.
class Gaussian {
 public:
  explicit Gaussian(unsigned seed) : rng_(seed) {}
  double operator()() {
    const double u1 = (static_cast<double>(rng_() >> 11) + 0.5) * 0x1.0p-53;
    const double u2 = static_cast<double>(rng_() >> 11) * 0x1.0p-53;
    return std::sqrt(-2.0 * std::log(u1)) * std::cos(2.0 * std::numbers::pi * u2);
  }

 private:
  std::mt19937_64 rng_;
};

inline std::vector<double> with_noise(std::vector<double> x, double fraction, unsigned seed) {
  double m = 0.0, v = 0.0;
  for (double xi : x) m += xi;
  m /= static_cast<double>(x.size());
  for (double xi : x) v += (xi - m) * (xi - m);
  const double sd = std::sqrt(v / static_cast<double>(x.size()));
  Gaussian g(seed);
  for (double& xi : x) xi += fraction * sd * g();
  return x;
}

/// Rounded to `levels` steps over the record's range: an A/D converter of log2(levels) bits.
inline std::vector<double> quantised(std::vector<double> x, double levels) {
  const auto [lo, hi] = std::minmax_element(x.begin(), x.end());
  const double q = (*hi - *lo) / levels, base = *lo;
  for (double& xi : x) xi = base + q * std::round((xi - base) / q);
  return x;
}

inline std::vector<double> logistic(std::size_t n, double r, double x0 = 0.3) {
  std::vector<double> x(n);
  double v = x0;
  for (int i = 0; i < 2000; ++i) v = r * v * (1.0 - v);
  for (auto& xi : x) xi = v = r * v * (1.0 - v);
  return x;
}

/// Rossler with parameters a, b, c (x component).
inline std::vector<double> rossler(std::size_t n, double a, double b, double c, double dt) {
  return flow_x(
      [a, b, c](const std::array<double, 3>& s, std::array<double, 3>& d, double) {
        d = {-s[1] - s[2], s[0] + a * s[1], b + s[2] * (s[0] - c)};
      },
      {1.0, 1.0, 0.0}, dt, n, static_cast<std::size_t>(300.0 / dt));
}

/// Ueda's forced Duffing oscillator x'' + k x' + x^3 = B cos t, k = 0.05, B = 7.5 (Ueda 1979,
/// chaotic; the third coordinate is the forcing phase).
inline std::vector<double> ueda(std::size_t n, double dt = 0.1) {
  return flow_x(
      [](const std::array<double, 3>& s, std::array<double, 3>& d, double) {
        d = {s[1], -0.05 * s[1] - s[0] * s[0] * s[0] + 7.5 * std::cos(s[2]), 1.0};
      },
      {2.5, 0.0, 0.0}, dt, n, static_cast<std::size_t>(300.0 / dt));
}

/// Van der Pol x'' - mu (1 - x^2) x' + x = 0: a limit cycle.
inline std::vector<double> van_der_pol(std::size_t n, double mu, double dt) {
  return flow_x(
      [mu](const std::array<double, 3>& s, std::array<double, 3>& d, double) {
        d = {s[1], mu * (1.0 - s[0] * s[0]) * s[1] - s[0], 0.0};
      },
      {2.0, 0.0, 0.0}, dt, n, static_cast<std::size_t>(100.0 / dt));
}

/// Mackey-Glass x' = 0.2 x(t-17) / (1 + x(t-17)^10) - 0.1 x (Mackey & Glass 1977; chaotic for
/// tau = 17, Farmer 1982), Heun's method at h = 0.02, sampled every `dt`.
inline std::vector<double> mackey_glass(std::size_t n, double dt = 1.0) {
  const double h = 0.02;
  const auto lag = static_cast<std::size_t>(std::lround(17.0 / h));
  const auto every = static_cast<std::size_t>(std::lround(dt / h));
  const std::size_t transient = static_cast<std::size_t>(1000.0 / h);
  std::vector<double> hist(lag + 1, 1.2);  // ring buffer of the last tau
  const auto f = [](double x, double xl) { return 0.2 * xl / (1.0 + std::pow(xl, 10)) - 0.1 * x; };
  std::vector<double> out;
  double x = 1.2;
  for (std::size_t i = 0; out.size() < n; ++i) {
    const double xl0 = hist[i % (lag + 1)], xl1 = hist[(i + 1) % (lag + 1)];
    const double k1 = f(x, xl0), k2 = f(x + h * k1, xl1);
    x += 0.5 * h * (k1 + k2);
    hist[i % (lag + 1)] = x;  // becomes x(t - tau) lag + 1 steps later
    if (i >= transient && (i - transient) % every == 0) out.push_back(x);
  }
  return out;
}

/// Two incommensurate frequencies (golden ratio): a torus.
inline std::vector<double> torus(std::size_t n, double f1_per_sample) {
  std::vector<double> x(n);
  const double g = (1.0 + std::sqrt(5.0)) / 2.0;
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * f1_per_sample * static_cast<double>(i);
    x[i] = std::sin(t) + 0.6 * std::sin(g * t + 0.3);
  }
  return x;
}

/// A velocity resting at exactly zero for 40 % of each 500-sample cycle, then a half sine.
inline std::vector<double> stick_slip(std::size_t n) {
  std::vector<double> ss(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double phase = std::fmod(2.0 * static_cast<double>(i) / 1000.0, 1.0);
    ss[i] = phase < 0.4 ? 0.0 : 0.1 * std::sin((phase - 0.4) / 0.6 * std::numbers::pi);
  }
  return ss;
}

inline std::vector<double> damped(std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = static_cast<double>(i);
    x[i] = 0.066 + 0.02 * std::exp(-t / 300.0) * std::cos(0.05 * t);
  }
  return x;
}

/// x_n = a1 x_{n-1} + a2 x_{n-2} + e_n (AR(1) when a2 = 0).
inline std::vector<double> autoregressive(std::size_t n, double a1, double a2, unsigned seed) {
  Gaussian g(seed);
  std::vector<double> x(n);
  double p1 = 0.0, p2 = 0.0;
  for (std::size_t i = 0; i < n + 2000; ++i) {
    const double v = a1 * p1 + a2 * p2 + g();
    p2 = p1;
    p1 = v;
    if (i >= 2000) x[i - 2000] = v;
  }
  return x;
}

/// Narrow-band noise: AR(2) with poles at radius r and frequency f [cycles/sample].
inline std::vector<double> narrow_band(std::size_t n, double f, double r, unsigned seed) {
  return autoregressive(n, 2.0 * r * std::cos(2.0 * std::numbers::pi * f), -r * r, seed);
}

struct CorpusRecord {
  std::string name, source;
  Regime expected;
  double rate_Hz;
  std::function<std::vector<double>(std::size_t)> make;
};

inline std::vector<CorpusRecord> validation_corpus() {
  using R = Regime;
  return {
      {"logistic r=4", "May 1976; lambda = ln 2", R::kChaotic, 1.0,
       [](std::size_t n) { return logistic(n, 4.0); }},
      {"henon", "Henon 1976", R::kChaotic, 1.0, [](std::size_t n) { return henon_map(n); }},
      {"lorenz", "Lorenz 1963, dt 0.01", R::kChaotic, 100.0,
       [](std::size_t n) { return lorenz_x(n); }},
      {"rossler", "Rossler 1976, a=b=0.2, c=5.7, dt 0.1", R::kChaotic, 10.0,
       [](std::size_t n) { return rossler(n, 0.2, 0.2, 5.7, 0.1); }},
      {"rossler wolf", "Wolf et al. 1985: a=0.15, b=0.2, c=10", R::kChaotic, 10.0,
       [](std::size_t n) { return rossler(n, 0.15, 0.2, 10.0, 0.1); }},
      {"ueda", "Ueda 1979: k=0.05, B=7.5, dt 0.1", R::kChaotic, 10.0,
       [](std::size_t n) { return ueda(n); }},
      {"mackey-glass", "Mackey & Glass 1977, tau=17, dt 1", R::kChaotic, 1.0,
       [](std::size_t n) { return mackey_glass(n); }},
      {"lorenz 10% noise", "Lorenz + 10 % of std white noise", R::kChaotic, 100.0,
       [](std::size_t n) { return with_noise(lorenz_x(n), 0.1, 11); }},
      {"lorenz 8-bit", "Lorenz rounded to 256 levels", R::kChaotic, 100.0,
       [](std::size_t n) { return quantised(lorenz_x(n), 256.0); }},
      {"lorenz oversampled", "Lorenz, dt 0.005: 150 samples per orbit, as the rig at 1 kHz", R::kChaotic, 200.0,
       [](std::size_t n) { return lorenz_x(n, 0.005); }},
      {"sine 5% noise", "limit cycle + noise", R::kPeriodic, 1000.0,
       [](std::size_t n) { return sine(n, 10.0, 1000.0, 0.05); }},
      {"sine 20% noise", "limit cycle + noise", R::kPeriodic, 1000.0,
       [](std::size_t n) { return sine(n, 10.0, 1000.0, 0.2); }},
      {"van der pol 5% noise", "mu = 2, dt 0.05", R::kPeriodic, 20.0,
       [](std::size_t n) { return with_noise(van_der_pol(n, 2.0, 0.05), 0.05, 5); }},
      {"logistic r=3.83", "period-3 window", R::kPeriodic, 1.0,
       [](std::size_t n) { return logistic(n, 3.83); }},
      {"logistic r=3.5", "period 4 (doubled twice)", R::kPeriodic, 1.0,
       [](std::size_t n) { return logistic(n, 3.5); }},
      {"rossler c=3.5", "period-2 orbit (Rossler a=b=0.2, c=3.5)", R::kPeriodic, 10.0,
       [](std::size_t n) { return rossler(n, 0.2, 0.2, 3.5, 0.1); }},
      {"torus", "two incommensurate tones (golden ratio)", R::kQuasiPeriodic, 1000.0,
       [](std::size_t n) { return torus(n, 0.01); }},
      {"stick-slip", "rests 40 % of each cycle", R::kStickSlip, 1000.0,
       [](std::size_t n) { return stick_slip(n); }},
      {"damped", "damped approach to a steady speed", R::kSteady, 1000.0,
       [](std::size_t n) { return damped(n); }},
      {"white noise", "Gaussian", R::kStochastic, 1000.0,
       [](std::size_t n) { return autoregressive(n, 0.0, 0.0, 3); }},
      {"ar1 red noise", "AR(1), a = 0.95", R::kStochastic, 1000.0,
       [](std::size_t n) { return autoregressive(n, 0.95, 0.0, 4); }},
      {"narrow-band noise", "AR(2), f = 0.02/sample, r = 0.98", R::kStochastic, 1000.0,
       [](std::size_t n) { return narrow_band(n, 0.02, 0.98, 6); }},
  };
}

}  // namespace pneumachaos::testing
