#include "pneumachaos/analysis/continuous_alignment.hpp"

#include <algorithm>
#include <cmath>

namespace pneumachaos {

double interpolate_series(std::span<const double> x, double t) {
  const auto i = static_cast<std::size_t>(std::floor(t));
  const double u = t - static_cast<double>(i);
  const double p0 = x[i - 1], p1 = x[i], p2 = x[i + 1], p3 = x[i + 2];
  return p1 + 0.5 * u *
                  (p2 - p0 +
                   u * (2.0 * p0 - 5.0 * p1 + 4.0 * p2 - p3 + u * (3.0 * (p1 - p2) + p3 - p0)));
}

std::span<const double> shifted_series(std::span<const double> x, std::size_t j, double s,
                                       std::size_t count, std::vector<double>& buffer) {
  // t = j + s = base + u with 0 <= u < 1; Lagrange weights of the cubic through base-1..base+2.
  const double t = static_cast<double>(j) + s;
  const auto base = static_cast<std::size_t>(std::floor(t));
  const double u = t - static_cast<double>(base);
  const double w0 = -u * (u - 1.0) * (u - 2.0) / 6.0;
  const double w1 = (u + 1.0) * (u - 1.0) * (u - 2.0) / 2.0;
  const double w2 = -(u + 1.0) * u * (u - 2.0) / 2.0;
  const double w3 = (u + 1.0) * u * (u - 1.0) / 6.0;
  buffer.resize(count);
  const double* p = x.data() + base - 1;
  for (std::size_t k = 0; k < count; ++k) {
    buffer[k] = w0 * p[k] + w1 * p[k + 1] + w2 * p[k + 2] + w3 * p[k + 3];
  }
  return buffer;
}

double closest_offset(const DelayEmbedding& e, std::size_t i, std::size_t j) {
  double s = 0.0;
  for (int iteration = 0; iteration < 2; ++iteration) {
    double num = 0.0, den = 0.0;
    const double t = static_cast<double>(j) + s;
    for (std::size_t d = 0; d < e.dimension(); ++d) {
      const double here = interpolated_coordinate(e, t, d);
      const double tangent =
          0.5 * (interpolated_coordinate(e, t + 1.0, d) - interpolated_coordinate(e, t - 1.0, d));
      num += (here - e.coordinate(i, d)) * tangent;
      den += tangent * tangent;
    }
    if (den <= 0.0) break;
    s = std::clamp(s - num / den, -1.0, 1.0);
  }
  return s;
}

double distance2_to(const DelayEmbedding& e, std::size_t i, double j_plus_s) {
  double d2 = 0.0;
  for (std::size_t d = 0; d < e.dimension(); ++d) {
    const double diff = e.coordinate(i, d) - interpolated_coordinate(e, j_plus_s, d);
    d2 += diff * diff;
  }
  return d2;
}

}  // namespace pneumachaos
