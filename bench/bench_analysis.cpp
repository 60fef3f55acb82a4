// Time of the whole analysis and of each Lyapunov estimator on 1e4 and 1e5 samples of the
// Lorenz x coordinate (dt = 0.01); the ratio between the sizes shows the growth (N log N
// would be ~11.5x for 10x the points). The previous build's figures: bench/compare_builds.sh
// or this program built from the previous commit, run alternately (docs/notes/performance.md).
// Run: cmake --preset bench && cmake --build --preset bench && ./build/bench/bench_analysis
#include <benchmark/benchmark.h>

#include <fmt/format.h>

#include <cmath>
#include <filesystem>
#include <fstream>
#include <map>
#include <random>

#include "../tests/support/reference_series.hpp"
#include "pneumachaos/analysis/analyze.hpp"
#include "analysis/log_array.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/csv_reader.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace {

using namespace pneumachaos;

const std::vector<double>& lorenz(std::size_t n) {
  static std::map<std::size_t, std::vector<double>> cache;
  auto it = cache.find(n);
  if (it == cache.end()) it = cache.emplace(n, testing::lorenz_x(n)).first;
  return it->second;
}

void BM_AnalyzeAll(benchmark::State& state) {
  const auto& x = lorenz(static_cast<std::size_t>(state.range(0)));
  for (auto _ : state) benchmark::DoNotOptimize(analyze_series(x, 100.0).verdict.chaotic);
}

// The whole analysis with the surrogate test on (39 IAAFT surrogates, `analyze`'s default).
void BM_AnalyzeWithSurrogates(benchmark::State& state) {
  const auto& x = lorenz(static_cast<std::size_t>(state.range(0)));
  AnalysisOptions o;
  o.surrogates.count = 39;
  for (auto _ : state) benchmark::DoNotOptimize(analyze_series(x, 100.0, o).verdict.chaotic);
}

// The records of a textured sweep of the default rig (30 points: S1 2.45..3.70 mm^2 x S2
// 0.05..0.65 mm^2, the map's seal variation and bore texture): stick-slip, periodic and
// chaotic records and short ones ending at the stroke end, simulated once. Each is analysed
// as the sweep analyses it (judge_run: no Wolf, no surrogates); the figure is for all 30.
const std::vector<SweepRun>& sweep_records() {
  static const std::vector<SweepRun> runs = [] {
    SweepSpec spec;
    spec.base = default_scenario();
    spec.base.variation.friction_rel_sd = 0.03;
    spec.base.variation.texture_rel = 0.02;
    spec.axes = {parse_grid_axis("circuit.S1_mm2=2.45:3.70:0.25"),
                 parse_grid_axis("circuit.S2_mm2=0.05:0.65:0.15")};
    spec.repeats = 1;
    std::vector<SweepRun> out;
    for (std::size_t p = 0; p < spec.points(); ++p) out.push_back(simulate_run(spec, p, 0));
    return out;
  }();
  return runs;
}

void BM_AnalyzeSweepRecords(benchmark::State& state) {
  const std::vector<SweepRun>& runs = sweep_records();
  AnalysisOptions o;
  o.wolf = false;
  for (auto _ : state) {
    for (const SweepRun& run : runs) {
      if (!run.sim.summary.ok()) continue;
      try {
        benchmark::DoNotOptimize(
            analyze_series(run.measured_v, run.sim.series.rate_Hz(), o).verdict.chaotic);
      } catch (const Error&) {
        // too short to judge, as judge_run catches it
      }
    }
  }
}

// Reading a record as `analyze` does (read_csv_series): 1e4 samples of Lorenz x written as
// bench/write_series writes them (t with 6 decimals, x with 17 digits), from a file.
void BM_ReadCsv(benchmark::State& state) {
  const auto& x = lorenz(static_cast<std::size_t>(state.range(0)));
  const auto path = std::filesystem::temp_directory_path() / "pneumachaos_bench_read.csv";
  {
    std::ofstream out(path);
    out << "t,v\n";
    for (std::size_t i = 0; i < x.size(); ++i) {
      out << fmt::format("{:.6f},{:.17g}\n", 0.01 * static_cast<double>(i), x[i]);
    }
  }
  for (auto _ : state) {
    benchmark::DoNotOptimize(read_csv_series(path.string(), {}).size());
  }
  std::filesystem::remove(path);
}

// The estimators alone, on the embedding the analysis chooses for this record.
DivergenceOptions embedding_of(const std::vector<double>& x) {
  AnalysisOptions o;
  o.wolf = false;
  const AnalysisResult r = analyze_series(x, 100.0, o);
  DivergenceOptions d;
  d.dimension = r.dimension.dimension;
  d.delay = r.delay.delay;
  d.theiler = r.theiler;
  return d;
}

void BM_Divergence(benchmark::State& state) {
  const auto& x = lorenz(static_cast<std::size_t>(state.range(0)));
  const DivergenceOptions d = embedding_of(x);
  for (auto _ : state) benchmark::DoNotOptimize(divergence_exponent(x, 100.0, d).lambda_per_s);
}

void BM_Wolf(benchmark::State& state) {
  const auto& x = lorenz(static_cast<std::size_t>(state.range(0)));
  const DivergenceOptions d = embedding_of(x);
  WolfOptions w;
  w.dimension = d.dimension;
  w.delay = d.delay;
  w.theiler = d.theiler;
  for (auto _ : state) benchmark::DoNotOptimize(wolf_exponent(x, 100.0, w).lambda_per_s);
}

// Wolf's program on 1e5 samples of white noise, called directly (the analysis does not run
// it on records without deterministic structure), on the embedding the analysis chooses.
void BM_WolfWhiteNoise(benchmark::State& state) {
  const auto x = testing::white_noise(static_cast<std::size_t>(state.range(0)));
  const DivergenceOptions d = embedding_of(x);
  WolfOptions w;
  w.dimension = d.dimension;
  w.delay = d.delay;
  w.theiler = d.theiler;
  for (auto _ : state) benchmark::DoNotOptimize(wolf_exponent(x, 100.0, w).lambda_per_s);
}

// The local-Jacobian estimator (`analyze --jacobian-exponents`): on Lorenz at the analysis's
// embedding, and on white noise, where every sample is a map (delay 1) in a high dimension.
JacobianOptions jacobian_of(const DivergenceOptions& d) {
  JacobianOptions j;
  j.dimension = d.dimension;
  j.delay = d.delay;
  j.theiler = d.theiler;
  return j;
}

void BM_Jacobian(benchmark::State& state) {
  const auto& x = lorenz(static_cast<std::size_t>(state.range(0)));
  const JacobianOptions j = jacobian_of(embedding_of(x));
  for (auto _ : state) benchmark::DoNotOptimize(jacobian_exponents(x, 100.0, j).lambda_per_s);
}

void BM_JacobianWhiteNoise(benchmark::State& state) {
  const auto x = testing::white_noise(static_cast<std::size_t>(state.range(0)));
  const JacobianOptions j = jacobian_of(embedding_of(x));
  for (auto _ : state) benchmark::DoNotOptimize(jacobian_exponents(x, 100.0, j).lambda_per_s);
}

// The divergence curve's logarithms: one step's 729 squared distances (a 1e4 record's
// horizon), the C library's log one by one (what the curve called before) against log_array.
std::vector<double> squared_distances() {
  std::mt19937_64 rng(3);
  std::uniform_real_distribution<double> exponent(-12.0, 4.0);
  std::vector<double> d2(729);
  for (double& v : d2) v = std::exp(exponent(rng));
  return d2;
}

void BM_LogLibrary(benchmark::State& state) {
  const std::vector<double> d2 = squared_distances();
  std::vector<double> out(d2.size());
  for (auto _ : state) {
    for (std::size_t k = 0; k < d2.size(); ++k) out[k] = std::log(d2[k]);
    benchmark::DoNotOptimize(out.data());
  }
}

void BM_LogArray(benchmark::State& state) {
  const std::vector<double> d2 = squared_distances();
  std::vector<double> out(d2.size());
  for (auto _ : state) {
    log_array(d2, out);
    benchmark::DoNotOptimize(out.data());
  }
}

BENCHMARK(BM_AnalyzeAll)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_ReadCsv)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AnalyzeSweepRecords)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_AnalyzeWithSurrogates)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Divergence)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Wolf)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_Jacobian)->Arg(10000)->Arg(100000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_JacobianWhiteNoise)->Arg(10000)->Unit(benchmark::kMillisecond);
BENCHMARK(BM_LogLibrary);
BENCHMARK(BM_LogArray);
BENCHMARK(BM_WolfWhiteNoise)->Arg(100000)->Iterations(1)->Unit(benchmark::kMillisecond);

}  // namespace

BENCHMARK_MAIN();
