// The paper's Fig. 7 example run (pneumachaos/claims/example_run.hpp): one record of the rig, with
// the seal's random level when the scenario has one, without the maps' scatter and texture.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

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

// The example is analysed from the velocity as the scenario's transducer records it, as the
// paper's record was measured and as every map run is: the motion is the same, the analysed
// record is the transducer's; with ideal transducers it is the simulated velocity itself.
TEST(ExampleRun, IsJudgedFromTheTransducersRecord) {
  const std::vector<std::string> rig = {"load.coupling=rigid", "run.duration_s=3"};
  const ExampleRun ideal = run_example(build_scenario("", rig), 3.0, false);
  const auto& simulated = ideal.sim.series.channel("v").values;
  EXPECT_EQ(ideal.v, std::vector<double>(simulated.begin() + static_cast<std::ptrdiff_t>(ideal.settle),
                                         simulated.end()));
  std::vector<std::string> measured = rig;
  measured.push_back("transducer.velocity_noise_mm_per_s=1");
  const ExampleRun noisy = run_example(build_scenario("", measured), 3.0, false);
  EXPECT_EQ(friction_of(noisy), friction_of(ideal));
  ASSERT_EQ(noisy.v.size(), ideal.v.size());
  double square_sum = 0.0;
  for (std::size_t i = 0; i < ideal.v.size(); ++i) {
    const double d = noisy.v[i] - ideal.v[i];
    square_sum += d * d;
  }
  // The difference is the transducer's 1 mm/s of white noise (within 10 % over ~1000 samples).
  EXPECT_NEAR(std::sqrt(square_sum / static_cast<double>(ideal.v.size())), 1e-3, 1e-4);
}

}  // namespace
}  // namespace pneumachaos
