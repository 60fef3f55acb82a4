// The dysts validation table (docs/notes/exponent_validation.md): for every flow of
// tests/data/dysts/flows.tsv, the exponent from the equations (two trajectories), dysts's
// reference, and the analysis's exponent, 95 % interval and verdict at 5,000 and 10,000
// samples. A program printing a table, not a timing.
//
//   build/bench/bench_dysts [--records DIR] [--jacobian] [NAME...]     (no name: every system)
//
// --jacobian also runs the local-Jacobian estimator (`analyze --jacobian-exponents`), prints
// its value under each row and scores both estimators against the truth and the record's own
// stretch (docs/validation.md, "Two estimators").
//
// --records DIR also writes each record (DIR/NAME_N.txt, one sample a line) and DIR/index.tsv
// (name, samples, sampling rate, class, truth, our value): the input of bench/nolds_dysts.py,
// which runs a peer's estimator on the very same records.
#include <fmt/format.h>
#include <fmt/os.h>

#include <algorithm>
#include <cstdio>
#include <filesystem>
#include <optional>
#include <string>
#include <vector>

#include "dysts_runner.hpp"

namespace {

using namespace pneumachaos::testing::dysts;

void write_record(const std::filesystem::path& dir, const System& s, const Row& r,
                  std::FILE* index) {
  const std::vector<double> x = record(s, r.samples);
  auto out = fmt::output_file((dir / fmt::format("{}_{}.txt", s.name, r.samples)).string());
  for (const double v : x) out.print("{:.17g}\n", v);
  fmt::print(index, "{}\t{}\t{:.17g}\t{}\t{:.17g}\t{}\n", s.name, r.samples,
             kPointsPerPeriod / s.period, truth_name(truth_class(r)), r.truth,
             r.found ? fmt::format("{:.17g}", r.lambda) : "-");
}

}  // namespace

int main(int argc, char** argv) {
  std::vector<std::string> only(argv + 1, argv + argc);
  std::optional<std::filesystem::path> records;
  if (only.size() >= 2 && only.front() == "--records") {
    records = only[1];
    only.erase(only.begin(), only.begin() + 2);
    std::filesystem::create_directories(*records);
  }
  const auto flag = std::find(only.begin(), only.end(), "--jacobian");
  const bool jacobian = flag != only.end();
  if (jacobian) only.erase(flag);
  std::FILE* index = records ? std::fopen((*records / "index.tsv").string().c_str(), "w") : nullptr;
  if (records && index == nullptr) {
    fmt::print(stderr, "bench_dysts: cannot write {}\n", (*records / "index.tsv").string());
    return 3;
  }
  if (index != nullptr) fmt::print(index, "# name\tsamples\trate\tclass\ttruth\tours\n");
  std::vector<Row> rows5, rows10;
  fmt::print("{}\n", table_header());
  for (const System& s : load_systems(PNEUMACHAOS_DYSTS_TSV)) {
    if (!only.empty() && std::find(only.begin(), only.end(), s.name) == only.end()) continue;
    const Benettin long_run = benettin(s);
    for (const std::size_t n : {5000u, 10000u}) {
      const Row r = analyse(s, n, long_run, 1, jacobian);
      if (truth_class(r) == Truth::kChaotic) (n == 5000 ? rows5 : rows10).push_back(r);
      fmt::print("{}  (long run +-{:.4f})\n", format_row(r), long_run.spread);
      if (jacobian) {
        fmt::print("{:>27} local Jacobians {:.4f} +-{:.4f} ({:+.0f}% of truth, {:+.0f}% of span){}\n",
                   "", r.jacobian, r.jacobian_half, 100.0 * (r.jacobian / r.truth - 1.0),
                   100.0 * (r.jacobian / r.span - 1.0),
                   !r.jacobian_found ? " not computed" : r.jacobian_reliable ? "" : " unreliable");
      }
      if (index != nullptr) write_record(*records, s, r, index);
      std::fflush(stdout);
    }
  }
  if (index != nullptr) std::fclose(index);
  fmt::print("chaotic flows, 5,000 samples: {}\nchaotic flows, 10,000 samples: {}\n",
             summarise(rows5).text(),
             summarise(rows10).text());
  if (jacobian) {
    fmt::print("both estimators, 5,000 samples: {}\nboth estimators, 10,000 samples: {}\n",
               score_estimators(rows5).text(), score_estimators(rows10).text());
  }
}
