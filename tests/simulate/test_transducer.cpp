// The transducers between the simulated signals and the measured records (docs/model.md, "The
// transducer"): the first-order lag, the noise, the converter, and their keys.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <numbers>
#include <string>
#include <vector>

#include "support/error_text.hpp"
#include "pneumachaos/model/variation.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/simulate/measured_channels.hpp"
#include "simulate/transducer_stages.hpp"

namespace pneumachaos {
namespace {

constexpr double kRate_Hz = 1000.0;  // the paper's A/D rate
constexpr double kH_s = 1.0 / kRate_Hz;
constexpr double kAmbient_Pa = 101325.0;

double tau_of(double bandwidth_Hz) { return 1.0 / (2.0 * std::numbers::pi * bandwidth_Hz); }

// A record with the channels the transducers read.
TimeSeries record_of(std::vector<double> v, std::vector<double> p1, std::vector<double> p2) {
  TimeSeries s(kRate_Hz);
  s.add_channel("v", "m/s", std::move(v));
  s.add_channel("P1", "Pa", std::move(p1));
  s.add_channel("P2", "Pa", std::move(p2));
  return s;
}

TimeSeries constant_record(std::size_t n, double v, double p1, double p2) {
  return record_of(std::vector<double>(n, v), std::vector<double>(n, p1),
                   std::vector<double>(n, p2));
}

std::vector<double> difference(const std::vector<double>& a, const std::vector<double>& b) {
  std::vector<double> d(a.size());
  for (std::size_t i = 0; i < a.size(); ++i) d[i] = a[i] - b[i];
  return d;
}

double mean_of(const std::vector<double>& x) {
  double sum = 0.0;
  for (double v : x) sum += v;
  return sum / static_cast<double>(x.size());
}

double sd_of(const std::vector<double>& x) {
  const double m = mean_of(x);
  double sum = 0.0;
  for (double v : x) sum += (v - m) * (v - m);
  return std::sqrt(sum / static_cast<double>(x.size()));
}

TEST(Transducer, LagHasUnitGainAtDc) {
  const std::vector<double> y = first_order_lag(std::vector<double>(5000, 0.123), kRate_Hz, 20.0);
  for (double v : y) EXPECT_NEAR(v, 0.123, 1e-15);
}

// The exact solution of tau y' + y = x on a stretch where x is linear with slope s, from
// (y0, x0) over dt: y = x - s tau + (y0 - x0 + s tau) exp(-dt / tau).
double lag_of_ramp(double y0, double x0, double slope, double tau, double dt) {
  const double x = x0 + slope * dt;
  return x - slope * tau + (y0 - x0 + slope * tau) * std::exp(-dt / tau);
}

// A first-order hold joins the samples by straight lines, so on an input that is linear
// between breakpoints at samples the discrete lag must equal the continuous solution at
// every sample, to rounding; here computed stretch by stretch from its start.
TEST(Transducer, LagIsExactOnAPiecewiseLinearInput) {
  const std::vector<std::pair<std::size_t, double>> corners = {
      {0, 0.2}, {30, 1.0}, {80, 1.0}, {95, -0.5}, {300, -0.5}};
  std::vector<double> x, exact;
  const double tau = tau_of(20.0);
  double y0 = corners[0].second;  // the sensor settled on the first sample
  for (std::size_t k = 0; k + 1 < corners.size(); ++k) {
    const auto [n0, x0] = corners[k];
    const auto [n1, x1] = corners[k + 1];
    const double slope = (x1 - x0) / (static_cast<double>(n1 - n0) * kH_s);
    for (std::size_t n = n0; n < n1; ++n) {
      const double dt = static_cast<double>(n - n0) * kH_s;
      x.push_back(x0 + slope * dt);
      exact.push_back(lag_of_ramp(y0, x0, slope, tau, dt));
    }
    y0 = lag_of_ramp(y0, x0, slope, tau, static_cast<double>(n1 - n0) * kH_s);
  }
  const std::vector<double> y = first_order_lag(x, kRate_Hz, 20.0);
  for (std::size_t n = 0; n < y.size(); ++n) EXPECT_NEAR(y[n], exact[n], 1e-13) << n;
}

// A step in a record sampled at 1 kHz lies somewhere between two samples; the first-order hold
// draws it as a ramp over that interval, which lags the ideal step response 1 - exp(-t/tau) by
// about h/2. At t = tau = 10 h the ramp's exact response is 1 - e^-1 (tau/h)(e^(h/tau) - 1), so
// the gap to 1 - e^-1 is e^-1 ((tau/h)(e^(h/tau) - 1) - 1) = 0.0190: the tolerance 0.02.
TEST(Transducer, StepReachesOneMinusOneOverEAtTau) {
  const double tau = 10.0 * kH_s;
  const double bandwidth_Hz = 1.0 / (2.0 * std::numbers::pi * tau);
  std::vector<double> x(100, 1.0);
  x[0] = 0.0;
  const std::vector<double> y = first_order_lag(x, kRate_Hz, bandwidth_Hz);
  const double ideal = 1.0 - std::exp(-1.0);
  const double held = 1.0 - std::exp(-1.0) * (tau / kH_s) * std::expm1(kH_s / tau);
  EXPECT_NEAR(y[10], held, 1e-12);
  EXPECT_NEAR(y[10], ideal, 0.02);
  EXPECT_LT(y[10], ideal);  // the hold's lag, never a lead
}

// A sine at the corner frequency: amplitude 1/sqrt(2) and phase -45 degrees. Sampling costs the
// amplitude the linear interpolation's own loss at f, sinc^2(pi f h) ~ 1 - (pi f h)^2 / 3: 0.82 %
// at 50 Hz, 0.033 % at 10 Hz, which is the tolerance; the interpolation is symmetric, so it
// leaves the phase (within 0.1 degree).
TEST(Transducer, SineAtTheCornerIsAttenuatedToOneOverRootTwo) {
  for (const double f_Hz : {10.0, 50.0}) {
    std::vector<double> x(3000);
    for (std::size_t n = 0; n < x.size(); ++n)
      x[n] = std::sin(2.0 * std::numbers::pi * f_Hz * n * kH_s);
    const std::vector<double> y = first_order_lag(x, kRate_Hz, f_Hz);
    // Past the transient (exp(-1 s / tau)), over the last 2 s: a whole number of periods.
    double in_phase = 0.0, quadrature = 0.0;
    for (std::size_t n = 1000; n < y.size(); ++n) {
      const double w = 2.0 * std::numbers::pi * f_Hz * n * kH_s;
      in_phase += 2.0 * y[n] * std::sin(w) / 2000.0;
      quadrature += 2.0 * y[n] * std::cos(w) / 2000.0;
    }
    const double gain = std::hypot(in_phase, quadrature) * std::sqrt(2.0);
    const double loss = std::pow(std::numbers::pi * f_Hz * kH_s, 2) / 3.0;
    EXPECT_NEAR(gain, 1.0, loss * 1.01) << f_Hz;
    EXPECT_NEAR(gain, 1.0 - loss, 1e-5) << f_Hz;
    EXPECT_NEAR(std::atan2(quadrature, in_phase) * 180.0 / std::numbers::pi, -45.0, 0.1) << f_Hz;
  }
}

TEST(Transducer, QuantiserStepsGridAndClipping) {
  const double range = 0.5, step = 2.0 * range / 4096.0;  // 12 bits over +-500 mm/s
  std::vector<double> x = {0.0, 0.1234567, -0.3141592, 0.4999, 0.7, -0.7, step / 3.0};
  const std::vector<double> in = x;
  quantise(x, 12, -range, range);
  EXPECT_EQ(x[0], 0.0);  // mid-tread: zero is a level
  for (std::size_t i = 1; i < 3; ++i) {
    const double k = (x[i] + range) / step;
    EXPECT_EQ(k, std::round(k)) << i;  // on the grid
    EXPECT_LE(std::abs(x[i] - in[i]), step / 2.0) << i;
  }
  EXPECT_EQ(x[3], range - step);  // the top level, as a two's-complement converter's
  EXPECT_EQ(x[4], range - step);
  EXPECT_EQ(x[5], -range);
  EXPECT_EQ(x[6], 0.0);
}

TEST(Transducer, PressureConverterIsGaugeOverItsRangeAndRecordsAbsolute) {
  TransducerParams t;
  t.pressure.bits = 12;
  t.pressure.range_Pa = 1.0e6;  // 0..1 MPa gauge
  const double step = 1.0e6 / 4096.0;
  TimeSeries s = record_of(
      {0.0, 0.0, 0.0, 0.0},
      {kAmbient_Pa, kAmbient_Pa + 0.25e6 + 100.0, kAmbient_Pa - 5000.0, kAmbient_Pa + 2e6},
      {kAmbient_Pa + 1234.0, 0.0, 0.0, 0.0});
  add_measured_channels(s, t, kAmbient_Pa, 1);
  const std::vector<double>& p1 = s.channel("P1_measured").values;
  EXPECT_EQ(s.channel("P1_measured").unit, "Pa");
  EXPECT_EQ(p1[0], kAmbient_Pa);  // zero gauge is a level
  EXPECT_EQ(p1[1], kAmbient_Pa + std::round((0.25e6 + 100.0) / step) * step);
  EXPECT_EQ(p1[2], kAmbient_Pa);  // below ambient: clipped to the range's zero
  EXPECT_EQ(p1[3], kAmbient_Pa + 1.0e6 - step);
  EXPECT_EQ(s.channel("P2_measured").values[0], kAmbient_Pa + 5.0 * step);  // 1234 Pa -> 5 steps
  EXPECT_EQ(s.channel("v_measured").values, s.channel("v").values);  // its own transducer ideal
}

TEST(Transducer, IdealTransducersRecordTheSignalsExactly) {
  TimeSeries s = record_of({0.01, -0.02, 0.3}, {2e5, 2.1e5, 3e5}, {1.5e5, 1.4e5, 1.2e5});
  add_measured_channels(s, TransducerParams{}, kAmbient_Pa, 7);
  for (const char* name : {"v", "P1", "P2"}) {
    EXPECT_EQ(s.channel(std::string(name) + "_measured").values, s.channel(name).values) << name;
  }
}

// 20000 draws: the sample mean's standard error is sd / 141, the sample sd's about
// sd / sqrt(2 n) = sd / 200; 5 of each makes a false failure a one-in-a-million event. The
// lag comes before the noise, so the noise in the record keeps its whole sd.
TEST(Transducer, NoiseHasItsSdAfterTheLagAndIsSeededPerChannel) {
  TransducerParams t;
  t.velocity.noise_m_per_s = 1e-3;
  t.velocity.bandwidth_Hz = 5.0;
  t.pressure.noise_Pa = 500.0;
  const std::size_t n = 20000;
  TimeSeries s = constant_record(n, 0.05, 3e5, 2e5);
  add_measured_channels(s, t, kAmbient_Pa, 3);
  const std::vector<double> dv = difference(s.channel("v_measured").values, s.channel("v").values);
  EXPECT_NEAR(mean_of(dv), 0.0, 5.0 * 1e-3 / 141.0);
  EXPECT_NEAR(sd_of(dv), 1e-3, 5.0 * 1e-3 / 200.0);
  const std::vector<double> d1 =
      difference(s.channel("P1_measured").values, s.channel("P1").values);
  const std::vector<double> d2 =
      difference(s.channel("P2_measured").values, s.channel("P2").values);
  EXPECT_NEAR(sd_of(d1), 500.0, 5.0 * 500.0 / 200.0);
  EXPECT_NEAR(sd_of(d2), 500.0, 5.0 * 500.0 / 200.0);
  // Independent streams: the correlation of P1's and P2's noise is within 5 / sqrt(n) of 0.
  double product = 0.0;
  for (std::size_t i = 0; i < n; ++i) product += d1[i] * d2[i] / (500.0 * 500.0 * n);
  EXPECT_NEAR(product, 0.0, 5.0 / std::sqrt(static_cast<double>(n)));
  TimeSeries again = constant_record(n, 0.05, 3e5, 2e5);
  add_measured_channels(again, t, kAmbient_Pa, 3);
  EXPECT_EQ(again.channel("v_measured").values, s.channel("v_measured").values);
  EXPECT_EQ(again.channel("P2_measured").values, s.channel("P2_measured").values);
  TimeSeries other = constant_record(n, 0.05, 3e5, 2e5);
  add_measured_channels(other, t, kAmbient_Pa, 4);
  EXPECT_NE(other.channel("v_measured").values, s.channel("v_measured").values);
}

// The velocity's noise is the run's velocity stream, added to the sample: the sweep's maps
// with noise draw the numbers sensor_noise() gives for the run's seed.
TEST(Transducer, VelocityNoiseIsTheRunsVelocityStream) {
  TransducerParams t;
  t.velocity.noise_m_per_s = 0.5e-3;
  TimeSeries s = record_of({0.01, 0.02, 0.03, 0.04}, {2e5, 2e5, 2e5, 2e5}, {1e5, 1e5, 1e5, 1e5});
  add_measured_channels(s, t, kAmbient_Pa, 42);
  const std::vector<double> noise = sensor_noise(42, NoiseStream::kVelocity, 4, 0.5e-3);
  for (std::size_t i = 0; i < 4; ++i) {
    EXPECT_EQ(s.channel("v_measured").values[i], s.channel("v").values[i] + noise[i]);
  }
}

TEST(Transducer, BadKeysAreRefusedNamingTheKey) {
  const auto refused = [](std::vector<std::string> sets) {
    return error_of([&] { build_scenario("", sets); });
  };
  EXPECT_NE(refused({"transducer.velocity_bits=12"})
                .find("transducer.velocity_range_mm_per_s = 0: must be > 0 when "
                      "transducer.velocity_bits = 12"),
            std::string::npos);
  EXPECT_NE(refused({"transducer.pressure_bits=12"}).find("transducer.pressure_range_MPa"),
            std::string::npos);
  EXPECT_NE(refused({"transducer.pressure_noise_kPa=-1"})
                .find("transducer.pressure_noise_kPa: -1 kPa is out of range"),
            std::string::npos);
  EXPECT_NE(refused({"transducer.velocity_bits=25"}).find("transducer.velocity_bits: 25"),
            std::string::npos);
  EXPECT_NE(refused({"transducer.velocity_bits=2.5"}).find("expected a whole number"),
            std::string::npos);
  EXPECT_NE(
      refused({"transducer.velocity_bandwidth_Hz=-3"}).find("transducer.velocity_bandwidth_Hz"),
      std::string::npos);
  EXPECT_EQ(refused({"transducer.velocity_bits=12", "transducer.velocity_range_mm_per_s=500"}),
            "(no error)");
}

TEST(Transducer, ScenariosBuiltInCodeAreCheckedToo) {
  const auto refused = [](const std::function<void(Scenario&)>& set) {
    Scenario s = default_scenario();
    set(s);
    return error_of([&] { s.validate(); });
  };
  EXPECT_NE(refused([](Scenario& s) {
              s.transducer.pressure.bits = 30;
            }).find("transducer.pressure_bits = 30: must be between 0 and 24"),
            std::string::npos);
  EXPECT_NE(refused([](Scenario& s) {
              s.transducer.velocity.noise_m_per_s = -1e-3;
            }).find("transducer.velocity_noise_mm_per_s = -1: must be finite and >= 0"),
            std::string::npos);
  EXPECT_NE(refused([](Scenario& s) {
              s.transducer.pressure.range_Pa = NAN;
            }).find("transducer.pressure_range_MPa"),
            std::string::npos);
  EXPECT_TRUE(default_scenario().transducer.ideal());
}

}  // namespace
}  // namespace pneumachaos
