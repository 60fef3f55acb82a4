// The one unit reader of every record: units parsed from headers or --units entries, converted
// to SI, and values no rig produces refused with the likely mistake named.

#include <gtest/gtest.h>

#include <optional>
#include <string>
#include <vector>

#include "support/error_text.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/column_units.hpp"

using namespace pneumachaos;

TEST(ColumnUnits, EveryAcceptedUnitIsReadToSI) {
  const auto scale = [](const char* text, Quantity q) {
    return parse_unit(text, q, "c", "f").scale;
  };
  EXPECT_DOUBLE_EQ(scale("s", Quantity::kTime), 1.0);
  EXPECT_DOUBLE_EQ(scale("ms", Quantity::kTime), 1e-3);
  EXPECT_DOUBLE_EQ(scale("us", Quantity::kTime), 1e-6);
  EXPECT_DOUBLE_EQ(scale("mm/s", Quantity::kVelocity), 1e-3);
  EXPECT_DOUBLE_EQ(scale("kPa", Quantity::kPressure), 1e3);
  EXPECT_DOUBLE_EQ(scale("MPa", Quantity::kPressure), 1e6);
  EXPECT_DOUBLE_EQ(scale("bar", Quantity::kPressure), 1e5);
  EXPECT_DOUBLE_EQ(scale("N", Quantity::kForce), 1.0);
  EXPECT_DOUBLE_EQ(scale("", Quantity::kPressure), 1.0);  // no unit: SI
  for (const char* gauge : {"kPa g", "kPa gauge", "kPa(g)", "kPa (g)"}) {
    const ColumnUnit u = parse_unit(gauge, Quantity::kPressure, "P1", "f");
    EXPECT_TRUE(u.gauge) << gauge;
    EXPECT_DOUBLE_EQ(u.scale, 1e3) << gauge;
  }
  EXPECT_FALSE(parse_unit("kPa abs", Quantity::kPressure, "P1", "f").gauge);
  // With no quantity expected (the analysed column) a known unit is recognised, another kept.
  EXPECT_EQ(parse_unit("kPa g", std::nullopt, "P1", "f").quantity, Quantity::kPressure);
  const ColumnUnit volts = parse_unit("V", std::nullopt, "u", "f");
  EXPECT_EQ(volts.quantity, Quantity::kOther);
  EXPECT_EQ(volts.text, "V");
}

TEST(ColumnUnits, UnknownUnitIsRefusedNamingTheColumn) {
  const std::string m =
      error_of([] { parse_unit("min", Quantity::kTime, "t[min]", "rec.csv:1:1"); });
  EXPECT_NE(m.find("rec.csv:1:1"), std::string::npos) << m;
  EXPECT_NE(m.find("column t[min]"), std::string::npos) << m;
  EXPECT_NE(m.find("s, ms, us"), std::string::npos) << m;
  EXPECT_NE(error_of([] { parse_unit("m/s g", std::nullopt, "v", "f"); }), "(no error)");
}

TEST(ColumnUnits, OverridesFillHeadersWithoutBrackets) {
  const UnitOverrides o = parse_unit_overrides({"t=ms", "P1=kPa g"}, "--units");
  const auto units = header_units({"t", "v[mm/s]", "P1"}, o, "rec.csv:1");
  EXPECT_EQ(units, (std::vector<std::string>{"ms", "mm/s", "kPa g"}));
  EXPECT_NE(error_of([&] { header_units({"t[s]"}, o, "rec.csv:1"); }).find("lacks"),
            std::string::npos);
  const std::string twice = error_of([] { header_units({"t[s]"}, {{"t", "ms"}}, "rec.csv:1"); });
  EXPECT_NE(twice.find("states its unit in brackets"), std::string::npos) << twice;
  EXPECT_NE(error_of([] { parse_unit_overrides({"t"}, "--units"); }).find("--units"),
            std::string::npos);
  EXPECT_NE(error_of([] { parse_unit_overrides({"t=s", "t=ms"}, "--units"); }), "(no error)");
}

TEST(ColumnUnits, ImplausibleValuesNameTheLikelyMistake) {
  const ColumnUnit pa = parse_unit("Pa", Quantity::kPressure, "P1[Pa]", "f");
  PlausibleRange range;
  EXPECT_EQ(implausible_value(101325.0, pa, "P1[Pa]", range), "");
  // kPa written under [Pa], and gauge values under [Pa]: both read far below the atmosphere.
  const std::string kpa = implausible_value(351.0, pa, "P1[Pa]", range);
  EXPECT_NE(kpa.find("look like gauge values or kPa"), std::string::npos) << kpa;
  EXPECT_NE(kpa.find("P1[kPa]"), std::string::npos) << kpa;
  EXPECT_NE(implausible_value(0.0, pa, "P1[Pa]", range), "");
  range.supply_Pa = 0.6e6;
  EXPECT_EQ(implausible_value(0.7e6, pa, "P1[Pa]", range), "");  // a meter-out rod side
  EXPECT_NE(implausible_value(1.3e6, pa, "P1[Pa]", range).find("supply"), std::string::npos);
  const ColumnUnit ms = parse_unit("m/s", Quantity::kVelocity, "v[m/s]", "f");
  EXPECT_EQ(implausible_value(-9.0, ms, "v[m/s]", range), "");
  EXPECT_NE(implausible_value(-35.0, ms, "v[m/s]", range).find("look like mm/s"),
            std::string::npos);
}

TEST(ColumnUnits, ScaleNamesItsUnit) {
  EXPECT_EQ(unit_with_scale(Quantity::kTime, 1e-3), "ms");
  EXPECT_EQ(unit_with_scale(Quantity::kTime, 1.0005e-6), "us");
  EXPECT_EQ(unit_with_scale(Quantity::kTime, 2.0), "");
}
