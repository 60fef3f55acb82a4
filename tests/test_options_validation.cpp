// Every options struct names the field that is out of range (Ceres's Options::IsValid style):
// the verdict's thresholds and the fit's settings, checked before any work.
#include <gtest/gtest.h>

#include <cmath>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/identify/fit.hpp"

namespace pneumachaos {
namespace {

template <class Options>
std::string message_of(const Options& o) {
  try {
    o.validate();
  } catch (const Error& e) {
    return e.what();
  }
  return "";
}

TEST(OptionsValidation, VerdictThresholdsAreNamed) {
  EXPECT_EQ(message_of(VerdictOptions{}), "");
  VerdictOptions o;
  o.zero_one_split = 1.5;
  EXPECT_NE(message_of(o).find("verdict zero_one_split"), std::string::npos) << message_of(o);
  o = VerdictOptions{};
  o.lyapunov_sigmas = NAN;  // a NaN is out of every range
  EXPECT_NE(message_of(o).find("lyapunov_sigmas"), std::string::npos);
  o = VerdictOptions{};
  o.min_rest_samples = 0;
  EXPECT_NE(message_of(o).find("min_rest_samples"), std::string::npos);
  o = VerdictOptions{};
  o.repetition.candidates = 0;  // the nested options are checked too
  EXPECT_NE(message_of(o).find("candidates"), std::string::npos);
}

TEST(OptionsValidation, AnalysisRefusesABadVerdictThresholdBeforeWork) {
  std::vector<double> x(2000);
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = std::sin(0.1 * static_cast<double>(k));
  AnalysisOptions o;
  o.wolf = false;
  o.verdict.periodic_max_broadband = -0.1;
  EXPECT_THROW(analyze_series(x, 100.0, o), Error);
}

TEST(OptionsValidation, FitSettingsAreNamed) {
  EXPECT_EQ(message_of(identify::FitOptions{}), "");
  identify::FitOptions o;
  o.max_factor = 0.5;
  EXPECT_NE(message_of(o).find("fit max_factor"), std::string::npos) << message_of(o);
  o = identify::FitOptions{};
  o.first_segment_lengths_s = {0.1, -0.2};
  EXPECT_NE(message_of(o).find("first_segment_lengths_s"), std::string::npos);
  o = identify::FitOptions{};
  o.relative_tolerance = 1e-14;
  EXPECT_NE(message_of(o).find("relative_tolerance"), std::string::npos);
}

}  // namespace
}  // namespace pneumachaos
