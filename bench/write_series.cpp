// Writes a reference record as CSV (t, v) for timing the command line: Lorenz x at dt = 0.01
// (tests/reference_series.hpp) or Gaussian white noise. Used by bench/compare_builds.sh.
// Usage: write_series lorenz|noise SAMPLES > file.csv
#include <cstdio>
#include <cstdlib>
#include <string>

#include "../tests/reference_series.hpp"

int main(int argc, char** argv) {
  if (argc != 3) {
    std::fprintf(stderr, "usage: %s lorenz|noise SAMPLES\n", argv[0]);
    return 2;
  }
  const std::string kind = argv[1];
  const std::size_t n = std::strtoul(argv[2], nullptr, 10);
  const auto x = kind == "lorenz" ? pneumachaos::testing::lorenz_x(n)
                                  : pneumachaos::testing::white_noise(n);
  std::printf("t,v\n");
  for (std::size_t i = 0; i < x.size(); ++i) std::printf("%.6f,%.17g\n", 0.01 * i, x[i]);
  return 0;
}
