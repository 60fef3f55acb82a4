#pragma once
// The two strongest lines of a record's spectrum, located finely enough to tell a torus (two
// incommensurate frequencies) from a periodic orbit (harmonics, or the subharmonics of a
// period doubling): one Hann-windowed periodogram of the whole record, peaks refined by
// parabolic interpolation of the log power (accurate to a small fraction of a bin).

#include <span>

namespace pneumachaos {

struct SpectralLines {
  double first_frequency = 0.0;   ///< cycles per sample
  double second_frequency = 0.0;  ///< 0 when there is no second local maximum
  double second_power = 0.0;      ///< second line's power / first line's power
  /// No p/q with q <= 3 matches second/first within the frequency resolution.
  bool incommensurate = false;
};

SpectralLines spectral_lines(std::span<const double> x);

/// The orbital period [samples] of a record whose maxima are `maxima_spacing` apart and whose
/// two strongest lines are `lines`: the maxima spacing, unless the maxima follow a harmonic —
/// the faster of the two lines is an integer multiple (>= 2) of the slower and the maxima
/// spacing is that faster line's period — in which case the record repeats only after the
/// slower line's period, which is returned (docs/analysis.md "Orbital period").
double orbital_period(double maxima_spacing, const SpectralLines& lines, std::size_t samples);

}  // namespace pneumachaos
