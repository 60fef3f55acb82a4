// Held-out records for the verdict (docs/validation.md, the held-out row): systems and settings
// that are not in the validation corpus. Prints every verdict (the table in the docs) and
// asserts what must hold whatever the remaining misses: no regular or stochastic record is
// called chaotic, and the short Lorenz record is undetermined. About 30 s: label `long`.
#include <gtest/gtest.h>

#include <fmt/format.h>

#include <cstdlib>

#include "pneumachaos/analysis/analyze.hpp"
#include "support/validation_corpus.hpp"

namespace pneumachaos {
namespace {

using namespace pneumachaos::testing;

std::vector<double> lozi(std::size_t n) {  // Lozi 1978, a = 1.7, b = 0.5: chaotic
  std::vector<double> x(n);
  double a = 0.1, b = 0.1;
  for (std::size_t i = 0; i < n + 1000; ++i) {
    const double an = 1.0 - 1.7 * std::abs(a) + b;
    b = 0.5 * a;
    a = an;
    if (i >= 1000) x[i - 1000] = a;
  }
  return x;
}

// Guckenheimer & Holmes' forced Duffing x'' + 0.3 x' - x + x^3 = 0.5 cos(1.2 t): chaotic.
std::vector<double> duffing(std::size_t n) {
  const double dt = 0.05 * 2.0 * std::numbers::pi / 1.2 / 2.0;
  return flow_x(
      [](const std::array<double, 3>& s, std::array<double, 3>& d, double) {
        d = {s[1], -0.3 * s[1] + s[0] - s[0] * s[0] * s[0] + 0.5 * std::cos(s[2]), 1.2};
      },
      {1.0, 0.0, 0.0}, dt, n, static_cast<std::size_t>(300.0 / dt));
}

// Mackey-Glass with tau = 30 (Farmer 1982: chaotic, higher-dimensional than tau = 17), Heun's
// method at h = 0.02, sampled every 2 time units.
std::vector<double> mackey_glass_30(std::size_t n) {
  const double h = 0.02;
  const std::size_t lag = 1500, every = 100, transient = 50000;
  std::vector<double> hist(lag + 1, 1.2), out;
  const auto f = [](double x, double xl) { return 0.2 * xl / (1.0 + std::pow(xl, 10)) - 0.1 * x; };
  double x = 1.2;
  for (std::size_t i = 0; out.size() < n; ++i) {
    const double k1 = f(x, hist[i % (lag + 1)]), k2 = f(x + h * k1, hist[(i + 1) % (lag + 1)]);
    x += 0.5 * h * (k1 + k2);
    hist[i % (lag + 1)] = x;
    if (i >= transient && (i - transient) % every == 0) out.push_back(x);
  }
  return out;
}

std::vector<double> torus3(std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) {
    const double t = 2.0 * std::numbers::pi * 0.013 * static_cast<double>(i);
    x[i] = std::sin(t) + 0.5 * std::sin(std::sqrt(2.0) * t) + 0.3 * std::sin(std::sqrt(3.0) * t);
  }
  return x;
}

std::vector<double> sawtooth(std::size_t n) {
  std::vector<double> x(n);
  for (std::size_t i = 0; i < n; ++i) x[i] = std::fmod(static_cast<double>(i) / 77.0, 1.0);
  return with_noise(x, 0.05, 9);
}

std::vector<double> random_walk(std::size_t n) {
  Gaussian g(31);
  std::vector<double> x(n);
  double v = 0.0;
  for (double& xi : x) xi = v += g();
  return x;
}

std::vector<CorpusRecord> held_out() {
  using R = Regime;
  return {
      {"logistic r=3.9", "", R::kChaotic, 1.0, [](std::size_t n) { return logistic(n, 3.9, 0.2); }},
      {"logistic r=3.74", "period 5", R::kPeriodic, 1.0,
       [](std::size_t n) { return logistic(n, 3.74, 0.2); }},
      {"logistic r=3.2", "period 2", R::kPeriodic, 1.0,
       [](std::size_t n) { return logistic(n, 3.2, 0.2); }},
      {"lozi", "", R::kChaotic, 1.0, lozi},
      {"lorenz dt 0.02", "other start", R::kChaotic, 50.0,
       [](std::size_t n) { return lorenz_x(n, 0.02, {-3.0, 2.0, 25.0}); }},
      {"lorenz 6-bit", "", R::kChaotic, 100.0,
       [](std::size_t n) { return quantised(lorenz_x(n, 0.01, {2.0, -1.0, 15.0}), 64); }},
      {"lorenz 20% noise", "", R::kChaotic, 100.0,
       [](std::size_t n) { return with_noise(lorenz_x(n), 0.2, 17); }},
      {"rossler dt 0.2", "", R::kChaotic, 5.0,
       [](std::size_t n) { return rossler(n, 0.2, 0.2, 5.7, 0.2); }},
      {"rossler c=4", "period 4", R::kPeriodic, 10.0,
       [](std::size_t n) { return rossler(n, 0.2, 0.2, 4.0, 0.1); }},
      {"duffing", "0.3/0.5/1.2", R::kChaotic, 20.0, duffing},
      {"mackey-glass 30", "", R::kChaotic, 0.5, mackey_glass_30},
      {"torus 3", "", R::kQuasiPeriodic, 1000.0, torus3},
      {"van der pol mu=5", "2 % noise", R::kPeriodic, 20.0,
       [](std::size_t n) { return with_noise(van_der_pol(n, 5.0, 0.05), 0.02, 8); }},
      {"sawtooth", "5 % noise", R::kPeriodic, 1000.0, sawtooth},
      {"sine 50% noise", "", R::kPeriodic, 1000.0,
       [](std::size_t n) { return sine(n, 7.0, 1000.0, 0.5, 4); }},
      {"ar1 0.8", "", R::kStochastic, 1000.0,
       [](std::size_t n) { return autoregressive(n, 0.8, 0.0, 41); }},
      {"ar1 0.99", "", R::kStochastic, 1000.0,
       [](std::size_t n) { return autoregressive(n, 0.99, 0.0, 42); }},
      {"narrow band", "f 0.05, r 0.95", R::kStochastic, 1000.0,
       [](std::size_t n) { return narrow_band(n, 0.05, 0.95, 43); }},
      {"random walk", "", R::kStochastic, 1000.0, random_walk},
  };
}

TEST(RegimeHeldOut, NoFalseChaosAndShortLorenzUndetermined) {
  if (std::getenv("PNEUMACHAOS_LONG_TESTS") == nullptr) {
    GTEST_SKIP() << "a long check: ctest --test-dir build -L long";
  }
  int right = 0, total = 0;
  for (std::size_t n : {5000u, 10000u}) {
    for (std::size_t surrogates : {0u, 39u}) {
      for (const CorpusRecord& c : held_out()) {
        AnalysisOptions o;
        o.surrogates.count = surrogates;
        const AnalysisResult r = analyze_series(c.make(n), c.rate_Hz, o);
        fmt::print("{:<18} {:>6} surrogates {:>2}: expected {:<14} verdict {}\n", c.name, n,
                   surrogates, regime_name(c.expected), regime_name(r.verdict.regime));
        right += r.verdict.regime == c.expected ? 1 : 0;
        ++total;
        if (c.expected != Regime::kChaotic) EXPECT_FALSE(r.verdict.chaotic) << c.name << " " << n;
      }
    }
  }
  fmt::print("held out: {} of {} verdicts right\n", right, total);
  EXPECT_EQ(analyze_series(lorenz_x(1000), 100.0).verdict.regime, Regime::kUndetermined);
}

}  // namespace
}  // namespace pneumachaos
