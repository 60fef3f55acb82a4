// Sweep throughput on 1 and 2 threads (parallel efficiency) over 60 runs spread across the
// paper's S2 range, and the full paper map (780 points x 5 repeats).
// Run: cmake --preset bench && cmake --build --preset bench && ./build/bench/bench_sweep
#include <benchmark/benchmark.h>

#include <filesystem>

#include "pneumachaos/sweep/sweep_runner.hpp"

namespace {

using namespace pneumachaos;

void sweep_into(const SweepSpec& spec, std::size_t threads, benchmark::State& state) {
  const auto dir = std::filesystem::temp_directory_path() / "pneumachaos_bench_sweep";
  for (auto _ : state) {
    state.PauseTiming();
    std::filesystem::remove_all(dir);
    state.ResumeTiming();
    SweepOptions o;
    o.out_dir = dir.string();
    o.threads = threads;
    o.progress = false;
    benchmark::DoNotOptimize(run_sweep(spec, o).runs);
  }
  std::filesystem::remove_all(dir);
  state.counters["runs_per_s"] = benchmark::Counter(
      static_cast<double>(spec.runs()) * state.iterations(), benchmark::Counter::kIsRate);
}

void BM_SweepThreads(benchmark::State& state) {
  SweepSpec spec;
  spec.base = default_scenario();
  spec.axes = {parse_grid_axis("circuit.S1_mm2=2.7:2.7:1"),
               parse_grid_axis("circuit.S2_mm2=0.05:4.40:0.15")};
  spec.repeats = 2;
  sweep_into(spec, static_cast<std::size_t>(state.range(0)), state);
}

// The same 60 runs with the map's seal variation (friction levels and a four-mode texture
// along the bore, docs/sweep.md), as the paper maps are swept; one thread.
void BM_SweepTextured(benchmark::State& state) {
  SweepSpec spec;
  spec.base = default_scenario();
  spec.base.variation.friction_rel_sd = 0.03;
  spec.base.variation.texture_rel = 0.02;
  spec.axes = {parse_grid_axis("circuit.S1_mm2=2.7:2.7:1"),
               parse_grid_axis("circuit.S2_mm2=0.05:4.40:0.15")};
  spec.repeats = 2;
  sweep_into(spec, 1, state);
}

void BM_FullPaperMap(benchmark::State& state) {
  SweepSpec spec;
  spec.base = default_scenario();
  spec.axes = paper_valve_grid();
  spec.repeats = 5;
  sweep_into(spec, 0, state);
}

BENCHMARK(BM_SweepThreads)->Arg(1)->Arg(2)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_SweepTextured)->Unit(benchmark::kMillisecond)->UseRealTime();
BENCHMARK(BM_FullPaperMap)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
