#include "identify/fit_synthetic.hpp"

#include <algorithm>
#include <cmath>
#include <random>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/simulate/simulate.hpp"

namespace pneumachaos::identify {
namespace {

double quantise(double value, double lo, double hi, int bits) {
  if (bits <= 0) return value;
  const double levels = std::ldexp(1.0, bits) - 1.0;
  const double lsb = (hi - lo) / levels;
  const double code = std::clamp(std::round((value - lo) / lsb), 0.0, levels);
  return lo + code * lsb;
}

}  // namespace

MeasuredRecord synthetic_record(const Scenario& scenario, double duration_s,
                                const RigDegradation& rig, std::uint64_t seed,
                                double sample_rate_Hz) {
  const Plant plant(scenario);
  RunParams so = scenario.run;
  so.duration_s = duration_s;
  so.sample_rate_Hz = sample_rate_Hz;
  const SimulationResult sim = simulate(plant, so);
  if (!sim.summary.ok()) throw RunError("synthetic record", describe(sim.summary));
  const TimeSeries& ts = sim.series;
  const auto& x = ts.channel("x").values;
  const auto& v = ts.channel("v").values;
  const auto& p1 = ts.channel("P1").values;
  const auto& p2 = ts.channel("P2").values;
  std::mt19937_64 rng(seed);
  std::normal_distribution<double> unit(0.0, 1.0);
  MeasuredRecord r;
  r.source = "synthetic";
  const double pf = rig.pressure_full_scale_Pa, vf = rig.velocity_full_scale_m_per_s;
  const double stroke = scenario.cylinder.stroke_m;
  std::vector<double> xs;
  for (std::size_t k = 0; k < ts.size(); ++k) {
    r.t_s.push_back(ts.time_s(k));
    r.p1_Pa.push_back(quantise(p1[k] + rig.pressure_noise_Pa * unit(rng), 0.0, pf, rig.adc_bits));
    r.p2_Pa.push_back(quantise(p2[k] + rig.pressure_noise_Pa * unit(rng), 0.0, pf, rig.adc_bits));
    r.v_m_per_s.push_back(
        quantise(v[k] + rig.velocity_noise_m_per_s * unit(rng), -vf, vf, rig.adc_bits));
    xs.push_back(quantise(x[k], 0.0, stroke, rig.adc_bits));
  }
  if (rig.keep_position) r.x_m = std::move(xs);
  return r;
}

}  // namespace pneumachaos::identify
