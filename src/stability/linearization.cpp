#include "pneumachaos/stability/linearization.hpp"

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// Positions of the reduced states; kNone where the plant has no such state.
struct ReducedLayout {
  static constexpr int kNone = -1;
  int v = 0, P1 = 1, P2 = 2, z = kNone, deflection = kNone, v_load = kNone, z_guide = kNone;
  int size = 3;
};

ReducedLayout reduced_layout(const Plant& plant) {
  const StateLayout& L = plant.layout();
  if (L.seal_z_count > 1 || L.guide_z_count > 1) {
    throw Error("friction.model", "the linearization supports at most one internal friction state");
  }
  ReducedLayout r;
  if (L.seal_z_count == 1) r.z = r.size++;
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
  if (r.z != ReducedLayout::kNone) x[L.seal_z] = y[r.z];
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
  if (r.z != ReducedLayout::kNone) add("z", eq.state[L.seal_z]);
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
  if (r.z != ReducedLayout::kNone) dy[r.z] = dx[L.seal_z];
  if (r.deflection != ReducedLayout::kNone) {
    dy[r.deflection] = dx[L.x] - dx[L.load_x];
    dy[r.v_load] = dx[L.load_v];
  }
  if (r.z_guide != ReducedLayout::kNone) dy[r.z_guide] = dx[L.guide_z];
  return dy;
}

Eigen::MatrixXd jacobian(const Plant& plant, const Equilibrium& eq) {
  const ReducedLayout r = reduced_layout(plant);
  const Scenario& s = plant.scenario();
  const StateLayout& L = plant.layout();
  const std::vector<double>& x = eq.state;
  const double k = s.polytropic_exponent;
  const double RT = s.gas.R_J_per_kgK * s.temperature_K;
  const double Pa = s.ambient_pressure_Pa;
  const double A1 = plant.A1();
  const double A2 = plant.A2();
  const double V1 = s.cylinder.volume_head_m3(eq.position_m);
  const double V2 = s.cylinder.volume_rod_m3(eq.position_m);
  const double v = x[L.v];
  const double P1 = x[L.P1];
  const double P2 = x[L.P2];
  const double mp = plant.piston_mass_kg();
  const bool spring = r.deflection != ReducedLayout::kNone;
  const double kc = s.load.coupling_stiffness_N_per_m;
  const double cc = s.load.coupling_damping_Ns_per_m;

  Eigen::MatrixXd J = Eigen::MatrixXd::Zero(r.size, r.size);
  const FrictionInput seal_in{v, P1 + P2 - 2.0 * Pa, x[L.x]};
  const auto zs = L.seal_z_count == 0 ? std::span<const double>{}
                                      : std::span<const double>(x).subspan(L.seal_z, 1);
  const FrictionPartials fs = plant.seal_friction().partials(seal_in, +1, zs);

  // Piston: m_p dv/dt = A1 (P1 - Pa) - A2 (P2 - Pa) - F_seal - [F_ext | kc d + cc (v - v_L)].
  J(r.v, r.v) = (-fs.dF_dv - (spring ? cc : 0.0)) / mp;
  J(r.v, r.P1) = (A1 - fs.dF_dp) / mp;
  J(r.v, r.P2) = (-A2 - fs.dF_dp) / mp;
  if (r.z != ReducedLayout::kNone) J(r.v, r.z) = -fs.dF_dz / mp;

  // Chambers, eqs. (2) and (3) with the volumes frozen.
  const Orifice::Partials w1 = plant.valve1().mass_flow_partials(s.supply_pressure_Pa(), P1);
  const Orifice::Partials w2 = plant.valve2().mass_flow_partials(P2, Pa);
  J(r.P1, r.v) = -k * P1 * A1 / V1;
  J(r.P1, r.P1) = k * RT / V1 * w1.dW_dPb - k * A1 * v / V1;
  J(r.P2, r.v) = k * P2 * A2 / V2;
  J(r.P2, r.P2) = -k * RT / V2 * w2.dW_dPa + k * A2 * v / V2;

  if (r.z != ReducedLayout::kNone) {
    J(r.z, r.v) = fs.dzdot_dv;
    J(r.z, r.P1) = J(r.z, r.P2) = fs.dzdot_dp;
    J(r.z, r.z) = fs.dzdot_dz;
  }
  if (spring) {
    const double mL = s.load.mass_kg;
    const double vL = x[L.load_v];
    const FrictionInput guide_in{vL, 0.0, x[L.load_x]};
    const auto zg = L.guide_z_count == 0 ? std::span<const double>{}
                                         : std::span<const double>(x).subspan(L.guide_z, 1);
    const FrictionPartials fg = plant.guide_friction()->partials(guide_in, +1, zg);
    J(r.v, r.deflection) = -kc / mp;
    J(r.v, r.v_load) = cc / mp;
    J(r.deflection, r.v) = 1.0;
    J(r.deflection, r.v_load) = -1.0;
    // Load: m_L dv_L/dt = kc d + cc (v - v_L) - F_ext - F_guide.
    J(r.v_load, r.deflection) = kc / mL;
    J(r.v_load, r.v) = cc / mL;
    J(r.v_load, r.v_load) = (-cc - fg.dF_dv) / mL;
    if (r.z_guide != ReducedLayout::kNone) {
      J(r.v_load, r.z_guide) = -fg.dF_dz / mL;
      J(r.z_guide, r.v_load) = fg.dzdot_dv;
      J(r.z_guide, r.z_guide) = fg.dzdot_dz;
    }
  }
  return J;
}

}  // namespace pneumachaos
