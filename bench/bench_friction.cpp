// Time of `friction`'s work on a 6,000-sample record (6 s at 1 kHz, a stick-slip record of
// the simple rig degraded like a rig's A/D): the estimate alone, and the estimate with all
// four fits (classic, stribeck, stribeck_delta, lugre). The goal: under 0.5 s.
// Run: cmake --preset bench && cmake --build --preset bench && ./build/bench/bench_friction
#include <benchmark/benchmark.h>

#include <cmath>
#include <random>

#include "pneumachaos/identify/friction_estimate.hpp"
#include "pneumachaos/identify/friction_fits.hpp"
#include "pneumachaos/model/plant.hpp"
#include "pneumachaos/simulate/simulate.hpp"

namespace {

using namespace pneumachaos;
using namespace pneumachaos::identify;

Scenario rig() {
  Scenario s = simple_rig_scenario();
  s.circuit.S2_m2 = 0.2e-6;
  s.cylinder.frozen_position_m = 0.42;
  return s;
}

const MeasuredRecord& record() {
  static const MeasuredRecord r = [] {
    const Scenario s = rig();
    RunParams o = s.run;
    o.duration_s = 5.999;  // 6,000 samples
    const SimulationResult sim = simulate(Plant(s), o);
    std::mt19937 rng(7);
    std::normal_distribution<double> unit(0.0, 1.0);
    const auto q = [](double v, double step) { return step * std::round(v / step); };
    MeasuredRecord m;
    for (std::size_t k = 0; k < sim.series.size(); ++k) {
      m.t_s.push_back(sim.series.time_s(k));
      m.v_m_per_s.push_back(q(sim.series.channel("v").values[k] + 0.5e-3 * unit(rng), 1.0 / 4096));
      m.p1_Pa.push_back(q(sim.series.channel("P1").values[k] + 300.0 * unit(rng), 1e6 / 4096));
      m.p2_Pa.push_back(q(sim.series.channel("P2").values[k] + 300.0 * unit(rng), 1e6 / 4096));
    }
    return m;
  }();
  return r;
}

void BM_FrictionEstimate(benchmark::State& state) {
  const auto& r = record();
  const auto settings = estimate_spec_from(rig());
  for (auto _ : state) benchmark::DoNotOptimize(estimate_friction(r, settings).sticks.size());
  state.counters["samples"] = double(r.size());
}

void BM_FrictionAllFits(benchmark::State& state) {
  const auto& r = record();
  const Scenario s = rig();
  const auto settings = estimate_spec_from(s);
  FrictionFitOptions o;
  o.start = s.friction;
  o.fixed_exponent = s.friction.curve.stribeck_exponent;
  for (auto _ : state) {
    const auto e = estimate_friction(r, settings);
    benchmark::DoNotOptimize(fit_friction(e, o).preferred_model);
  }
  state.counters["samples"] = double(r.size());
}

}  // namespace

BENCHMARK(BM_FrictionEstimate)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_FrictionAllFits)->Unit(benchmark::kMillisecond);
BENCHMARK_MAIN();
