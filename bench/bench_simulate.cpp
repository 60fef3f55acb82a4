// Simulated seconds per wall second for a 10 s run at 1 kHz output on one core: the simple
// rig (one rigid mass, Stribeck seal) sliding and in stick-slip, LuGre on both steppers, and
// the default two-mass virtual rig, plain and as a sweep runs it (textured bore). Each prints
// its right-hand-side evaluations and steps per run; StepControl compares the step-size
// controllers in one process (docs/notes/performance.md, "Step-size control"), QuasiStatic
// LuGre's full bristle equation with its quasi-static limit ("Simulation (third round)"),
// GmsQuasiStatic the GMS seal's limit ("Simulation (fourth round: the GMS seal)").
// Run: cmake --preset bench && cmake --build --preset bench && ./build/bench/bench_simulate
#include <benchmark/benchmark.h>

#include "pneumachaos/model/variation.hpp"
#include "pneumachaos/simulate/simulate.hpp"

namespace {

using namespace pneumachaos;

// The work of one run: right-hand-side evaluations and steps (each the same in every run).
void count_work(benchmark::State& state, const IntegrationSummary& s) {
  state.counters["rhs_per_run"] = static_cast<double>(s.rhs_evaluations);
  state.counters["steps_per_run"] = static_cast<double>(s.steps_accepted);
  state.counters["rejected_per_run"] = static_cast<double>(s.steps_rejected);
}

void run(benchmark::State& state, Scenario s) {
  s.run.duration_s = 10.0;
  s.cylinder.stroke_m = 2.0;  // long enough that the full 10 s are simulated
  const Plant plant(s);
  const auto options = s.run;
  double simulated = 0.0;
  std::size_t events = 0;
  IntegrationSummary last;
  for (auto _ : state) {
    const auto r = simulate(plant, options);
    benchmark::DoNotOptimize(r.series.size());
    simulated += r.summary.t_final_s;
    events = r.summary.event_log.size();
    last = r.summary;
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  state.counters["events_per_run"] = static_cast<double>(events);
  count_work(state, last);
}

// A 10 s run of the scenario as it stands (its own stroke and volumes), for the virtual rig.
void run_rig(benchmark::State& state, Scenario s) {
  s.run.duration_s = 10.0;
  const Plant plant(s);
  const auto options = s.run;
  double simulated = 0.0;
  IntegrationSummary last;
  for (auto _ : state) {
    const auto r = simulate(plant, options);
    benchmark::DoNotOptimize(r.series.size());
    simulated += r.summary.t_final_s;
    last = r.summary;
  }
  state.counters["sim_s_per_wall_s"] = benchmark::Counter(simulated, benchmark::Counter::kIsRate);
  count_work(state, last);
}

void BM_Sliding(benchmark::State& state) { run(state, simple_rig_scenario()); }

void BM_StickSlip(benchmark::State& state) {
  Scenario s = simple_rig_scenario();
  s.circuit.S2_m2 = 0.05e-6;
  run(state, s);
}

void BM_SlidingLuGre(benchmark::State& state) {
  Scenario s = simple_rig_scenario();
  s.friction.kind = FrictionKind::kLuGre;
  run(state, s);
}

void BM_SlidingLuGreRosenbrock(benchmark::State& state) {
  Scenario s = simple_rig_scenario();
  s.friction.kind = FrictionKind::kLuGre;
  s.run.stepper = StepperKind::kRosenbrock4;
  run(state, s);
}

// The default scenario: the two-mass virtual rig in chaotic oscillation, volumes frozen.
void BM_VirtualRigChaotic(benchmark::State& state) { run_rig(state, default_scenario()); }

// A run of a sweep of the default map: the map's seal variation gives both contacts a
// four-mode texture along the bore (docs/sweep.md), whose sines the friction laws evaluate.
void BM_VirtualRigTextured(benchmark::State& state) {
  Scenario base = default_scenario();
  base.variation.friction_rel_sd = 0.03;
  base.variation.texture_rel = 0.02;
  run_rig(state, vary(base, run_seed(1, 0, 0)));
}

// The default rig at the map's largest S2 (4.4 mm^2), sliding at ~0.8 m/s: the step is bound
// by the stability of the guide's bristles (rate sigma0 |v| / g ~ 1.2e4 1/s), not by the
// tolerance, and such points cost the most RHS evaluations of a sweep (docs/notes/performance.md).
void BM_VirtualRigFastSliding(benchmark::State& state) {
  Scenario s = default_scenario();
  s.circuit.S2_m2 = 4.4e-6;
  run_rig(state, s);
}

// LuGre's quasi-static limit (docs/model.md, "Friction") off (first argument 0: the full
// bristle equation throughout, as before it) and on (1, the default) in one process, at the
// sliding points S2 = 2.0 and 4.4 mm^2 (second argument in 0.01 mm^2) of the map.
void BM_VirtualRigQuasiStatic(benchmark::State& state) {
  Scenario s = default_scenario();
  s.circuit.S2_m2 = static_cast<double>(state.range(1)) * 1e-8;
  if (state.range(0) == 0) {
    s.friction.lugre.quasi_static_rate_per_s = 0.0;
    s.load.guide_friction.lugre.quasi_static_rate_per_s = 0.0;
  }
  state.SetLabel(state.range(0) == 0 ? "full bristle equation" : "quasi-static limit (default)");
  run_rig(state, s);
}

// The GMS seal's quasi-static limit (docs/model.md, "Friction"; off by default) off (first
// argument 0, the full law as the default runs it) and at a threshold of the second argument
// in 1/s, in one process; third argument S2 in 0.01 mm^2: the fast-sliding points 3.0 and
// 4.4 mm^2, where it is accurate, and the chaotic default 0.35 mm^2, where it is not
// (docs/notes/performance.md, "The GMS seal's quasi-static limit").
void BM_VirtualRigGmsQuasiStatic(benchmark::State& state) {
  Scenario s = default_scenario();
  s.circuit.S2_m2 = static_cast<double>(state.range(2)) * 1e-8;
  s.friction.gms.quasi_static_rate_per_s =
      state.range(0) == 0 ? 0.0 : static_cast<double>(state.range(1));
  state.SetLabel(state.range(0) == 0 ? "full law (default)" : "GMS limit (option)");
  run_rig(state, s);
}

// The default rig integrated without output, with the default step-size controller
// (Boost.Odeint's, first argument 0) and Hairer's PI controller (1, tried and not adopted:
// docs/notes/performance.md), in one process; second argument S2 in 0.01 mm^2 (the chaotic
// default and the stiff fast-sliding point).
void BM_VirtualRigStepControl(benchmark::State& state) {
  Scenario s = default_scenario();
  s.circuit.S2_m2 = static_cast<double>(state.range(1)) * 1e-8;
  s.run.duration_s = 10.0;
  const Plant plant(s);
  IntegratorOptions io = integrator_options(s.run);
  io.sample_rate_Hz = 0.0;
  io.record_events = false;
  const bool previous = state.range(0) == 0;  // the default
  io.step_control = previous ? StepControl::kOdeint : StepControl::kPI;
  IntegrationSummary last;
  for (auto _ : state) {
    std::vector<double> x = plant.initial_state();
    Mode mode = plant.initial_mode(x, 0.0);
    last = integrate_hybrid(plant, x, mode, io, {});
    benchmark::DoNotOptimize(x.data());
  }
  state.SetLabel(previous ? "odeint controller (default)" : "PI controller (option)");
  count_work(state, last);
}

BENCHMARK(BM_Sliding)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VirtualRigChaotic)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VirtualRigTextured)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VirtualRigFastSliding)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VirtualRigQuasiStatic)
    ->ArgsProduct({{0, 1}, {200, 440}})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VirtualRigGmsQuasiStatic)
    ->Args({0, 0, 300})
    ->Args({1, 8000, 300})
    ->Args({0, 0, 440})
    ->Args({1, 8000, 440})
    ->Args({0, 0, 35})
    ->Args({1, 8000, 35})
    ->Args({1, 16000, 35})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_VirtualRigStepControl)
    ->Args({0, 35})
    ->Args({1, 35})
    ->Args({0, 440})
    ->Args({1, 440})
    ->Unit(benchmark::kMillisecond);
BENCHMARK(BM_StickSlip)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SlidingLuGre)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SlidingLuGreRosenbrock)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
