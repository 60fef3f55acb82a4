#pragma once
// Linearization of the full nonlinear model about a steady motion. The piston position only
// sets the chamber volumes and grows steadily, so it is frozen at the equilibrium position;
// every other state is kept (velocity, both pressures, friction internal states and, for the
// spring-coupled load, the spring deflection x - x_load, the load velocity and its friction
// states).

#include <Eigen/Dense>
#include <string>
#include <vector>

#include "pneumachaos/stability/equilibrium.hpp"

namespace pneumachaos {

struct ReducedState {
  std::vector<std::string> names;  ///< e.g. v, P1, P2, z, deflection, v_load, z_guide
  Eigen::VectorXd value;
};

/// The reduced state at an equilibrium.
ReducedState reduced_state(const Plant& plant, const Equilibrium& eq);

/// The full plant state for a reduced state (position frozen at the equilibrium's).
std::vector<double> full_state(const Plant& plant, const Equilibrium& eq, const Eigen::VectorXd& y);

/// d(reduced state)/dt, from the plant's own derivative in the steady sliding mode.
Eigen::VectorXd reduced_derivative(const Plant& plant, const Equilibrium& eq,
                                   const Eigen::VectorXd& y);

/// The Jacobian of reduced_derivative, from the plant's exact Jacobian (automatic
/// differentiation of its equations; checked against finite differences in the tests).
Eigen::MatrixXd jacobian(const Plant& plant, const Equilibrium& eq);

}  // namespace pneumachaos
