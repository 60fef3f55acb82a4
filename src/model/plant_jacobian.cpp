// The Plant's Jacobian by forward-mode automatic differentiation (Eigen's AutoDiff module) of
// the same templated equations derivative() runs, so no derivative is written by hand.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <cmath>
#include <limits>
#include <unsupported/Eigen/AutoDiff>
#include <vector>

#include "plant_equations.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// Derivative vectors live on the stack up to this many states (4 + friction states + a
// second body with its friction states + every optional block: 4 + 8 + 2 + 8 + 4), so the
// Jacobian allocates nothing per call.
constexpr int kMaxStates = 24;
using Gradient = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxStates, 1>;
using Dual = Eigen::AutoDiffScalar<Gradient>;

// Column j of df/dx by a forward difference, for the states where the law has no derivative:
// a Stribeck exponent below 1 makes the level's slope infinite at rest (d sqrt(|v|)/dv at
// v = 0), which automatic differentiation returns as inf or NaN. The secant over a step of
// sqrt(eps) times the state's size (or its scale) is the finite slope the law has next to that
// point; it is what a stiff stepper needs there, as exactness is not defined at the kink.
// f0 is the derivative at x, shared by every repaired column.
void difference_column(const Plant& plant, const Mode& mode, std::span<const double> x,
                       std::span<const double> f0, std::size_t j, double scale,
                       std::span<double> dfdx) {
  const std::size_t n = x.size();
  std::vector<double> xh(x.begin(), x.end());
  std::vector<double> fh(n);
  const double h = std::sqrt(std::numeric_limits<double>::epsilon()) *
                   std::max(std::abs(x[j]), scale);
  xh[j] += h;
  plant.derivative(mode, xh, fh, 0.0);
  const double step = xh[j] - x[j];  // the step as represented
  for (std::size_t i = 0; i < n; ++i) dfdx[i * n + j] = (fh[i] - f0[i]) / step;
}

// Every column with an inf or NaN entry is replaced by its difference quotient.
void repair_nondifferentiable_columns(const Plant& plant, const Mode& mode,
                                      std::span<const double> x, std::span<double> dfdx) {
  const std::size_t n = x.size();
  std::vector<double> scales, f0;
  for (std::size_t j = 0; j < n; ++j) {
    bool finite = true;
    for (std::size_t i = 0; i < n; ++i) finite = finite && std::isfinite(dfdx[i * n + j]);
    if (finite) continue;
    if (scales.empty()) {
      scales = plant.state_scales();
      f0.resize(n);
      plant.derivative(mode, x, f0, 0.0);
    }
    difference_column(plant, mode, x, f0, j, scales[j], dfdx);
  }
}

}  // namespace

bool Plant::jacobian(const Mode& mode, std::span<const double> x, double /*t*/,
                     std::span<double> dfdx, std::span<double> dfdt) const {
  const std::size_t n = layout_.size;
  if (n > static_cast<std::size_t>(kMaxStates)) {
    throw Error("friction.model",
                "too many states for the automatic-differentiation Jacobian (raise kMaxStates)");
  }
  std::array<Dual, kMaxStates> xa;
  std::array<Dual, kMaxStates> fa;
  const auto size = static_cast<Eigen::Index>(n);
  for (std::size_t j = 0; j < n; ++j) xa[j] = Dual(x[j], size, static_cast<Eigen::Index>(j));
  evaluate<Dual>(mode, std::span<const Dual>(xa.data(), n), std::span<Dual>(fa.data(), n));
  for (std::size_t i = 0; i < n; ++i) {
    // A result that depends on no state (e.g. v held at 0 while stuck) has no derivatives.
    const Gradient& d = fa[i].derivatives();
    for (std::size_t j = 0; j < n; ++j) {
      dfdx[i * n + j] = d.size() == 0 ? 0.0 : d[static_cast<Eigen::Index>(j)];
    }
  }
  repair_nondifferentiable_columns(*this, mode, x, dfdx);
  std::fill(dfdt.begin(), dfdt.end(), 0.0);
  return true;
}

}  // namespace pneumachaos
