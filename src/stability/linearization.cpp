#include "pneumachaos/stability/linearization.hpp"

#include <fmt/format.h>

#include <string>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// Positions of the reduced states; kNone where the plant has no such state. The seal's
// internal states (one for LuGre, one per element for GMS) follow P2 as a block of z_count.
struct ReducedLayout {
  static constexpr int kNone = -1;
  int v = 0, P1 = 1, P2 = 2, z = kNone, deflection = kNone, v_load = kNone, z_guide = kNone;
  int z_count = 0;
  int size = 3;
};

ReducedLayout reduced_layout(const Plant& plant) {
  const StateLayout& L = plant.layout();
  if (L.guide_z_count > 1) {
    throw Error("guide_friction.model",
                "the linearization supports at most one internal state of the guide's friction");
  }
  if (L.has_temperatures()) {
    throw Error("thermal.chamber_model",
                "the linearization does not include the chamber temperatures yet; use polytropic");
  }
  if (L.has_valve_opening()) {
    throw Error("valve.S1_opening",
                "the linearization assumes S1 fully open; use \"instant\"");
  }
  if (L.has_supply_line()) {
    throw Error("supply_line.volume_cm3",
                "the linearization does not include the supply line yet; use 0 (ideal supply)");
  }
  ReducedLayout r;
  if (L.seal_z_count > 0) {
    r.z = r.size;
    r.z_count = static_cast<int>(L.seal_z_count);
    r.size += r.z_count;
  }
  if (L.has_load_body()) {
    r.deflection = r.size++;
    r.v_load = r.size++;
    if (L.guide_z_count == 1) r.z_guide = r.size++;
  }
  return r;
}

std::vector<double> full_state_impl(const Plant& plant, const Equilibrium& eq,
                                    const ReducedLayout& r, const Eigen::VectorXd& y) {
  const StateLayout& L = plant.layout();
  std::vector<double> x = eq.state;
  x[L.x] = eq.position_m;
  x[L.v] = y[r.v];
  x[L.P1] = y[r.P1];
  x[L.P2] = y[r.P2];
  for (int i = 0; i < r.z_count; ++i) x[L.seal_z + i] = y[r.z + i];
  if (r.deflection != ReducedLayout::kNone) {
    x[L.load_x] = eq.position_m - y[r.deflection];
    x[L.load_v] = y[r.v_load];
  }
  if (r.z_guide != ReducedLayout::kNone) x[L.guide_z] = y[r.z_guide];
  return x;
}

}  // namespace

std::vector<double> full_state(const Plant& plant, const Equilibrium& eq,
                               const Eigen::VectorXd& y) {
  return full_state_impl(plant, eq, reduced_layout(plant), y);
}

ReducedState reduced_state(const Plant& plant, const Equilibrium& eq) {
  const ReducedLayout r = reduced_layout(plant);
  const StateLayout& L = plant.layout();
  // Appended in the order reduced_layout assigns the positions.
  ReducedState out;
  std::vector<double> values;
  const auto add = [&](std::string name, double v) {
    out.names.push_back(std::move(name));
    values.push_back(v);
  };
  add("v", eq.state[L.v]);
  add("P1", eq.state[L.P1]);
  add("P2", eq.state[L.P2]);
  // "z" for a single state (LuGre), "z1", "z2", ... for the GMS elements.
  for (int i = 0; i < r.z_count; ++i)
    add(r.z_count == 1 ? std::string("z") : fmt::format("z{}", i + 1), eq.state[L.seal_z + i]);
  if (r.deflection != ReducedLayout::kNone) {
    add("deflection", eq.state[L.x] - eq.state[L.load_x]);
    add("v_load", eq.state[L.load_v]);
  }
  if (r.z_guide != ReducedLayout::kNone) add("z_guide", eq.state[L.guide_z]);
  out.value =
      Eigen::Map<const Eigen::VectorXd>(values.data(), static_cast<Eigen::Index>(values.size()));
  return out;
}

Eigen::VectorXd reduced_derivative(const Plant& plant, const Equilibrium& eq,
                                   const Eigen::VectorXd& y) {
  const ReducedLayout r = reduced_layout(plant);
  const StateLayout& L = plant.layout();
  const std::vector<double> x = full_state_impl(plant, eq, r, y);
  std::vector<double> dx(x.size());
  plant.derivative(plant.sliding_mode(+1), x, dx, 0.0);
  Eigen::VectorXd dy(r.size);
  dy[r.v] = dx[L.v];
  dy[r.P1] = dx[L.P1];
  dy[r.P2] = dx[L.P2];
  for (int i = 0; i < r.z_count; ++i) dy[r.z + i] = dx[L.seal_z + i];
  if (r.deflection != ReducedLayout::kNone) {
    dy[r.deflection] = dx[L.x] - dx[L.load_x];
    dy[r.v_load] = dx[L.load_v];
  }
  if (r.z_guide != ReducedLayout::kNone) dy[r.z_guide] = dx[L.guide_z];
  return dy;
}

Eigen::MatrixXd jacobian(const Plant& plant, const Equilibrium& eq) {
  const ReducedLayout r = reduced_layout(plant);
  const StateLayout& L = plant.layout();
  const auto n = static_cast<Eigen::Index>(L.size);
  const std::vector<double> x = full_state_impl(plant, eq, r, reduced_state(plant, eq).value);
  Eigen::Matrix<double, Eigen::Dynamic, Eigen::Dynamic, Eigen::RowMajor> dfdx(n, n);
  Eigen::VectorXd dfdt(n);
  plant.jacobian(plant.sliding_mode(+1), x, 0.0, std::span<double>(dfdx.data(), dfdx.size()),
                 std::span<double>(dfdt.data(), dfdt.size()));
  // The reduced state is a linear function of the full one and back (full_state_impl and
  // reduced_derivative), so the chain rule is exact: J = D dfdx E.
  Eigen::MatrixXd E = Eigen::MatrixXd::Zero(n, r.size);  // d full state / d reduced state
  Eigen::MatrixXd D = Eigen::MatrixXd::Zero(r.size, n);  // d reduced rate / d full rate
  const auto both = [&](int reduced, std::size_t full) {
    E(static_cast<Eigen::Index>(full), reduced) = 1.0;
    D(reduced, static_cast<Eigen::Index>(full)) = 1.0;
  };
  both(r.v, L.v);
  both(r.P1, L.P1);
  both(r.P2, L.P2);
  for (int i = 0; i < r.z_count; ++i) both(r.z + i, L.seal_z + static_cast<std::size_t>(i));
  if (r.deflection != ReducedLayout::kNone) {
    E(static_cast<Eigen::Index>(L.load_x), r.deflection) = -1.0;  // x_load = x - deflection
    D(r.deflection, static_cast<Eigen::Index>(L.x)) = 1.0;
    D(r.deflection, static_cast<Eigen::Index>(L.load_x)) = -1.0;
    both(r.v_load, L.load_v);
  }
  if (r.z_guide != ReducedLayout::kNone) both(r.z_guide, L.guide_z);
  return D * dfdx * E;
}

}  // namespace pneumachaos
