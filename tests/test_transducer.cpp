// The transducers between the simulated signals and the measured records (docs/model.md, "The
// transducer"): their keys.
#include <gtest/gtest.h>

#include <cmath>
#include <functional>
#include <string>
#include <vector>

#include "error_text.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_toml.hpp"

namespace pneumachaos {
namespace {

TEST(Transducer, BadKeysAreRefusedNamingTheKey) {
  const auto refused = [](std::vector<std::string> sets) {
    return error_of([&] { build_scenario("", sets); });
  };
  EXPECT_NE(refused({"transducer.velocity_bits=12"})
                .find("transducer.velocity_range_mm_per_s: a 12-bit converter"),
            std::string::npos);
  EXPECT_NE(refused({"transducer.pressure_bits=12"}).find("transducer.pressure_range_MPa"),
            std::string::npos);
  EXPECT_NE(refused({"transducer.pressure_noise_kPa=-1"})
                .find("transducer.pressure_noise_kPa: -1 kPa is out of range"),
            std::string::npos);
  EXPECT_NE(refused({"transducer.velocity_bits=25"}).find("transducer.velocity_bits: 25"),
            std::string::npos);
  EXPECT_NE(refused({"transducer.velocity_bits=2.5"}).find("expected a whole number"),
            std::string::npos);
  EXPECT_NE(
      refused({"transducer.velocity_bandwidth_Hz=-3"}).find("transducer.velocity_bandwidth_Hz"),
      std::string::npos);
  EXPECT_EQ(refused({"transducer.velocity_bits=12", "transducer.velocity_range_mm_per_s=500"}),
            "(no error)");
}

TEST(Transducer, ScenariosBuiltInCodeAreCheckedToo) {
  const auto refused = [](const std::function<void(Scenario&)>& set) {
    Scenario s = default_scenario();
    set(s);
    return error_of([&] { s.validate(); });
  };
  EXPECT_NE(refused([](Scenario& s) {
              s.transducer.pressure.bits = 30;
            }).find("transducer.pressure_bits: 30 is out of range"),
            std::string::npos);
  EXPECT_NE(refused([](Scenario& s) {
              s.transducer.velocity.noise_m_per_s = -1e-3;
            }).find("transducer.velocity_noise_mm_per_s: -1 mm/s"),
            std::string::npos);
  EXPECT_NE(refused([](Scenario& s) {
              s.transducer.pressure.range_Pa = NAN;
            }).find("transducer.pressure_range_MPa"),
            std::string::npos);
  EXPECT_TRUE(default_scenario().transducer.ideal());
}

}  // namespace
}  // namespace pneumachaos
