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

std::shared_ptr<const TextureTable> tabulate_texture(std::span<const TextureMode> modes,
                                                     double from_m, double to_m) {
  if (modes.empty()) return nullptr;
  return std::make_shared<const TextureTable>(modes, from_m, to_m);
}

}  // namespace pneumachaos
