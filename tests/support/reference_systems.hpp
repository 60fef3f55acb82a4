#pragma once
// Reference hybrid systems with known solutions, shared by the tests (see docs/architecture.md).

#include <cmath>
#include <numbers>

#include "pneumachaos/core/hybrid_system.hpp"

namespace pneumachaos::testing {

/// A system without events or modes: only the derivative is left to define.
class SmoothSystem : public HybridSystem {
 public:
  [[nodiscard]] std::size_t event_count(const Mode&) const override { return 0; }
  void event_functions(const Mode&, std::span<const double>, double,
                       std::span<double>) const override {}
  EventOutcome apply_event(std::size_t, Mode&, std::span<double>, double) const override {
    return {};
  }
  [[nodiscard]] Mode initial_mode(std::span<const double>, double) const override { return {}; }
};

/// x'' = -omega^2 x; state (x, v). Exact: x = x0 cos(omega t).
class HarmonicOscillator final : public SmoothSystem {
 public:
  explicit HarmonicOscillator(double omega) : omega_(omega) {}
  [[nodiscard]] std::size_t state_size() const override { return 2; }
  void derivative(const Mode&, std::span<const double> x, std::span<double> dxdt,
                  double) const override {
    dxdt[0] = x[1];
    dxdt[1] = -omega_ * omega_ * x[0];
  }

 private:
  double omega_;
};

/// Lorenz (sigma 10, rho 28, beta 8/3) as a hybrid system without events; largest exponent
/// 0.9056 per time unit (Sprott, Chaos and Time-Series Analysis, 2003, table A.1).
class LorenzSystem final : public SmoothSystem {
 public:
  [[nodiscard]] std::size_t state_size() const override { return 3; }
  void derivative(const Mode&, std::span<const double> s, std::span<double> d,
                  double) const override {
    d[0] = 10.0 * (s[1] - s[0]);
    d[1] = s[0] * (28.0 - s[2]) - s[1];
    d[2] = s[0] * s[1] - 8.0 / 3.0 * s[2];
  }
};

/// A block of mass m on a fixed floor with Coulomb friction (static Fs, kinetic Fc), pushed
/// through a spring k whose far end moves at constant speed u: the pushing force ramps while
/// the block sticks. Analytic cycle (derived in test_event_integrator.cpp): breakaway at
/// t1 = Fs/(k u); slip lasts (pi + 2 phi)/omega with omega = sqrt(k/m),
/// phi = atan2(u/omega, (Fs-Fc)/k); the block then sticks for 2 (Fs - Fc)/(k u).
/// State (x, v); mode value[0]: 0 stuck, 1 sliding forward.
struct RampedBlock final : public HybridSystem {
  double m = 1.0, k = 100.0, u = 0.05, Fs = 3.0, Fc = 2.0;

  [[nodiscard]] double push(std::span<const double> x, double t) const {
    return k * (u * t - x[0]);
  }
  [[nodiscard]] std::size_t state_size() const override { return 2; }
  void derivative(const Mode& mode, std::span<const double> x, std::span<double> dxdt,
                  double t) const override {
    if (mode.value[0] == 0) {
      dxdt[0] = dxdt[1] = 0.0;
    } else {
      dxdt[0] = x[1];
      dxdt[1] = (push(x, t) - Fc) / m;
    }
  }
  [[nodiscard]] std::size_t event_count(const Mode&) const override { return 1; }
  void event_functions(const Mode& mode, std::span<const double> x, double t,
                       std::span<double> g) const override {
    g[0] = mode.value[0] == 0 ? Fs - push(x, t) : x[1];
  }
  EventOutcome apply_event(std::size_t, Mode& mode, std::span<double> x, double t) const override {
    if (mode.value[0] == 0) {
      mode.value[0] = 1;
      return {EventKind::kSlip, false, ""};
    }
    x[1] = 0.0;
    mode.value[0] = push(x, t) > Fs ? 1 : 0;
    return {EventKind::kStick, false, ""};
  }
  [[nodiscard]] Mode initial_mode(std::span<const double>, double) const override { return {}; }

  [[nodiscard]] double omega() const { return std::sqrt(k / m); }
  [[nodiscard]] double breakaway_time() const { return Fs / (k * u); }
  [[nodiscard]] double slip_duration() const {
    const double phi = std::atan2(u / omega(), (Fs - Fc) / k);
    return (std::numbers::pi + 2.0 * phi) / omega();
  }
  [[nodiscard]] double stick_duration() const { return 2.0 * (Fs - Fc) / (k * u); }
};

}  // namespace pneumachaos::testing
