// Errors carry the field they concern as data (ErrorField, declared next to the options):
// the id a caller maps to its own names, the label and detail that make up where(). The
// command line maps ids to flags (apps/pneumachaos/flag_names.cpp); these tests pin what the
// library hands it.
#include <gtest/gtest.h>

#include <functional>
#include <string>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/model/parameter_grid.hpp"
#include "pneumachaos/model/scenario.hpp"
#include "pneumachaos/model/scenario_toml.hpp"
#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos {
namespace {

Error caught(const std::function<void()>& f) {
  try {
    f();
  } catch (const Error& e) {
    return e;
  }
  ADD_FAILURE() << "no Error thrown";
  return Error("", "");
}

TEST(ErrorFields, WhereIsTheLabelThenTheDetail) {
  const Error e(SweepSpec::kRepeatsField, " 3", "must be odd");
  EXPECT_EQ(e.field(), "sweep.repeats");
  EXPECT_EQ(e.where(), "repeats 3");
  EXPECT_EQ(e.detail(), " 3");
  EXPECT_STREQ(e.what(), "repeats 3: must be odd");
  const Error plain("repeats", "must be odd");  // text alone names no field
  EXPECT_EQ(plain.field(), "");
  EXPECT_EQ(plain.detail(), "");
}

TEST(ErrorFields, GridAxisKeepsItsText) {
  const Error e = caught([] { parse_grid_axis("circuit.S1_mm2=3:2:1"); });
  EXPECT_EQ(e.field(), kGridAxisField.id);
  EXPECT_EQ(e.detail(), " circuit.S1_mm2=3:2:1");
  EXPECT_STREQ(e.what(), "grid axis circuit.S1_mm2=3:2:1: FROM 3 lies above TO 2");
  // An unknown key inside the axis: the key follows the axis text, as for a bad range.
  const Error unknown = caught([] { parse_grid_axis("circuit.S3_mm2=1:2:1"); });
  EXPECT_EQ(unknown.field(), kGridAxisField.id);
  EXPECT_EQ(unknown.detail().rfind(" circuit.S3_mm2=1:2:1: circuit.S3_mm2", 0), 0u)
      << unknown.detail();
}

TEST(ErrorFields, OverridesNameTheKeyAfterTheField) {
  Scenario s = default_scenario();
  const Error malformed = caught([&] { apply_overrides(s, {"friction.Fs_N"}); });
  EXPECT_EQ(malformed.field(), kOverrideField.id);
  EXPECT_EQ(malformed.where(), "override friction.Fs_N");
  const Error range = caught([&] { apply_overrides(s, {"friction.Fs_N=-1"}); });
  EXPECT_EQ(range.field(), kOverrideField.id);
  EXPECT_EQ(range.detail(), ": friction.Fs_N");
  // A cross-key check after every override names the override too (validate_scenario).
  SettingOrigins origins;
  Scenario bad = default_scenario();
  apply_overrides(bad, {"cylinder.rod_mm=60", "cylinder.bore_mm=40"}, &origins);
  const Error cross = caught([&] { validate_scenario(bad, origins); });
  EXPECT_EQ(cross.field(), kOverrideField.id);
  EXPECT_EQ(cross.where().rfind("override: cylinder.", 0), 0u) << cross.where();
}

TEST(ErrorFields, SweepAndWindowFields) {
  SweepSpec spec;
  EXPECT_EQ(caught([&] { spec.validate(); }).field(), kGridField.id);  // no axis
  spec.axes = {parse_grid_axis("circuit.S2_mm2=0.05:0.35:0.15")};
  spec.repeats = 0;
  EXPECT_EQ(caught([&] { spec.validate(); }).field(), SweepSpec::kRepeatsField.id);
  spec.repeats = 1;
  spec.adaptive.enabled = true;  // one axis
  EXPECT_EQ(caught([&] { spec.validate(); }).field(), AdaptiveSpec::kEnabledField.id);
  TimeSeries series(10.0);
  series.add_channel("v", "m/s", {1.0, 2.0, 3.0});
  EXPECT_EQ(caught([&] { time_window(series, 5.0, std::nullopt); }).field(),
            kWindowFromField.id);
  EXPECT_EQ(caught([&] { time_window(series, std::nullopt, 0.05); }).field(), kWindowToField.id);
}

}  // namespace
}  // namespace pneumachaos
