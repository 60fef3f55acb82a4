#include "texture_table.hpp"

#include <algorithm>
#include <cmath>
#include <memory>
#include <numbers>

namespace pneumachaos {

TextureTable::TextureTable(std::span<const TextureMode> modes, double from_m, double to_m)
    : from_m_(from_m) {
  double k_max = 0.0, amplitude_sum = 0.0;
  for (const TextureMode& m : modes) {
    k_max = std::max(k_max, std::abs(m.wavenumber_per_m));
    amplitude_sum += std::abs(m.amplitude);
  }
  const double shortest = k_max > 0.0 ? 2.0 * std::numbers::pi / k_max : to_m - from_m;
  step_m_ = shortest / kNodesPerWavelength;
  error_bound_ = std::pow(step_m_ * k_max, 4) / 384.0 * amplitude_sum;
  const auto nodes = static_cast<std::size_t>(std::ceil((to_m - from_m) / step_m_)) + 1;
  value_.assign(nodes, 1.0);
  slope_.assign(nodes, 0.0);
  for (std::size_t j = 0; j < nodes; ++j) {
    const double x = from_m + static_cast<double>(j) * step_m_;
    for (const TextureMode& m : modes) {
      const double phase = m.wavenumber_per_m * x + m.phase;
      value_[j] += m.amplitude * std::sin(phase);
      slope_[j] += m.amplitude * m.wavenumber_per_m * std::cos(phase) * step_m_;
    }
  }
}

TextureTable TextureTable::periodic(std::vector<double> value, std::vector<double> slope,
                                   double from_m, double step_m) {
  TextureTable t;
  t.from_m_ = from_m;
  t.step_m_ = step_m;
  t.periodic_ = true;
  // The node after the period is the first again, so every interval has both its ends.
  value.push_back(value.front());
  slope.push_back(slope.front());
  t.value_ = std::move(value);
  t.slope_ = std::move(slope);
  return t;
}

std::optional<std::pair<double, double>> TextureTable::value_and_slope(double position_m) const {
  const auto where = locate(position_m);
  if (!where) return std::nullopt;
  const auto [j, u] = *where;
  const double w = 1.0 - u;
  const double value = (1.0 + 2.0 * u) * w * w * value_[j] + u * w * w * slope_[j] +
                       u * u * (3.0 - 2.0 * u) * value_[j + 1] - u * u * w * slope_[j + 1];
  // The derivatives of the Hermite basis, per unit u; one step of x is one unit of u.
  const double du = -6.0 * u * w * value_[j] + w * (w - 2.0 * u) * slope_[j] +
                    6.0 * u * w * value_[j + 1] + u * (3.0 * u - 2.0) * slope_[j + 1];
  return std::pair{value, du / step_m_};
}

// On [0, 1] the value basis functions are a convex pair and each slope basis function stays
// within 4/27 in magnitude, so no point of an interval lies below the smaller end value by
// more than 4/27 of the two scaled slopes.
double TextureTable::lowest() const {
  double low = value_.front();
  for (std::size_t j = 0; j + 1 < value_.size(); ++j) {
    const double reach = 4.0 / 27.0 * (std::abs(slope_[j]) + std::abs(slope_[j + 1]));
    low = std::min(low, std::min(value_[j], value_[j + 1]) - reach);
  }
  return low;
}

std::shared_ptr<const TextureTable> tabulate_texture(std::span<const TextureMode> modes,
                                                     double from_m, double to_m) {
  if (modes.empty()) return nullptr;
  return std::make_shared<const TextureTable>(modes, from_m, to_m);
}

}  // namespace pneumachaos
