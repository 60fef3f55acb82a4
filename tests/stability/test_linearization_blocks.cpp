// The linearization takes every block of the Plant's state: each optional block against a
// known answer (a decoupled mode exactly, or the limit in which the block disappears).
#include <gtest/gtest.h>

#include <Eigen/Eigenvalues>
#include <algorithm>
#include <complex>

#include "support/simple_rig.hpp"
#include "stability/linearization.hpp"

namespace pneumachaos {
namespace {

// The paper's analysis is about the simple rig (one rigid mass): the tests start from it.
Scenario scenario(const std::vector<std::string>& sets) { return simple_rig_with(sets); }

struct Linearized {
  std::vector<std::complex<double>> eigenvalues;  // ascending real part
  ReducedState state;
  Eigen::VectorXd rates;  // at the equilibrium: zero for a steady motion
};

Linearized linearize(const std::vector<std::string>& sets) {
  const Plant plant(scenario(sets));
  const EquilibriumResult eqs = find_equilibria(plant);
  EXPECT_TRUE(eqs.exists()) << eqs.reason;
  if (!eqs.exists()) return {};
  const Equilibrium& e = eqs.primary();
  Linearized out;
  out.state = reduced_state(plant, e);
  out.rates = reduced_derivative(plant, e, out.state.value);
  const Eigen::VectorXcd ev = Eigen::EigenSolver<Eigen::MatrixXd>(jacobian(plant, e)).eigenvalues();
  out.eigenvalues.assign(ev.begin(), ev.end());
  std::sort(out.eigenvalues.begin(), out.eigenvalues.end(),
            [](auto a, auto b) { return a.real() < b.real(); });
  return out;
}

// The relative distance from `z` to the nearest of `set`.
double nearest(const std::vector<std::complex<double>>& set, std::complex<double> z) {
  double best = 1e300;
  for (const auto& w : set) best = std::min(best, std::abs(w - z) / std::max(std::abs(z), 1e-12));
  return best;
}

// A Stribeck drop wide enough that the simple rig's steady motion is self-excited (as in
// test_stability.cpp): the modes compared below are the ones the paper reads.
const std::vector<std::string> kRig{"friction.vs_mm_per_s=40", "friction.stribeck_exponent=1"};

std::vector<std::string> with(std::vector<std::string> sets) {
  sets.insert(sets.begin(), kRig.begin(), kRig.end());
  return sets;
}

// S1's opening lag, once open (S1_open = 1), is its own first-order mode: its row holds only
// -1/tau, so the Jacobian is block-triangular and its spectrum is the instant valve's plus
// -1/tau, exactly.
TEST(LinearizationBlocks, ValveOpeningLagAddsExactlyItsOwnMode) {
  const Linearized instant = linearize(with({}));
  const Linearized lag = linearize(with({"valve.S1_opening=lag", "valve.S1_opening_time_ms=20"}));
  ASSERT_EQ(lag.eigenvalues.size(), instant.eigenvalues.size() + 1);
  EXPECT_LT(nearest(lag.eigenvalues, {-1.0 / 0.020, 0.0}), 1e-9);
  for (const auto& z : instant.eigenvalues) EXPECT_LT(nearest(lag.eigenvalues, z), 1e-9) << z;
  EXPECT_EQ(lag.state.names.at(3), "S1_open");
}

// A supply line whose regulator passage is very wide holds P0 at Ps: the ideal supply's modes
// return, and the line adds one fast decaying mode of its own.
TEST(LinearizationBlocks, WideSupplyLineApproachesTheIdealSupply) {
  const Linearized ideal = linearize(with({}));
  const Linearized line =
      linearize(with({"supply_line.volume_cm3=20", "supply_line.regulator_S_mm2=5000"}));
  ASSERT_EQ(line.eigenvalues.size(), ideal.eigenvalues.size() + 1);
  EXPECT_LT(line.rates.cwiseAbs().maxCoeff(), 1e-3);  // every state steady, P0 included
  for (const auto& z : ideal.eigenvalues) EXPECT_LT(nearest(line.eigenvalues, z), 1e-3) << z;
  EXPECT_LT(line.eigenvalues.front().real(), 100.0 * ideal.eigenvalues.front().real());
}

// The same line with a narrow regulator passage moves the modes: the block is not ignored.
TEST(LinearizationBlocks, NarrowSupplyLineMovesTheModes) {
  const Linearized ideal = linearize(with({}));
  const Linearized line =
      linearize(with({"supply_line.volume_cm3=20", "supply_line.regulator_S_mm2=1"}));
  double moved = 0.0;
  for (const auto& z : ideal.eigenvalues) moved = std::max(moved, nearest(line.eigenvalues, z));
  EXPECT_GT(moved, 1e-2);
}

// With a very large wall heat transfer the chambers stay at the wall's temperature: the energy
// equation's modes approach the isothermal chambers' (gas.polytropic_exponent = 1), and each
// temperature adds a fast decaying mode of its own.
TEST(LinearizationBlocks, StrongHeatTransferApproachesIsothermalChambers) {
  const Linearized isothermal = linearize(with({"gas.polytropic_exponent=1"}));
  const Linearized energy =
      linearize(with({"thermal.chamber_model=energy", "thermal.heat_transfer_W_per_m2K=1e7",
                      "thermal.wall_temperature_K=293.15", "gas.temperature_K=293.15"}));
  ASSERT_EQ(energy.eigenvalues.size(), isothermal.eigenvalues.size() + 2);
  EXPECT_LT(energy.rates.cwiseAbs().maxCoeff(), 1e-3);
  for (const auto& z : isothermal.eigenvalues)
    EXPECT_LT(nearest(energy.eigenvalues, z), 1e-2) << z;
}

// The two-state memory with slip lengths far below the motion's: its states follow the
// Stribeck weight almost at once, so the memoryless seal's modes return, and each state adds
// a fast decaying mode of its own, near -v / L_i (the slip law's rate at the steady speed).
TEST(LinearizationBlocks, ShortSlipLengthsApproachTheMemorylessSeal) {
  const Linearized plain = linearize(with({}));
  const Linearized memory =
      linearize(with({"friction.memory=rate_state", "friction.rate_state_slip_length_um=0.01",
                      "friction.rate_state_slip_length2_um=0.02"}));
  ASSERT_EQ(memory.eigenvalues.size(), plain.eigenvalues.size() + 2);
  EXPECT_LT(memory.rates.cwiseAbs().maxCoeff(), 1e-3);  // the states steady too
  for (const auto& z : plain.eigenvalues) EXPECT_LT(nearest(memory.eigenvalues, z), 1e-2) << z;
  EXPECT_EQ(memory.state.names.back(), "theta2");  // named as the output channel
  EXPECT_LT(memory.eigenvalues.front().real(), 100.0 * plain.eigenvalues.front().real());
}

// Long slip lengths keep the states slow: the drop's negative slope does not act at once,
// and the modes move (the block is not ignored).
TEST(LinearizationBlocks, LongSlipLengthsMoveTheModes) {
  const Linearized plain = linearize(with({}));
  const Linearized memory =
      linearize(with({"friction.memory=rate_state", "friction.rate_state_slip_length_um=2000",
                      "friction.rate_state_slip_length2_um=5000"}));
  double moved = 0.0;
  for (const auto& z : plain.eigenvalues) moved = std::max(moved, nearest(memory.eigenvalues, z));
  EXPECT_GT(moved, 1e-2);
}

}  // namespace
}  // namespace pneumachaos
