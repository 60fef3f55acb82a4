// Time of the stability map over the paper's full S1 x S2 grid (780 points).
// Run: cmake --preset bench && cmake --build --preset bench && ./build/bench/bench_stability
#include <benchmark/benchmark.h>

#include "pneumachaos/stability/stability_map.hpp"

namespace {

using namespace pneumachaos;

void BM_PaperGridMap(benchmark::State& state) {
  Scenario s = default_scenario();
  if (state.range(0) == 1) s.friction.kind = FrictionKind::kLuGre;
  const auto axes = paper_valve_grid();
  for (auto _ : state) {
    const StabilityMap map = stability_map(s, axes);
    benchmark::DoNotOptimize(map.agreeing);
  }
  state.counters["points_per_s"] = benchmark::Counter(
      static_cast<double>(grid_size(axes)) * state.iterations(), benchmark::Counter::kIsRate);
}

void BM_SinglePoint(benchmark::State& state) {
  const Plant plant(default_scenario());
  for (auto _ : state) benchmark::DoNotOptimize(analyze_stability(plant).max_real_part_per_s);
}

BENCHMARK(BM_PaperGridMap)->Arg(0)->Arg(1)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_SinglePoint)->Unit(benchmark::kMicrosecond);

}  // namespace

BENCHMARK_MAIN();
