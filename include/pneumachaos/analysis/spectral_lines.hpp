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
/// two strongest lines are `lines`: the maxima spacing, unless the maxima follow a faster
/// mode — the faster of the two lines, at least about twice the slower's frequency, has the
/// maxima's rate within 10 % — in which case the state repeats only after the slower line's
/// period, which is returned (the rig's piston: a 25 Hz mount oscillation on a 6.3 Hz orbit;
/// docs/notes/analysis.md "Orbital period").
double orbital_period(double maxima_spacing, const SpectralLines& lines, std::size_t samples);

}  // namespace pneumachaos
