#pragma once
// The bore texture's factor 1 + sum a sin(k x + phase), tabulated along the stroke for
// evaluation speed (docs/model.md, "Friction"; docs/notes/performance.md, "The texture table"):
// four library sines per contact and evaluation cost a fifth of a textured sweep run's time.
// The seal's random level field is tabulated the same way over one period, and repeats.
// Private to the model module.

#include <cmath>
#include <memory>
#include <optional>
#include <span>
#include <utility>
#include <vector>

#include "pneumachaos/model/friction.hpp"

namespace pneumachaos {

/// Piecewise cubic Hermite interpolant of the texture factor on nodes kNodesPerWavelength per
/// shortest wavelength, with the exact value and slope at every node. Its error is at most
/// (h k_max)^4 / 384 * sum |a| (the cubic Hermite bound, h^4 / 384 max |f''''|), which this
/// spacing makes (2 pi / 128)^4 / 384 * sum |a| = 1.5e-8 * sum |a|: 1e-9 of the friction level
/// at the sweeps' 2 % texture, a hundred times below the integration's relative tolerance.
class TextureTable {
 public:
  static constexpr int kNodesPerWavelength = 128;

  /// Tabulates `modes` over [from_m, to_m]; positions outside it are not served.
  TextureTable(std::span<const TextureMode> modes, double from_m, double to_m);

  /// A periodic table: `value` and `slope` (the derivative times `step_m`) at the nodes
  /// from_m + j step_m of one period, the period being value.size() steps; every position is
  /// served, wrapped into that period.
  static TextureTable periodic(std::vector<double> value, std::vector<double> slope,
                               double from_m, double step_m);

  /// The factor at x, or nothing outside the tabulated range. Defined inline below: the
  /// friction laws ask for it in every evaluation of the right-hand side.
  [[nodiscard]] std::optional<double> at(double position_m) const;

  /// The value and its derivative d/dx at x (for the Jacobian), or nothing outside the range.
  [[nodiscard]] std::optional<std::pair<double, double>> value_and_slope(double position_m) const;

  /// The bound above for these modes (tests/model/test_friction.cpp checks it).
  [[nodiscard]] double error_bound() const { return error_bound_; }

  /// A lower bound of the interpolant over the whole table.
  [[nodiscard]] double lowest() const;

 private:
  TextureTable() = default;
  /// The node interval and the position u in [0, 1) within it, or nothing outside the range.
  [[nodiscard]] std::optional<std::pair<std::size_t, double>> locate(double position_m) const;

  double from_m_ = 0.0;
  double step_m_ = 0.0;
  double error_bound_ = 0.0;
  bool periodic_ = false;
  std::vector<double> value_;  ///< factor at each node
  std::vector<double> slope_;  ///< its derivative times the step, at each node
};

inline std::optional<std::pair<std::size_t, double>> TextureTable::locate(
    double position_m) const {
  double t = (position_m - from_m_) / step_m_;
  const auto intervals = static_cast<double>(value_.size() - 1);
  if (periodic_) {
    t -= intervals * std::floor(t / intervals);
    if (t >= intervals) t = 0.0;  // a t just below 0 rounds up to the period's end
  }
  // The negated comparison also turns a NaN position away.
  if (!(t >= 0.0 && t < intervals)) return std::nullopt;
  const auto j = static_cast<std::size_t>(t);
  return std::pair{j, t - static_cast<double>(j)};
}

inline std::optional<double> TextureTable::at(double position_m) const {
  const auto where = locate(position_m);
  if (!where) return std::nullopt;
  const auto [j, u] = *where;
  const double w = 1.0 - u;
  // Hermite basis on [0, 1]: (1 + 2u) w^2, u w^2, u^2 (3 - 2u), -u^2 w.
  return (1.0 + 2.0 * u) * w * w * value_[j] + u * w * w * slope_[j] +
         u * u * (3.0 - 2.0 * u) * value_[j + 1] - u * u * w * slope_[j + 1];
}

/// How far beyond the stroke, either side, the Plant tabulates the bore (the guide's load
/// follows the piston through the mount); the random level field's period covers the stroke
/// and this margin either side.
inline constexpr double kBoreMargin_m = 0.05;

/// The table of `modes` over [from_m, to_m], for make_friction_model; null when there are none.
std::shared_ptr<const TextureTable> tabulate_texture(std::span<const TextureMode> modes,
                                                     double from_m, double to_m);

}  // namespace pneumachaos
