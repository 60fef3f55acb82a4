#pragma once
// The coordinates of a steady motion's linearization, derived from the Plant's state table
// (StateLayout) so that every block is included: every state but the piston position (which
// only sets the volumes and grows steadily, so it is frozen), with the load's position replaced
// by the spring deflection x - x_load. Private to the stability module.

#include <Eigen/Dense>
#include <span>
#include <string>
#include <vector>

#include "pneumachaos/model/plant.hpp"

namespace pneumachaos::reduced {

struct Entry {
  std::string name;        ///< v, P1, P2, z or z1..., deflection, v_load, z_guide, T1, P0, ...
  std::size_t full = 0;    ///< the full state it is (or, for the deflection, x_load)
  bool deflection = false;  ///< x - x_load rather than a state itself
};

/// In the order of the full state.
std::vector<Entry> entries(const StateLayout& L);

/// The reduced state of a full one.
Eigen::VectorXd of(const StateLayout& L, const std::vector<Entry>& r, std::span<const double> x);

/// The full state for reduced `y`, its other states (the position) taken from `base`.
std::vector<double> full(const StateLayout& L, const std::vector<Entry>& r,
                         std::vector<double> base, const Eigen::VectorXd& y);

/// d(reduced state)/dt at a full state, in the plant's steady forward-sliding mode.
Eigen::VectorXd rates(const Plant& plant, const std::vector<Entry>& r, std::span<const double> x);

/// Its Jacobian with respect to the reduced state, from the plant's exact Jacobian.
Eigen::MatrixXd jacobian(const Plant& plant, const std::vector<Entry>& r,
                         std::span<const double> x);

}  // namespace pneumachaos::reduced
