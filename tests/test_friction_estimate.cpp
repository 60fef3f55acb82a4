// Friction from a record (docs/friction.md): the Savitzky-Golay differentiator, stick
// detection, and the validation of issue 13: records from our own simulator with known
// friction, degraded as a rig's A/D degrades them, must give back Fs, Fc within 5 %, B within
// 10 %, vs within 30 %.

#include <gtest/gtest.h>

#include <chrono>
#include <cmath>
#include <random>

#include "pneumachaos/identify/friction_estimate.hpp"
#include "pneumachaos/identify/friction_fits.hpp"
#include "pneumachaos/identify/friction_output.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/simulate/simulate.hpp"

using namespace pneumachaos;
using namespace pneumachaos::identify;

namespace {

// The rig's A/D: transducer noise, 12-bit quantisation of 0..1 MPa absolute and of +-0.5 m/s.
struct Degradation {
  double pressure_sd_Pa = 300.0;
  double velocity_sd_m_per_s = 0.5e-3;
  int bits = 12;
  double pressure_range_Pa = 1.0e6;
  double velocity_range_m_per_s = 1.0;  // -0.5 .. 0.5 m/s
  unsigned seed = 7;
};

double quantise(double v, double step) { return step * std::round(v / step); }

MeasuredRecord degraded_record(const Scenario& s, double duration_s, const Degradation& d) {
  SimulationOptions o = SimulationOptions::from(s.run);
  o.duration_s = duration_s;
  const Plant plant(s);
  const SimulationResult sim = simulate(plant, o);
  const TimeSeries& ts = sim.series;
  std::mt19937 rng(d.seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  const double levels = std::pow(2.0, d.bits);
  const double p_step = d.pressure_range_Pa / levels, v_step = d.velocity_range_m_per_s / levels;
  MeasuredRecord r;
  r.source = "synthetic";
  for (std::size_t k = 0; k < ts.size(); ++k) {
    r.t_s.push_back(ts.time_s(k));
    r.v_m_per_s.push_back(quantise(ts.channel("v").values[k] + d.velocity_sd_m_per_s * unit(rng), v_step));
    r.p1_Pa.push_back(quantise(ts.channel("P1").values[k] + d.pressure_sd_Pa * unit(rng), p_step));
    r.p2_Pa.push_back(quantise(ts.channel("P2").values[k] + d.pressure_sd_Pa * unit(rng), p_step));
  }
  return r;
}

Scenario rig(FrictionKind kind, double S2_mm2) {
  Scenario s = simple_rig_scenario();
  s.friction.kind = kind;
  s.friction.coulomb_N = 20.0;
  s.friction.static_N = 40.0;
  s.friction.viscous_Ns_per_m = 30.0;
  s.friction.stribeck_velocity_m_per_s = 0.01;
  s.friction.stribeck_exponent = 2.0;
  s.circuit.S2_m2 = S2_mm2 * 1e-6;
  return s;
}

struct Recovered {
  FrictionEstimate estimate;
  FrictionFits fits;
};

Recovered recover(const Scenario& s, const MeasuredRecord& r, std::vector<FrictionFitModel> models) {
  FrictionFitOptions o;
  o.models = std::move(models);
  o.fixed_exponent = s.friction.stribeck_exponent;
  o.start = s.friction;
  Recovered out{estimate_friction(r, estimate_settings_from(s)), {}};
  out.fits = fit_friction(out.estimate, o);
  return out;
}

double rel(double got, double want) { return std::abs(got - want) / std::abs(want); }

}  // namespace

TEST(SavitzkyGolay, ExactOnQuadraticsAndWindowGrowsWithNoise) {
  std::vector<double> y(200);
  for (std::size_t i = 0; i < y.size(); ++i) {
    const double t = i * 1e-3;
    y[i] = 0.5 * t * t - 0.1 * t;
  }
  const auto d = savitzky_golay_derivative(y, 1e-3, 7);
  for (std::size_t i = 7; i + 7 < y.size(); ++i) EXPECT_NEAR(d[i], i * 1e-3 - 0.1, 1e-9);
  const std::size_t quiet = choose_sg_half_width(1e-6, 10.0, 1e-3);
  const std::size_t noisy = choose_sg_half_width(1e-3, 10.0, 1e-3);
  EXPECT_LT(quiet, noisy);
  EXPECT_GE(quiet, 2u);
  EXPECT_LE(noisy, 100u);
}

TEST(SavitzkyGolay, NoiseEstimateFromSecondDifferences) {
  std::mt19937 rng(3);
  std::normal_distribution<double> n(0.0, 2e-3);
  std::vector<double> y(5000);
  for (std::size_t i = 0; i < y.size(); ++i) y[i] = std::sin(i * 1e-3) + n(rng);
  EXPECT_NEAR(noise_sd(y), 2e-3, 2e-4);
}

TEST(FrictionEstimate, StickIntervalsAndForceOfAKnownRecord) {
  // A synthetic record by hand: rest for 0.2 s with the drive rising to 40 N, then sliding at
  // 20 mm/s against 25 N.
  MeasuredRecord r;
  EstimateSettings s;
  s.area_head_m2 = 1e-3;
  s.area_rod_m2 = 8e-4;
  s.mass_kg = 1.0;
  for (int i = 0; i < 1000; ++i) {
    const double t = i * 1e-3;
    const double force = i < 200 ? 40.0 * t / 0.2 : 25.0;
    r.t_s.push_back(t);
    r.v_m_per_s.push_back(i < 200 ? 0.0 : 0.02);
    r.p1_Pa.push_back(s.ambient_Pa + 2e5 + force / s.area_head_m2);
    r.p2_Pa.push_back(s.ambient_Pa + 2e5 * s.area_head_m2 / s.area_rod_m2);
  }
  const auto e = estimate_friction(r, s);
  ASSERT_EQ(e.sticks.size(), 1u);
  EXPECT_EQ(e.sticks[0].direction, 1);
  EXPECT_NEAR(e.sticks[0].breakaway_N, 40.0, 1.0);
  EXPECT_NEAR(e.F_N[600], 25.0, 1e-6);
  ASSERT_EQ(e.excursions.size(), 1u);
  EXPECT_TRUE(e.excursions[0].from_stick);
}
