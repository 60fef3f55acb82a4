// The paper's Fig. 7 example run (pneumachaos/claims/example_run.hpp): one record of the rig, with
// the seal's random level when the scenario has one, without the maps' scatter and texture.
#include <gtest/gtest.h>

#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/claims/example_run.hpp"

namespace pneumachaos {
namespace {

const std::vector<double>& friction_of(const ExampleRun& e) {
  return e.sim.series.channel("F_friction").values;
}

TEST(ExampleRun, CarriesTheSealsRandomLevelButNotTheMapsScatterOrTexture) {
  const std::vector<std::string> rig = {"load.coupling=rigid", "run.duration_s=3"};
  const ExampleRun plain = run_example(build_scenario("", rig), 3.0, false);
  std::vector<std::string> maps = rig;
  maps.push_back("variation.friction_rel_sd=0.03");
  maps.push_back("variation.texture_rel=0.02");
  EXPECT_EQ(friction_of(run_example(build_scenario("", maps), 3.0, false)), friction_of(plain));
  std::vector<std::string> seal = rig;
  seal.push_back("variation.seal_noise_rel=0.1");
  const ExampleRun noisy = run_example(build_scenario("", seal), 3.0, false);
  EXPECT_NE(friction_of(noisy), friction_of(plain));
  // One realisation: the same record every time.
  EXPECT_EQ(friction_of(run_example(build_scenario("", seal), 3.0, false)), friction_of(noisy));
}

}  // namespace
}  // namespace pneumachaos
