// The Plant's Jacobian by forward-mode automatic differentiation (Eigen's AutoDiff module) of
// the same templated equations derivative() runs, so no derivative is written by hand.
#include <Eigen/Core>
#include <algorithm>
#include <array>
#include <unsupported/Eigen/AutoDiff>

#include "plant_equations.hpp"
#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

// Derivative vectors live on the stack up to this many states (4 + friction states + a
// second body with its friction states), so the Jacobian allocates nothing per call.
constexpr int kMaxStates = 12;
using Gradient = Eigen::Matrix<double, Eigen::Dynamic, 1, 0, kMaxStates, 1>;
using Dual = Eigen::AutoDiffScalar<Gradient>;

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
  std::fill(dfdt.begin(), dfdt.end(), 0.0);
  return true;
}

}  // namespace pneumachaos
