// `fit` with four free parameters (S1, S2, Fc, Fs) on one core, from start values 20-25 %
// off, on 6 s records of the rigid single-mass rig degraded like an A/D rig (docs/notes/model_fit.md):
// sliding and stick-slip. Goal: under 30 s each.
// Run: cmake --preset bench && cmake --build --preset bench && ./build/bench/bench_fit
#include <benchmark/benchmark.h>

#include "pneumachaos/identify/fit.hpp"
#include "identify/fit_synthetic.hpp"
#include "pneumachaos/model/scenario_keys.hpp"

namespace {

using namespace pneumachaos;
using namespace pneumachaos::identify;

void run(benchmark::State& state, double S2_mm2) {
  Scenario truth = simple_rig_scenario();
  apply_setting(truth, "circuit.S2_mm2", S2_mm2, "bench");
  const MeasuredRecord record = synthetic_record(truth, 6.0, RigDegradation{}, 7);
  Scenario start = truth;
  apply_setting(start, "circuit.S1_mm2", 1.25 * 2.70, "bench");
  apply_setting(start, "circuit.S2_mm2", 0.78 * S2_mm2, "bench");
  apply_setting(start, "friction.Fc_N", 1.2 * truth.friction.curve.coulomb_N, "bench");
  apply_setting(start, "friction.Fs_N", 0.9 * truth.friction.curve.static_N, "bench");
  const auto keys = default_free_keys(start);
  double s1 = 0, s2 = 0;
  int iterations = 0;
  for (auto _ : state) {
    const FitResult r = fit_model(record, start, keys);
    s1 = r.parameters[0].value / 2.70 - 1.0;
    s2 = r.parameters[1].value / S2_mm2 - 1.0;
    iterations = r.iterations;
  }
  state.counters["S1_rel_error"] = s1;
  state.counters["S2_rel_error"] = s2;
  state.counters["ceres_iterations"] = iterations;
}

void BM_FitSliding(benchmark::State& state) { run(state, 0.35); }
void BM_FitStickSlip(benchmark::State& state) { run(state, 0.05); }

}  // namespace

BENCHMARK(BM_FitSliding)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK(BM_FitStickSlip)->Unit(benchmark::kSecond)->Iterations(1);
BENCHMARK_MAIN();
