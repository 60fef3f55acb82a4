// Where a run starts (include/pneumachaos/stability/run_start.hpp): at rest, or on the steady
// sliding motion, so a band where both are stable can be mapped from both sides.
#include <gtest/gtest.h>

#include <algorithm>
#include <functional>
#include <cmath>
#include <string>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/simulate/model_lyapunov.hpp"
#include "pneumachaos/simulate/simulate.hpp"
#include "pneumachaos/stability/equilibrium.hpp"
#include "pneumachaos/stability/run_start.hpp"

namespace pneumachaos {
namespace {

// The one-body rig at the Fig. 7 point with its volumes frozen at mid-stroke.
Scenario one_body(const std::string& S2_mm2, const std::string& start) {
  return build_scenario("", {"load.coupling=rigid", "load.mass_kg=1.5",
                             "cylinder.frozen_position_mm=250", "circuit.S2_mm2=" + S2_mm2,
                             "run.duration_s=8", "run.start=" + start});
}

// The share of the record from `from_s` at rest: the default seal has no true stiction (its
// presliding elements creep), so rest is |v| within 1 % of the record's largest speed, the
// analysis' own rest band for a clean record.
double share_at_rest(const SimulationResult& r, double from_s) {
  const auto& v = r.series.channel("v").values;
  const auto first = static_cast<std::size_t>(from_s * r.series.rate_Hz());
  double top = 0.0;
  for (std::size_t i = first; i < v.size(); ++i) top = std::max(top, std::abs(v[i]));
  std::size_t rest = 0;
  for (std::size_t i = first; i < v.size(); ++i) rest += std::abs(v[i]) <= 0.01 * top;
  return static_cast<double>(rest) / static_cast<double>(v.size() - first);
}

SimulationResult run_from_start(const Scenario& s) {
  const Plant plant(s);
  return simulate_from(plant, run_start_state(plant, s.run), s.run);
}

// Started on the steady motion, a run stays on it where it is stable: the first sample is
// the equilibrium's velocity and the velocity never leaves it by more than 1 % (a fixed point
// of the plant: its derivative is zero there up to the solver's tolerance).
TEST(RunStart, ASlidingStartBeginsOnTheSteadyMotionAndStaysWhereItIsStable) {
  const Scenario s = one_body("0.9", "sliding");
  const Plant plant(s);
  const double v0 = find_equilibria(plant).primary().v0_m_per_s;
  const SimulationResult r = run_from_start(s);
  ASSERT_TRUE(r.summary.ok()) << r.summary.message;
  const auto& v = r.series.channel("v").values;
  EXPECT_DOUBLE_EQ(v.front(), v0);
  for (const double vi : v) ASSERT_NEAR(vi, v0, 0.01 * v0);
  // From rest the same point starts at zero velocity.
  EXPECT_EQ(run_from_start(one_body("0.9", "rest")).series.channel("v").values.front(), 0.0);
}

// Where sliding and stick-slip coexist, a run from rest falls into stick-slip and one from the
// steady motion keeps sliding: the two sides of the band. The one-body rig with frozen volumes
// has such a band above its linear stability border: at S2 = 0.75 mm^2 the steady motion is
// damped (`stability`: largest real part -3.7 1/s; self-excited below about 0.67 mm^2).
TEST(RunStart, BothSidesOfTheBandWhereSlidingAndStickSlipCoexist) {
  const SimulationResult from_rest = run_from_start(one_body("0.75", "rest"));
  const SimulationResult sliding = run_from_start(one_body("0.75", "sliding"));
  ASSERT_TRUE(from_rest.summary.ok() && sliding.summary.ok());
  EXPECT_GT(share_at_rest(from_rest, 2.0), 0.05);  // 12 % measured
  EXPECT_EQ(share_at_rest(sliding, 2.0), 0.0);
}

// simulate() and plant_lyapunov() start at rest; asked for a sliding start they cannot find
// they refuse, naming the key, instead of starting at rest.
TEST(RunStart, TheRestOnlyEntryPointsRefuseASlidingStart) {
  const Scenario s = one_body("0.9", "sliding");
  const Plant plant(s);
  for (const auto& call : {std::function<void()>([&] { (void)simulate(plant, s.run); }),
                           std::function<void()>([&] { (void)plant_lyapunov(plant, s.run); })}) {
    try {
      call();
      ADD_FAILURE() << "a sliding start ran from rest";
    } catch (const Error& e) {
      EXPECT_NE(std::string(e.what()).find("run.start"), std::string::npos) << e.what();
    }
  }
}

// Where the drive cannot overcome the friction there is no steady sliding: an error naming
// run.start with the equilibrium search's reason. At 0.01 MPa the supply pushes the built-in
// rig's 45.5 mm piston with at most 16 N, below its Coulomb friction (22.8 N).
TEST(RunStart, NoSteadySlidingIsAnErrorNamingTheKey) {
  Scenario s = one_body("0.9", "sliding");
  s.supply_gauge_Pa = 0.01e6;
  ASSERT_LT(s.supply_gauge_Pa * s.cylinder.area_head_m2(), s.friction.curve.coulomb_N);
  const Plant plant(s);
  try {
    (void)run_start_state(plant, s.run);
    FAIL() << "a sliding start was found where the drive cannot move the piston";
  } catch (const Error& e) {
    EXPECT_NE(std::string(e.what()).find("run.start"), std::string::npos) << e.what();
  }
}

}  // namespace
}  // namespace pneumachaos
