#include "pneumachaos/analysis/paper_judge.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cmath>

#include "pneumachaos/analysis/analyze.hpp"

namespace pneumachaos {

std::optional<double> acf_envelope_after(const std::vector<double>& r, double rate_Hz,
                                         double after_s) {
  const auto first = static_cast<std::size_t>(after_s * rate_Hz);
  if (first >= r.size()) return std::nullopt;  // no lag that long: nothing to judge
  double m = 0.0;
  for (std::size_t k = first; k < r.size(); ++k) m = std::max(m, std::abs(r[k]));
  return m;
}

PaperJudgement paper_judge(const AnalysisResult& a) {
  PaperJudgement j;
  j.peak_share = a.spectrum.peak_share;
  j.acf_envelope = acf_envelope_after(a.acf.r, a.acf.rate_Hz, kPaperAcfAfter_s);
  if (!j.acf_envelope) {
    j.why = fmt::format("the autocorrelation does not reach {} s", kPaperAcfAfter_s);
    return j;
  }
  j.flat_spectrum = j.peak_share <= kPaperPeakShare;
  j.acf_converges = *j.acf_envelope <= kPaperAcfEnvelope;
  j.wolf_computed = a.wolf_run && std::isfinite(a.wolf.lambda_per_s);
  if (j.wolf_computed) {
    j.wolf_per_s = a.wolf.lambda_per_s;
    j.wolf_uncertainty_per_s = a.wolf.uncertainty_per_s;
    j.wolf_positive = j.wolf_per_s > kPaperExponentSigmas * j.wolf_uncertainty_per_s;
  } else if (j.flat_spectrum && j.acf_converges) {
    // The two indices at hand say chaos: only Wolf's exponent could decide.
    j.why = "Wolf's exponent was not computed";
    return j;
  }
  // Chaos needs all three indices: one that refuses decides without the others.
  j.evaluated = true;
  j.chaotic = j.flat_spectrum && j.acf_converges && j.wolf_positive;
  return j;
}

std::string describe(const PaperJudgement& j) {
  if (!j.evaluated) return "not judged: " + j.why;
  const auto mark = [](bool yes) { return yes ? "yes" : "no"; };
  const std::string wolf =
      j.wolf_computed ? fmt::format("{}, {:.3g} +- {:.2g} 1/s, above {} sigma",
                                    mark(j.wolf_positive), j.wolf_per_s,
                                    j.wolf_uncertainty_per_s, kPaperExponentSigmas)
                      : std::string("not computed, not needed");
  return fmt::format(
      "{} (no dominant line: {}, the largest holds {:.0f} % of the power, at most {:.0f} %; "
      "autocorrelation converges: {}, {:.2f} after {} s, at most {}; Wolf's exponent "
      "positive: {})",
      j.chaotic ? "chaotic" : "not chaotic", mark(j.flat_spectrum), 100.0 * j.peak_share,
      100.0 * kPaperPeakShare, mark(j.acf_converges), *j.acf_envelope, kPaperAcfAfter_s,
      kPaperAcfEnvelope, wolf);
}

}  // namespace pneumachaos
