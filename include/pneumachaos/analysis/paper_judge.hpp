#pragma once
// The paper's own judge of chaos: its three indices as it states them (Kosaki & Sano, Section
// 4.2: a power spectrum "without dominant peaks", an autocorrelation that "converged to zero",
// and Wolf's exponent "converged to a positive value"), with the thresholds the report's claim
// rules use. It sits beside the regime verdict, never in place of it: these three indices also
// call noise-driven motion chaotic (docs/notes/analysis.md "The paper's judge").

#include <optional>
#include <string>
#include <vector>

namespace pneumachaos {

struct AnalysisResult;

/// No spectral peak (+-1 bin) holds more than this share of the power.
inline constexpr double kPaperPeakShare = 0.25;
/// The autocorrelation's envelope at lags of at least kPaperAcfAfter_s is at most this.
inline constexpr double kPaperAcfEnvelope = 0.2;
inline constexpr double kPaperAcfAfter_s = 1.0;
/// An exponent is positive when it exceeds this many times its uncertainty.
inline constexpr double kPaperExponentSigmas = 3.0;

/// Largest |r| at lags of at least after_s: the envelope the ACF still has there; none when
/// the ACF does not reach that lag (a record too short to say whether it forgets itself).
std::optional<double> acf_envelope_after(const std::vector<double>& r, double rate_Hz,
                                         double after_s);

struct PaperJudgement {
  /// false: an index that could decide was not computed (see why). A record whose spectrum
  /// or autocorrelation already refuses is judged without Wolf's exponent.
  bool evaluated = false;
  bool chaotic = false;  ///< all three indices say so
  bool flat_spectrum = false, acf_converges = false, wolf_positive = false;
  bool wolf_computed = false;  ///< false: wolf_per_s and its uncertainty are not set
  double peak_share = 0.0;
  std::optional<double> acf_envelope;  ///< after kPaperAcfAfter_s
  double wolf_per_s = 0.0, wolf_uncertainty_per_s = 0.0;
  std::string why;  ///< when not evaluated: which index is missing
};

/// The paper's three indices read off an analysis (Wolf's estimator must have run).
PaperJudgement paper_judge(const AnalysisResult& a);

/// One line for the text output, e.g. "chaotic (spectrum: largest line 12 % <= 25 %; ...)".
std::string describe(const PaperJudgement& j);

}  // namespace pneumachaos
