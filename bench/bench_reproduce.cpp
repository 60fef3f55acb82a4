// The whole `reproduce --quick` in process (sweeps, figures, claims, report), on all cores.
// The sweeps are removed before each iteration so none is resumed. Compare with the same
// command of the previous build, or with `pneumachaos reproduce --quick` timed
// (docs/notes/performance.md).
// Run: cmake --preset bench && cmake --build --preset bench && ./build/bench/bench_reproduce
#include <benchmark/benchmark.h>

#include <filesystem>

#include "pneumachaos/report/reproduce.hpp"

namespace {

using namespace pneumachaos;

void BM_ReproduceQuick(benchmark::State& state) {
  const auto dir = std::filesystem::temp_directory_path() / "pneumachaos_bench_reproduce";
  for (auto _ : state) {
    state.PauseTiming();
    std::filesystem::remove_all(dir);
    state.ResumeTiming();
    ReproduceOptions o;
    o.out_dir = dir.string();
    o.quick = true;
    o.progress = false;
    benchmark::DoNotOptimize(reproduce(o).claims.size());
  }
  std::filesystem::remove_all(dir);
}

BENCHMARK(BM_ReproduceQuick)->Iterations(1)->Unit(benchmark::kSecond)->UseRealTime();

}  // namespace

BENCHMARK_MAIN();
