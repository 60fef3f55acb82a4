#include "level_field.hpp"

#include <boost/random/uniform_real_distribution.hpp>

#include <bit>
#include <cmath>
#include <complex>
#include <numbers>
#include <unsupported/Eigen/FFT>
#include <vector>

namespace pneumachaos {
namespace {

constexpr double kTwoPi = 2.0 * std::numbers::pi;

// Nodes of the table per shortest wavelength: the cubic Hermite interpolant is then within
// (2 pi / 32)^4 / 384 = 4e-6 of the sum of |a| of the sines (the texture table's bound).
constexpr std::size_t kNodesPerShortestWavelength = 32;

// The harmonic number of a mode of a field with this period.
std::size_t harmonic(const TextureMode& m, double period_m) {
  return static_cast<std::size_t>(std::llround(m.wavenumber_per_m * period_m / kTwoPi));
}

// sum_n c_n exp(i 2 pi n j / size) for j < size: the inverse transform, unscaled. A library
// FFT (Eigen's, which wraps kissfft) keeps the table's cost at size log size.
std::vector<std::complex<double>> synthesise(const std::vector<std::complex<double>>& c) {
  Eigen::FFT<double> fft;
  fft.SetFlag(Eigen::FFT<double>::Unscaled);
  std::vector<std::complex<double>> out;
  fft.inv(out, c);
  return out;
}

}  // namespace

RandomLevelField draw_level_field(double rel_sd, double correlation_m, double period_m,
                                  std::mt19937_64& rng) {
  RandomLevelField field;
  field.period_m = period_m;
  if (!(rel_sd > 0.0)) return field;
  const auto count =
      static_cast<std::size_t>(std::ceil(kFieldCutoff * period_m / (kTwoPi * correlation_m)));
  boost::random::uniform_real_distribution<double> phase(0.0, kTwoPi);
  double spectrum_sum = 0.0;
  for (std::size_t n = 1; n <= count; ++n) {
    const double k = kTwoPi * static_cast<double>(n) / period_m;
    const double spectrum = 1.0 / (1.0 + k * k * correlation_m * correlation_m);
    spectrum_sum += spectrum;
    field.modes.push_back({std::sqrt(spectrum), k, phase(rng)});
  }
  // sum a^2 / 2 = rel_sd^2: the variance of a sum of sines with independent uniform phases.
  const double scale = rel_sd * std::sqrt(2.0 / spectrum_sum);
  for (TextureMode& m : field.modes) m.amplitude *= scale;
  return field;
}

double level_field_covariance(const RandomLevelField& field, double lag_m) {
  double c = 0.0;
  for (const TextureMode& m : field.modes)
    c += 0.5 * m.amplitude * m.amplitude * std::cos(m.wavenumber_per_m * lag_m);
  return c;
}

std::shared_ptr<const TextureTable> tabulate_level_field(const RandomLevelField& field,
                                                         double from_m) {
  if (field.modes.empty()) return nullptr;
  std::size_t highest = 1;
  for (const TextureMode& m : field.modes) highest = std::max(highest, harmonic(m, field.period_m));
  const std::size_t size = std::bit_ceil(kNodesPerShortestWavelength * highest);
  const double step = field.period_m / static_cast<double>(size);
  std::vector<std::complex<double>> value_c(size), slope_c(size);
  for (const TextureMode& m : field.modes) {
    const std::complex<double> c = std::polar(m.amplitude, m.wavenumber_per_m * from_m + m.phase);
    value_c[harmonic(m, field.period_m)] += c;
    slope_c[harmonic(m, field.period_m)] += m.wavenumber_per_m * step * c;
  }
  const std::vector<std::complex<double>> v = synthesise(value_c), s = synthesise(slope_c);
  std::vector<double> value(size), slope(size);
  // a sin(k x + phase) is the imaginary part of a exp(i (k x + phase)), its derivative times
  // the step the real part of k step a exp(i (k x + phase)).
  for (std::size_t j = 0; j < size; ++j) {
    value[j] = v[j].imag();
    slope[j] = s[j].real();
  }
  return std::make_shared<const TextureTable>(
      TextureTable::periodic(std::move(value), std::move(slope), from_m, step));
}

}  // namespace pneumachaos
