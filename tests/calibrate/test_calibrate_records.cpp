// calibrate's records objective (docs/guide/calibrate.md, "Measured records"): a record made by
// the model itself at a known Coulomb friction, degraded as an A/D rig degrades it, is matched
// best at that friction, and the optimizer finds its basin. The spec's checks of records:
// tests/calibrate/test_calibrate.cpp.
#include <gtest/gtest.h>

#include <unistd.h>

#include <cmath>
#include <filesystem>
#include <fmt/format.h>
#include <fstream>

#include "calibrate/evaluator.hpp"
#include "identify/fit_synthetic.hpp"
#include "pneumachaos/calibrate/calibrate.hpp"
#include "pneumachaos/calibrate/calibration_spec.hpp"
#include "pneumachaos/model/scenario_keys.hpp"
#include "support/variant_scenarios.hpp"

namespace pneumachaos {
namespace {

const std::string kFree =
    "[[free]]\nkey = \"friction.Fc_N\"\nlower = 15\nupper = 35\nsource = \"a catalogue\"\n";
// On the compliant-mount rig's cylinder, supply and Fs (the built-in rig's Fs, 31.9 N, is
// below the free Fc's upper end).
const std::string kFixed = "[fixed]\nload.coupling = \"rigid\"\nfriction.model = \"stribeck\"\n" +
                           kCompliantMountFixed;

std::string write_record(const identify::MeasuredRecord& r, const std::string& path) {
  std::ofstream out(path);
  out << "t[s],v[m/s],P1[Pa],P2[Pa]\n";
  for (std::size_t i = 0; i < r.size(); ++i)
    out << fmt::format("{},{},{},{}\n", r.t_s[i], r.v_m_per_s[i], r.p1_Pa[i], r.p2_Pa[i]);
  return path;
}

std::string records_objective(const std::string& file) {
  return "[objective]\nkind = \"records\"\nrecords = [ { file = \"" + file +
         "\", S1_mm2 = 2.7, S2_mm2 = 0.35, Ps_MPa = 0.25, m_kg = 1.5 } ]\n";
}

TEST(CalibrationRecords, TheModelsOwnRecordIsMatchedBestAtItsFrictionAndFound) {
  const std::string dir = (std::filesystem::temp_directory_path() /
                           fmt::format("pneumachaos_records_{}", ::getpid())).string();
  std::filesystem::remove_all(dir);
  std::filesystem::create_directories(dir);
  const std::string file = dir + "/record.csv";
  const CalibrationSpec spec = parse_calibration_spec(
      kFree + kFixed + records_objective(file) +
          "[optimizer]\nalgorithm = \"cmaes\"\npopulation = 6\nmax_evaluations = 60\nseed = 1\n",
      "spec.toml");
  // The "measurement": the rig at Fc = 25 N under the record's conditions, 3 s at 1 kHz with
  // 300 Pa and 0.5 mm/s of noise and 12-bit channels.
  Scenario truth = spec.base;
  apply_setting(truth, "friction.Fc_N", 25.0, "test");
  apply_setting(truth, "circuit.S1_mm2", 2.7, "test");
  apply_setting(truth, "circuit.S2_mm2", 0.35, "test");
  apply_setting(truth, "supply.pressure_MPa", 0.25, "test");
  truth.set_total_moving_mass(1.5);
  const identify::MeasuredRecord record = identify::synthetic_record(truth, 3.0, {}, 5);
  write_record(record, file);

  const detail::Evaluator ev(spec, {1, 1}, std::nullopt, {record});
  const auto error_at = [&](double Fc) { return ev.evaluate({(Fc - 15.0) / 20.0}, dir).terms[0]; };
  // Near the truth the error falls to the noise's level only within a fraction of a newton (a
  // slip moves in or out of a segment): 0.34 at 25 N, about 1 at 24 and 25.5 N, 2.7 at 20 N.
  const double at_truth = error_at(25.0), low_end = error_at(15.0), high_end = error_at(35.0);
  EXPECT_LT(at_truth, 0.5 * low_end);  // 10 N off: clearly worse (the check can fail)
  EXPECT_LT(at_truth, 0.5 * high_end);

  CalibrateOptions o;
  o.out_dir = dir + "/out";
  o.threads = 1;
  o.progress = false;
  const CalibrationResult r = calibrate(spec, o);
  // The optimizer finds the truth's basin (within 1 N) though not necessarily its narrow
  // bottom: `fit` from the best point refines it (docs/guide/calibrate.md).
  EXPECT_NEAR(r.best_values[0], 25.0, 1.0);
  ASSERT_EQ(r.record_errors.size(), 1u);
  EXPECT_LT(r.record_errors[0], 0.5 * std::min(low_end, high_end));
  // The file read back gives the record's error at the same point.
  EXPECT_NEAR(r.record_errors[0], error_at(r.best_values[0]), 1e-6 * r.record_errors[0]);
  std::filesystem::remove_all(dir);
}

}  // namespace
}  // namespace pneumachaos
