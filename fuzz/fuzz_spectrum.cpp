// libFuzzer harness: the spectral stage of the analysis on a short record (fuzz_input.hpp):
// Welch's spectrum with fuzzed segment length and overlap, the autocorrelation, the two
// strongest lines and the orbital period. Only pneumachaos::Error may come out; a spectrum
// that is computed has finite, non-negative densities at ascending frequencies up to Nyquist,
// and shares within [0, 1].
#include <cmath>
#include <cstddef>
#include <cstdint>

#include "fuzz_input.hpp"
#include "pneumachaos/analysis/autocorrelation.hpp"
#include "pneumachaos/analysis/series_statistics.hpp"
#include "pneumachaos/analysis/spectral_lines.hpp"
#include "pneumachaos/analysis/spectrum.hpp"
#include "pneumachaos/core/error.hpp"

namespace {

using pneumachaos::fuzz::require;

bool is_share(double v) { return v >= 0.0 && v <= 1.0 + 1e-9; }

void check_spectrum(const pneumachaos::Spectrum& s, double rate_Hz) {
  require(s.frequency_Hz.size() == s.psd.size() && !s.psd.empty());
  for (std::size_t i = 0; i < s.psd.size(); ++i) {
    require(std::isfinite(s.psd[i]) && s.psd[i] >= 0.0);
    require(i == 0 || s.frequency_Hz[i] > s.frequency_Hz[i - 1]);
  }
  require(s.frequency_Hz.back() <= 0.5 * rate_Hz * (1.0 + 1e-12));
  require(is_share(s.peak_share) && is_share(s.broadband_share));
}

}  // namespace

extern "C" int LLVMFuzzerTestOneInput(const std::uint8_t* data, std::size_t size) {
  pneumachaos::fuzz::FuzzInput in(data, size);
  pneumachaos::SpectrumOptions options;
  const std::uint8_t segment = in.byte();
  options.segment_length = segment < 128 ? 0 : segment;  // half the inputs: the default
  options.overlap = in.byte() / 256.0;
  options.strongest_bins = in.in_range(1, 20);
  const double rate_Hz = 1000.0;
  const auto x = in.samples(256);
  try {
    check_spectrum(pneumachaos::welch_spectrum(x, rate_Hz, options), rate_Hz);
  } catch (const pneumachaos::Error&) {
  }
  if (x.size() < 2) return 0;
  try {
    const auto acf = pneumachaos::autocorrelation(x, rate_Hz);
    require(std::isfinite(acf.late_envelope));
    const auto lines = pneumachaos::spectral_lines(x);
    require(std::isfinite(lines.first_frequency) && std::isfinite(lines.second_power));
    const double period =
        pneumachaos::orbital_period(pneumachaos::mean_maxima_spacing(x), lines, x.size());
    require(!std::isnan(period));
  } catch (const pneumachaos::Error&) {
  }
  return 0;
}
