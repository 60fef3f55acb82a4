// Simulates the default scenario through the installed library and reports the record.
#include <cstdio>

#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/simulate/simulate.hpp"

int main() {
  const pneumachaos::Scenario s = pneumachaos::build_scenario("", {"run.duration_s=2"});
  const pneumachaos::Plant plant(s);
  const auto r = pneumachaos::simulate(plant, s.run);
  std::printf("simulated %zu samples\n", r.series.size());
  return r.summary.ok() ? 0 : 1;
}
