// Every options struct names the field that is out of range as section.field with its value and
// range (core/validation.hpp): the verdict's thresholds and the fit's settings, checked before
// any work.
#include <gtest/gtest.h>

#include <cmath>

#include "pneumachaos/analysis/analyze.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/identify/fit.hpp"
#include "pneumachaos/identify/friction_estimate.hpp"
#include "pneumachaos/identify/friction_fits.hpp"
#include "pneumachaos/identify/measured_record_csv.hpp"
#include "pneumachaos/io/csv_reader.hpp"
#include "pneumachaos/analysis/local_stretching.hpp"
#include "pneumachaos/analysis/prediction_error.hpp"
#include "pneumachaos/calibrate/calibrate.hpp"
#include "pneumachaos/calibrate/calibration_spec.hpp"
#include "pneumachaos/plot/figure.hpp"
#include "pneumachaos/report/reproduce.hpp"
#include "pneumachaos/stability/stability_analysis.hpp"

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
  EXPECT_NE(message_of(o).find("verdict.zero_one_split = 1.5: must be > 0 and < 1"),
            std::string::npos)
      << message_of(o);
  o = VerdictOptions{};
  o.lyapunov_sigmas = NAN;  // a NaN is out of every range
  EXPECT_NE(message_of(o).find("verdict.lyapunov_sigmas = nan"), std::string::npos);
  o = VerdictOptions{};
  o.min_rest_samples = 0;
  EXPECT_NE(message_of(o).find("verdict.min_rest_samples = 0: must be >= 1"), std::string::npos);
  o = VerdictOptions{};
  o.repetition.candidates = 0;  // the nested options are checked too
  EXPECT_NE(message_of(o).find("self_repetition.candidates = 0"), std::string::npos);
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
  EXPECT_NE(message_of(o).find("fit.max_factor = 0.5: must be > 1"), std::string::npos)
      << message_of(o);
  o = identify::FitOptions{};
  o.first_segment_lengths_s = {0.1, -0.2};
  EXPECT_NE(message_of(o).find("fit.first_segment_lengths_s = -0.2"), std::string::npos);
  o = identify::FitOptions{};
  o.relative_tolerance = 1e-14;
  EXPECT_NE(message_of(o).find("fit.relative_tolerance = 1e-14: must be >= 1e-12 and < 1"),
            std::string::npos);
}

TEST(OptionsValidation, RecordReadingAndFrictionFitSettingsAreNamed) {
  using identify::FrictionFitOptions;
  using identify::RecordReadOptions;
  EXPECT_EQ(message_of(RecordReadOptions{}), "");
  RecordReadOptions r;
  r.ambient_Pa = -1.0;
  EXPECT_NE(message_of(r).find("record.ambient_Pa = -1"), std::string::npos) << message_of(r);
  r = RecordReadOptions{};
  r.stroke_m = 0.0;
  EXPECT_NE(message_of(r).find("record.stroke_m = 0"), std::string::npos);
  EXPECT_EQ(message_of(FrictionFitOptions{}), "");
  FrictionFitOptions f;
  f.models.clear();
  EXPECT_NE(message_of(f).find("friction_fit.models"), std::string::npos);
  f = FrictionFitOptions{};
  f.max_iterations = 0;
  EXPECT_NE(message_of(f).find("friction_fit.max_iterations = 0: must be >= 1"), std::string::npos);
}

TEST(OptionsValidation, SeriesReadingAndStabilitySettingsAreNamed) {
  EXPECT_EQ(message_of(CsvSeriesOptions{}), "");
  CsvSeriesOptions c;
  c.time_jitter = 2.0;
  EXPECT_NE(message_of(c).find("csv.time_jitter = 2: must be >= 0 and < 1"), std::string::npos);
  c = CsvSeriesOptions{};
  c.column.clear();
  EXPECT_NE(message_of(c).find("csv.column"), std::string::npos);
  // The reader checks them before it reads a line.
  c = CsvSeriesOptions{};
  c.time_jitter = -1.0;
  EXPECT_THROW(parse_csv_series("t,v\n0,1\n", "test.csv", c), Error);
  EXPECT_EQ(message_of(StabilityOptions{}), "");
  StabilityOptions s;
  s.equilibrium.scan_points = 2;  // the nested options are checked too
  EXPECT_NE(message_of(s).find("equilibrium.scan_points = 2: must be >= 8"), std::string::npos);
}

TEST(OptionsValidation, AnalysisStagesAndTheReportAreNamed) {
  EXPECT_EQ(message_of(StretchingOptions{}), "");
  StretchingOptions st;
  st.horizon = 0;
  EXPECT_NE(message_of(st).find("stretching.horizon = 0: must be >= 1"), std::string::npos);
  EXPECT_EQ(message_of(PredictionOptions{}), "");
  PredictionOptions p;
  p.neighbours = 0;
  EXPECT_NE(message_of(p).find("prediction.neighbours = 0: must be >= 1"), std::string::npos);
  const std::vector<double> x(400, 1.0);
  EXPECT_THROW(prediction_errors(x, p), Error);  // checked before the record is read
  EXPECT_EQ(message_of(ReproduceOptions{}), "");
  ReproduceOptions r;
  r.out_dir.clear();
  EXPECT_NE(message_of(r).find("reproduce.out_dir: name the report's output directory"),
            std::string::npos);
}

TEST(OptionsValidation, FrictionEstimateSpecFieldsAreNamed) {
  identify::EstimateSpec s;
  s.area_head_m2 = 1e-3;
  s.area_rod_m2 = 8e-4;
  s.mass_kg = 1.0;
  EXPECT_EQ(message_of(s), "");
  s.mass_kg = 0.0;
  EXPECT_NE(message_of(s).find("estimate.mass_kg = 0: must be finite and > 0"), std::string::npos)
      << message_of(s);
  s.mass_kg = 1.0;
  s.min_stick_s = NAN;
  EXPECT_NE(message_of(s).find("estimate.min_stick_s = nan"), std::string::npos);
  EXPECT_NE(message_of(identify::EstimateSpec{}).find("estimate.area_head_m2 = 0"),
            std::string::npos);
}

// The figure's, the calibration's maps', optimizer's and run options, named the same way.
TEST(OptionsValidation, FigureCalibrationMapsAndOptimizerAreNamed) {
  FigureSpec f;
  f.name = "fig7_record";
  EXPECT_EQ(message_of(f), "");
  f.name = "../fig7";
  EXPECT_NE(message_of(f).find("figure.name = ../fig7: must be a plain file stem"),
            std::string::npos) << message_of(f);
  f.name = "fig7";
  f.height = 0;
  EXPECT_NE(message_of(f).find("figure.height = 0: must be between 16 and 10000"),
            std::string::npos) << message_of(f);
  MapSpec m;
  EXPECT_EQ(message_of(m), "");
  m.duration_s = NAN;
  EXPECT_NE(message_of(m).find("objective.duration_s = nan: must be > 0 and <= 3600"),
            std::string::npos) << message_of(m);
  m.duration_s = 5.0;
  m.repeats = 0;
  EXPECT_NE(message_of(m).find("objective.repeats = 0"), std::string::npos);
  OptimizerSpec o;
  EXPECT_EQ(message_of(o), "");
  o.population = 4;
  EXPECT_NE(message_of(o).find("optimizer.population = 4: must be between 5 and 10000"),
            std::string::npos) << message_of(o);
  o.population = 10;
  o.max_evaluations = 19;
  EXPECT_NE(message_of(o).find("optimizer.max_evaluations = 19: must be >= 20"), std::string::npos)
      << message_of(o);
  CalibrateOptions c;
  EXPECT_NE(message_of(c).find("calibrate.out_dir"), std::string::npos) << message_of(c);
  c.out_dir = "/tmp/pneumachaos_never_created_here";
  c.threads = 5000;
  EXPECT_NE(message_of(c).find("calibrate.threads = 5000: must be <= 4096"), std::string::npos)
      << message_of(c);
}

}  // namespace
}  // namespace pneumachaos
