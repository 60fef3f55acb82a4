// Simulates the default scenario through the installed library's one public header, set by
// typed fields (SI units), and reports the record.
#include <cstdio>

#include "pneumachaos/pneumachaos.hpp"

int main() {
  pneumachaos::Scenario s = pneumachaos::default_scenario();
  s.run.duration_s = 2.0;
  s.validate();
  const pneumachaos::Plant plant(s);
  const auto r = pneumachaos::simulate(plant, s.run);
  std::printf("simulated %zu samples\n", r.series.size());
  return r.summary.ok() ? 0 : 1;
}
