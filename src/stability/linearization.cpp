#include "stability/linearization.hpp"

#include "reduced_coordinates.hpp"

namespace pneumachaos {

std::vector<double> full_state(const Plant& plant, const Equilibrium& eq,
                               const Eigen::VectorXd& y) {
  const StateLayout& L = plant.layout();
  std::vector<double> base = eq.state;
  base[L.x] = eq.position_m;
  return reduced::full(L, reduced::entries(L), std::move(base), y);
}

ReducedState reduced_state(const Plant& plant, const Equilibrium& eq) {
  const StateLayout& L = plant.layout();
  const std::vector<reduced::Entry> r = reduced::entries(L);
  ReducedState out;
  for (const reduced::Entry& e : r) out.names.push_back(e.name);
  out.value = reduced::of(L, r, eq.state);
  return out;
}

Eigen::VectorXd reduced_derivative(const Plant& plant, const Equilibrium& eq,
                                   const Eigen::VectorXd& y) {
  return reduced::rates(plant, reduced::entries(plant.layout()), full_state(plant, eq, y));
}

Eigen::MatrixXd jacobian(const Plant& plant, const Equilibrium& eq) {
  const Eigen::VectorXd y = reduced_state(plant, eq).value;
  return reduced::jacobian(plant, reduced::entries(plant.layout()), full_state(plant, eq, y));
}

}  // namespace pneumachaos
