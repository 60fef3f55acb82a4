// The dysts validation table (docs/notes/exponent_validation.md): for every flow of
// tests/data/dysts/flows.tsv, the exponent from the equations (two trajectories), dysts's
// reference, and the analysis's exponent, 95 % interval and verdict at 5,000 and 10,000
// samples. A program printing a table, not a timing.
//
//   build/bench/bench_dysts [NAME...]     (no name: every system)
#include <fmt/format.h>

#include <algorithm>
#include <cstdio>
#include <string>
#include <vector>

#include "dysts_runner.hpp"

int main(int argc, char** argv) {
  using namespace pneumachaos::testing::dysts;
  const std::vector<std::string> only(argv + 1, argv + argc);
  std::vector<Row> rows5, rows10;
  fmt::print("{}\n", table_header());
  for (const System& s : load_systems(PNEUMACHAOS_DYSTS_TSV)) {
    if (!only.empty() && std::find(only.begin(), only.end(), s.name) == only.end()) continue;
    const Benettin long_run = benettin(s);
    for (const std::size_t n : {5000u, 10000u}) {
      const Row r = analyse(s, n, long_run);
      if (truth_class(r) == Truth::kChaotic) (n == 5000 ? rows5 : rows10).push_back(r);
      fmt::print("{}  (long run +-{:.4f})\n", format_row(r), long_run.spread);
      std::fflush(stdout);
    }
  }
  fmt::print("chaotic flows, 5,000 samples: {}\nchaotic flows, 10,000 samples: {}\n",
             summarise(rows5).text(),
             summarise(rows10).text());
}
