// Writes a reference record as CSV (t, v) for timing the command line: Lorenz x at dt = 0.01,
// Rossler x at dt = 0.1, the Henon map's x (tests/support/reference_series.hpp) or Gaussian white
// noise. Used by bench/compare_builds.sh and bench/tisean_cost.sh; the time column is the
// sample number times the record's step.
// Usage: write_series lorenz|rossler|henon|noise SAMPLES > file.csv
#include <cstdio>
#include <cstdlib>
#include <string>
#include <vector>

#include "../tests/support/reference_series.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s lorenz|rossler|henon|noise SAMPLES\n", argv[0]);
    return 2;
  }
  const std::string kind = argv[1];
  const std::size_t n = std::strtoul(argv[2], nullptr, 10);
  namespace t = pneumachaos::testing;
  double step = 0.01;
  std::vector<double> x;
  if (kind == "lorenz") {
    x = t::lorenz_x(n);
  } else if (kind == "rossler") {
    x = t::rossler_x(n);
    step = 0.1;
  } else if (kind == "henon") {
    x = t::henon_map(n);
    step = 1.0;
  } else if (kind == "noise") {
    x = t::white_noise(n);
  } else {
    std::fprintf(stderr, "unknown record \"%s\": lorenz, rossler, henon or noise\n", kind.c_str());
    return 2;
  }
  std::printf("t,v\n");
  for (std::size_t i = 0; i < x.size(); ++i) std::printf("%.6f,%.17g\n", step * i, x[i]);
  return 0;
}
