// The event-locating integrator against systems with known solutions.
#include <gtest/gtest.h>

#include <cmath>
#include <numbers>
#include <vector>

#include "pneumachaos/simulate/event_integrator.hpp"
#include "support/reference_systems.hpp"

namespace pneumachaos {
namespace {

using testing::HarmonicOscillator;
using testing::RampedBlock;

double max_error_harmonic(const IntegratorOptions& o, double omega) {
  HarmonicOscillator osc(omega);
  std::vector<double> x{1.0, 0.0};
  Mode mode;
  double err = 0.0;
  const auto summary = integrate_hybrid(osc, x, mode, o, [&](double t, auto s, const Mode&) {
    err = std::max(err, std::abs(s[0] - std::cos(omega * t)));
  });
  EXPECT_EQ(summary.termination, Termination::kDurationReached);
  return err;
}

TEST(EventIntegrator, Dopri5ConvergesWithFifthOrderInTheStep) {
  // Loose tolerances leave the step at max_step; samples fall on step ends, so the error is
  // the propagated 5th-order solution's: halving h must divide it by about 2^5 = 32.
  constexpr double kOmega = 2.0 * std::numbers::pi;
  std::vector<double> errors;
  for (double h : {0.02, 0.01, 0.005}) {
    IntegratorOptions o;
    o.t_end_s = 2.0;
    o.relative_tolerance = o.absolute_tolerance = 1e-2;
    o.max_step_s = o.initial_step_s = h;
    o.sample_rate_Hz = 1.0 / h;
    errors.push_back(max_error_harmonic(o, kOmega));
  }
  for (std::size_t i = 1; i < errors.size(); ++i) {
    const double order = std::log2(errors[i - 1] / errors[i]);
    EXPECT_GT(order, 4.5) << "h step " << i;  // 5 expected; 4.5 allows pre-asymptotic terms
    EXPECT_LT(order, 6.0) << "h step " << i;
  }
}

TEST(EventIntegrator, GlobalErrorFollowsTheTolerance) {
  // With error control, dopri5's step scales as tol^(1/5) and the global error as about
  // tol^(4/5): the fitted exponent must lie near 0.8 and the error near the tolerance.
  constexpr double kOmega = 2.0 * std::numbers::pi;
  std::vector<double> tols{1e-5, 1e-6, 1e-7, 1e-8, 1e-9, 1e-10};
  std::vector<double> errors;
  for (double tol : tols) {
    IntegratorOptions o;
    o.t_end_s = 5.0;
    o.relative_tolerance = o.absolute_tolerance = tol;
    o.max_step_s = 1.0;
    o.sample_rate_Hz = 100.0;
    errors.push_back(max_error_harmonic(o, kOmega));
    EXPECT_LT(errors.back(), 100.0 * tol);
  }
  const double slope =
      std::log10(errors.front() / errors.back()) / std::log10(tols.front() / tols.back());
  EXPECT_GT(slope, 0.65);
  EXPECT_LT(slope, 1.1);
}

TEST(EventIntegrator, PIStepControlKeepsTheToleranceWithFewerRejections) {
  // The same harmonic oscillator under Hairer's PI controller: the global error stays near
  // the tolerance, and fewer steps are rejected than under odeint's default controller.
  constexpr double kOmega = 2.0 * std::numbers::pi;
  for (double tol : {1e-6, 1e-9}) {
    IntegratorOptions o;
    o.t_end_s = 5.0;
    o.relative_tolerance = o.absolute_tolerance = tol;
    o.max_step_s = 1.0;
    o.sample_rate_Hz = 100.0;
    o.step_control = StepControl::kPI;
    EXPECT_LT(max_error_harmonic(o, kOmega), 100.0 * tol) << "tol " << tol;
    std::size_t rejected[2];
    for (StepControl c : {StepControl::kOdeint, StepControl::kPI}) {
      o.step_control = c;
      HarmonicOscillator osc(kOmega);
      std::vector<double> x{1.0, 0.0};
      Mode mode;
      rejected[c == StepControl::kPI] = integrate_hybrid(osc, x, mode, o).steps_rejected;
    }
    EXPECT_LT(rejected[1], rejected[0]) << "tol " << tol;
  }
}

class SteppersTest : public ::testing::TestWithParam<StepperKind> {};

TEST_P(SteppersTest, RampedBlockSticksAndSlipsOnTheAnalyticSchedule) {
  const RampedBlock block;
  std::vector<double> x{0.0, 0.0};
  Mode mode = block.initial_mode(x, 0.0);
  IntegratorOptions o;
  o.t_end_s = 3.0;
  o.relative_tolerance = 1e-10;
  o.absolute_tolerance = 1e-12;
  o.max_step_s = 1e-2;
  o.stepper = GetParam();
  double max_stuck_speed = 0.0;
  const auto summary = integrate_hybrid(block, x, mode, o, [&](double, auto s, const Mode& m) {
    if (m.value[0] == 0) max_stuck_speed = std::max(max_stuck_speed, std::abs(s[1]));
  });
  ASSERT_EQ(summary.termination, Termination::kDurationReached) << summary.message;
  EXPECT_EQ(max_stuck_speed, 0.0);  // true stiction: v held at exactly zero

  // Expected: slip at t1, then alternately stick after the slip duration and slip after the
  // stick duration (see reference_systems.hpp for the derivation).
  std::vector<std::pair<double, EventKind>> expected;
  double t = block.breakaway_time();
  while (t < o.t_end_s) {
    expected.emplace_back(t, EventKind::kSlip);
    t += block.slip_duration();
    if (t >= o.t_end_s) break;
    expected.emplace_back(t, EventKind::kStick);
    t += block.stick_duration();
  }
  ASSERT_GE(expected.size(), 5u);
  ASSERT_EQ(summary.event_log.size(), expected.size());
  // Event times are roots of the dense output, so they carry the integration error: with
  // rtol = 1e-10 over a ~1 s schedule both steppers land within ~1e-10 s (measured 6e-11);
  // 1e-9 leaves a factor of ten.
  constexpr double kTimeTolerance = 1e-9;
  for (std::size_t i = 0; i < expected.size(); ++i) {
    EXPECT_EQ(summary.event_log[i].kind, expected[i].second) << "event " << i;
    EXPECT_NEAR(summary.event_log[i].t_s, expected[i].first, kTimeTolerance) << "event " << i;
  }
}

INSTANTIATE_TEST_SUITE_P(Steppers, SteppersTest,
                         ::testing::Values(StepperKind::kDopri5, StepperKind::kRosenbrock4));

// x'' = -omega^2 x + c t, non-autonomous so that df/dt counts; optionally with its exact
// Jacobian. Exact: x = cos(omega t) - c/omega^3 sin(omega t) + c t/omega^2.
class ForcedOscillator final : public testing::SmoothSystem {
 public:
  explicit ForcedOscillator(bool exact) : exact_(exact) {}
  [[nodiscard]] std::size_t state_size() const override { return 2; }
  void derivative(const Mode&, std::span<const double> x, std::span<double> dxdt,
                  double t) const override {
    dxdt[0] = x[1];
    dxdt[1] = -kOmega * kOmega * x[0] + kC * t;
  }
  bool jacobian(const Mode&, std::span<const double>, double, std::span<double> dfdx,
                std::span<double> dfdt) const override {
    if (!exact_) return false;
    ++calls;
    dfdx[0] = 0.0;
    dfdx[1] = 1.0;
    dfdx[2] = -kOmega * kOmega;
    dfdx[3] = 0.0;
    dfdt[0] = 0.0;
    dfdt[1] = kC;
    return true;
  }
  [[nodiscard]] static double exact_x(double t) {
    return std::cos(kOmega * t) - kC / std::pow(kOmega, 3) * std::sin(kOmega * t) +
           kC * t / (kOmega * kOmega);
  }
  static constexpr double kOmega = 10.0;
  static constexpr double kC = 5.0;
  mutable std::size_t calls = 0;

 private:
  bool exact_;
};

TEST(EventIntegrator, Rosenbrock4TakesTheSystemsExactJacobian) {
  IntegratorOptions o;
  o.t_end_s = 2.0;
  o.stepper = StepperKind::kRosenbrock4;
  o.relative_tolerance = o.absolute_tolerance = 1e-9;
  o.sample_rate_Hz = 100.0;
  const auto run = [&](const ForcedOscillator& system, double& err) {
    std::vector<double> x{1.0, 0.0};
    Mode mode;
    err = 0.0;
    return integrate_hybrid(system, x, mode, o, [&](double t, auto s, const Mode&) {
      err = std::max(err, std::abs(s[0] - ForcedOscillator::exact_x(t)));
    });
  };
  const ForcedOscillator exact(true);
  const ForcedOscillator numeric(false);
  double err_exact = 0.0, err_numeric = 0.0;
  const auto a = run(exact, err_exact);
  const auto b = run(numeric, err_numeric);
  EXPECT_GT(exact.calls, 0u);
  // Both within a few hundred times the tolerance of the exact solution over 3 periods.
  EXPECT_LT(err_exact, 1e-6);
  EXPECT_LT(err_numeric, 1e-6);
  // Differences cost n + 1 = 3 extra evaluations per Jacobian; the exact one costs none.
  EXPECT_LT(a.rhs_evaluations, b.rhs_evaluations);
}

TEST(EventIntegrator, SamplesAtExactlyTheRequestedRate) {
  HarmonicOscillator osc(1.0);
  std::vector<double> x{1.0, 0.0};
  Mode mode;
  IntegratorOptions o;
  o.t_end_s = 1.0;
  o.sample_rate_Hz = 1000.0;
  std::vector<double> times;
  integrate_hybrid(osc, x, mode, o, [&](double t, auto, const Mode&) { times.push_back(t); });
  ASSERT_EQ(times.size(), 1001u);
  for (std::size_t k = 0; k < times.size(); ++k) EXPECT_DOUBLE_EQ(times[k], k / 1000.0);
}

TEST(EventIntegrator, RejectsBadOptionsByName) {
  HarmonicOscillator osc(1.0);
  std::vector<double> x{1.0, 0.0};
  Mode mode;
  IntegratorOptions o;
  o.relative_tolerance = -1.0;
  EXPECT_THROW(
      {
        try {
          integrate_hybrid(osc, x, mode, o);
        } catch (const std::exception& e) {
          EXPECT_NE(std::string(e.what()).find("relative_tolerance"), std::string::npos);
          throw;
        }
      },
      std::exception);
}

}  // namespace
}  // namespace pneumachaos
