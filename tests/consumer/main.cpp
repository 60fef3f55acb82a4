// Simulates the default scenario through the installed library and prints the final speed.
#include <cstdio>

#include "pneumachaos/io/scenario_toml.hpp"
#include "pneumachaos/simulate/simulate.hpp"

int main() {
  const pneumachaos::Scenario s = pneumachaos::build_scenario("", {"run.duration_s=2"});
  const pneumachaos::Plant plant(s);
  const auto r = pneumachaos::simulate(plant, pneumachaos::SimulationOptions::from(s.run));
  std::printf("final speed %.4f m/s\n", r.series.channel("v").values.back());
  return r.summary.ok() ? 0 : 1;
}
