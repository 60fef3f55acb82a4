// Adaptive maps against the full grid, in one process: for each validation map
// (tests/support/adaptive_cases.hpp) the full sweep and the adaptive one, their agreement, the runs
// saved and the wall-time ratio. Not a timed test: the numbers of docs/sweep.md.
//
//   bench_adaptive [--step N] [--threads N] [NAME-PREFIX...]    (default: every map)

#include <fmt/format.h>
#include <unistd.h>

#include <cstdlib>
#include <filesystem>
#include <string>
#include <vector>

#include "adaptive_cases.hpp"
#include "sweep/map_agreement.hpp"

int main(int argc, char** argv) {
  using namespace pneumachaos;
  std::size_t step = AdaptiveSpec{}.coarse_step, threads = 0;
  std::vector<std::string> wanted;
  for (int i = 1; i < argc; ++i) {
    const std::string a = argv[i];
    if ((a == "--step" || a == "--threads") && i + 1 < argc) {
      (a == "--step" ? step : threads) = std::strtoul(argv[++i], nullptr, 10);
    } else {
      wanted.push_back(a);
    }
  }
  const auto dir = std::filesystem::temp_directory_path() /
                   fmt::format("pneumachaos_bench_adaptive_{}", ::getpid());
  double full_s = 0.0, adaptive_s = 0.0;
  std::size_t full_runs = 0, adaptive_runs = 0;
  for (AdaptiveCase& c : adaptive_cases(PNEUMACHAOS_VARIANTS_DIR)) {
    bool take = wanted.empty();
    for (const auto& w : wanted) take = take || c.name.rfind(w, 0) == 0;
    if (!take) continue;
    c.spec.adaptive.coarse_step = step;
    SweepOptions o;
    o.progress = false;
    o.threads = threads;
    o.out_dir = dir.string();
    const AdaptiveValidation v = validate_adaptive(c.spec, o);
    std::filesystem::remove_all(dir);
    const MapAgreement& m = v.agreement;
    fmt::print(
        "{} (coarse step {}): {}; wall {:.1f} s full, {:.1f} s adaptive ({:.2f}x); "
        "areas within borders: {}\n",
        c.name, step, m.describe(), v.full_wall_s, v.adaptive_wall_s,
        v.full_wall_s / v.adaptive_wall_s, m.areas_within_borders() ? "yes" : "NO");
    std::fflush(stdout);
    full_s += v.full_wall_s;
    adaptive_s += v.adaptive_wall_s;
    full_runs += m.full_runs;
    adaptive_runs += m.adaptive_runs;
  }
  if (adaptive_runs > 0) {
    fmt::print("all: {} of {} runs ({:.2f}x fewer); wall {:.1f} of {:.1f} s ({:.2f}x)\n",
               adaptive_runs, full_runs, static_cast<double>(full_runs) / adaptive_runs, adaptive_s,
               full_s, full_s / adaptive_s);
  }
  return 0;
}
