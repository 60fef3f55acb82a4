// The measured-record reader: units, gauge pressures, renamed columns, and every bad input
// named by file and line.

#include <gtest/gtest.h>

#include <cmath>
#include <fmt/format.h>
#include <functional>
#include <string>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/identify/measured_record_csv.hpp"

using namespace pneumachaos;
using namespace pneumachaos::identify;

namespace {

// n rows at 1 kHz: v = 0.01 sin, P1 = 300 kPa, P2 = 200 kPa absolute, in the given units.
std::string record(const std::string& header, int n,
                   const std::function<std::string(int, double)>& row) {
  std::string s = header + "\n";
  for (int i = 0; i < n; ++i) s += row(i, i * 1e-3) + "\n";
  return s;
}

std::string si_row(int, double t) {
  return fmt::format("{},{},{},{}", t, 0.01 * std::sin(t), 300000.0, 200000.0);
}

std::string message_of(const std::string& text, const RecordColumns& names = {},
                       const RecordReadOptions& options = {}) {
  try {
    parse_measured_record(text, "rec.csv", names, options);
  } catch (const Error& e) {
    return e.what();
  }
  return "no error";
}

}  // namespace

TEST(MeasuredRecord, ReadsSimulateHeader) {
  const auto r = parse_measured_record(
      record("t[s],x[m],v[m/s],P1[Pa],P2[Pa],F_friction[N]", 200,
             [](int, double t) { return fmt::format("{},0.1,0.02,300000,200000,5", t); }),
      "rec.csv", {});
  ASSERT_EQ(r.size(), 200u);
  EXPECT_DOUBLE_EQ(r.v_m_per_s[3], 0.02);
  EXPECT_DOUBLE_EQ(r.p1_Pa[0], 300000.0);
  ASSERT_TRUE(r.x_m.has_value());
  EXPECT_FALSE(r.a_m_per_s2.has_value());
  EXPECT_NEAR(r.dt_s(), 1e-3, 1e-12);
}

TEST(MeasuredRecord, ConvertsUnitsAndGauge) {
  RecordReadOptions o;
  o.ambient_Pa = 100000.0;
  const auto r = parse_measured_record(
      record("time[ms],v[mm/s],P1[MPa gauge],P2[bar],x[mm],a[mm/s^2]", 150,
             [](int i, double) { return fmt::format("{},20,0.2,2,150,1000", i); }),
      "rec.csv", {}, o);
  EXPECT_NEAR(r.dt_s(), 1e-3, 1e-12);
  EXPECT_DOUBLE_EQ(r.v_m_per_s[0], 0.02);
  EXPECT_DOUBLE_EQ(r.p1_Pa[0], 300000.0);
  EXPECT_DOUBLE_EQ(r.p2_Pa[0], 200000.0);
  EXPECT_DOUBLE_EQ((*r.x_m)[0], 0.15);
  EXPECT_DOUBLE_EQ((*r.a_m_per_s2)[0], 1.0);
  const auto k = parse_measured_record(
      record("t[s],v[m/s],P1[kPa],P2[kPa g]", 150,
             [](int i, double t) { return fmt::format("{},0,{},100", t, 300 + i % 2); }),
      "rec.csv", {});
  EXPECT_DOUBLE_EQ(k.p1_Pa[1], 301000.0);
  EXPECT_DOUBLE_EQ(k.p2_Pa[0], 100000.0 + kStandardAmbientPa);
}

TEST(MeasuredRecord, RenamedColumns) {
  RecordColumns names;
  names.v = "vel";
  names.P1 = "pA";
  names.P2 = "pB";
  const auto r = parse_measured_record(record("t[s],vel[m/s],pA[Pa],pB[Pa]", 120, si_row),
                                       "rec.csv", names);
  EXPECT_EQ(r.size(), 120u);
}

TEST(MeasuredRecord, MissingColumnIsNamed) {
  const std::string m = message_of(record("t[s],v[m/s],P1[Pa]", 120, [](int, double t) {
    return fmt::format("{},0,300000", t);
  }));
  EXPECT_NE(m.find("rec.csv:1"), std::string::npos) << m;
  EXPECT_NE(m.find("missing column \"P2\""), std::string::npos) << m;
}

TEST(MeasuredRecord, UnknownUnit) {
  const std::string m = message_of(record("t[s],v[in/s],P1[Pa],P2[Pa]", 120, si_row));
  EXPECT_NE(m.find("rec.csv:1:2"), std::string::npos) << m;
  EXPECT_NE(m.find("in/s"), std::string::npos) << m;
}

TEST(MeasuredRecord, PressureOutOfRange) {
  std::string m = message_of(record("t[s],v[m/s],P1[Pa],P2[Pa]", 120, [](int i, double t) {
    return fmt::format("{},0,{},200000", t, i == 50 ? -5.0 : 300000.0);
  }));
  EXPECT_NE(m.find("rec.csv:52:3"), std::string::npos) << m;
  EXPECT_NE(m.find("look like gauge values or kPa"), std::string::npos) << m;
  m = message_of(record("t[s],v[m/s],P1[MPa],P2[Pa]", 120, [](int, double t) {
    return fmt::format("{},0,300000,200000", t);  // Pa labelled MPa
  }));
  EXPECT_NE(m.find("rec.csv:2:3"), std::string::npos) << m;
  EXPECT_NE(m.find("above 10 MPa"), std::string::npos) << m;
}

TEST(MeasuredRecord, VelocityTooLargeForStroke) {
  RecordReadOptions o;
  o.stroke_m = 0.5;
  // 5 mm/s written into a column labelled m/s: 5 m/s, past 1.5 strokes in 0.15 s.
  const std::string m = message_of(
      record("t[s],v[m/s],P1[Pa],P2[Pa]", 1000,
             [](int, double t) { return fmt::format("{},5,300000,200000", t); }),
      {}, o);
  EXPECT_NE(m.find("rec.csv:"), std::string::npos) << m;
  EXPECT_NE(m.find("stroke"), std::string::npos) << m;
  EXPECT_NE(m.find("mm/s"), std::string::npos) << m;
  // The same in mm/s is fine.
  EXPECT_NO_THROW(parse_measured_record(
      record("t[s],v[mm/s],P1[Pa],P2[Pa]", 1000,
             [](int, double t) { return fmt::format("{},20,300000,200000", t); }),
      "rec.csv", {}, o));
}

TEST(MeasuredRecord, NonUniformTime) {
  const std::string m = message_of(record("t[s],v[m/s],P1[Pa],P2[Pa]", 120, [](int i, double) {
    const double t = (i < 60 ? i : i + 1) * 1e-3;  // sample 61 lost
    return fmt::format("{},0,300000,200000", t);
  }));
  EXPECT_NE(m.find("rec.csv:62"), std::string::npos) << m;
  EXPECT_NE(m.find("not uniform"), std::string::npos) << m;
  const std::string back = message_of(record("t[s],v[m/s],P1[Pa],P2[Pa]", 120, [](int i, double t) {
    return fmt::format("{},0,300000,200000", i == 30 ? 0.0 : t);
  }));
  EXPECT_NE(back.find("rec.csv:32:1"), std::string::npos) << back;
}

TEST(MeasuredRecord, NaNAndWords) {
  std::string m = message_of(record("t[s],v[m/s],P1[Pa],P2[Pa]", 120, [](int i, double t) {
    return fmt::format("{},{},300000,200000", t, i == 9 ? "nan" : "0");
  }));
  EXPECT_NE(m.find("rec.csv:11:2"), std::string::npos) << m;
  m = message_of(record("t[s],v[m/s],P1[Pa],P2[Pa]", 120, [](int i, double t) {
    return fmt::format("{},0,{},200000", t, i == 9 ? "high" : "300000");
  }));
  EXPECT_NE(m.find("rec.csv:11:3"), std::string::npos) << m;
  m = message_of(record("t[s],v[m/s],P1[Pa],P2[Pa]", 120, [](int i, double t) {
    return i == 5 ? fmt::format("{},0,300000", t) : fmt::format("{},0,300000,1e5", t);
  }));
  EXPECT_NE(m.find("rec.csv:7"), std::string::npos) << m;
  m = message_of(record("t[s],v[m/s],P1[Pa],P2[Pa]", 20, si_row));
  EXPECT_NE(m.find("at least 100"), std::string::npos) << m;
}

TEST(MeasuredRecord, SpeedAboveAnyCylinder) {
  // mm/s values in a column labelled m/s: refused even without a stroke to compare with.
  const std::string m = message_of(record("t[s],v[m/s],P1[Pa],P2[Pa]", 200, [](int i, double t) {
    return fmt::format("{},{},300000,200000", t, i == 150 ? 35.0 : 0.02);
  }));
  EXPECT_NE(m.find("rec.csv:152:2"), std::string::npos) << m;
  EXPECT_NE(m.find("look like mm/s"), std::string::npos) << m;
}

TEST(MeasuredRecord, KiloPascalOrGaugeUnderPascalIsRefused) {
  // kPa values under [Pa]: 300 Pa absolute, far below the atmosphere.
  std::string m = message_of(record("t[s],v[m/s],P1[Pa],P2[Pa]", 120,
                                    [](int, double t) { return fmt::format("{},0,300,200", t); }));
  EXPECT_NE(m.find("rec.csv:2:3 (P1[Pa])"), std::string::npos) << m;
  EXPECT_NE(m.find("look like gauge values or kPa"), std::string::npos) << m;
  // Gauge values under [Pa]: chamber 2 vented to 0 Pa gauge reads 0 Pa absolute.
  m = message_of(record("t[s],v[m/s],P1[Pa],P2[Pa]", 120, [](int i, double t) {
    return fmt::format("{},0,200000,{}", t, i < 60 ? 100000.0 : 0.0);
  }));
  EXPECT_NE(m.find("rec.csv:62:4 (P2[Pa])"), std::string::npos) << m;
  // Marked gauge, the same values are read right.
  const auto r = parse_measured_record(record("t[s],v[m/s],P1[Pa g],P2[Pa g]", 120,
                                              [](int i, double t) {
                                                return fmt::format("{},0,200000,{}", t,
                                                                   i < 60 ? 100000.0 : 0.0);
                                              }),
                                       "rec.csv", {});
  EXPECT_DOUBLE_EQ(r.p2_Pa.back(), kStandardAmbientPa);
}

TEST(MeasuredRecord, AboveTheSupplyIsRefused) {
  RecordReadOptions o;
  o.plausible.supply_Pa = 0.4e6;
  const std::string m =
      message_of(record("t[s],v[m/s],P1[kPa],P2[kPa]", 120,
                        [](int, double t) { return fmt::format("{},0,900,200", t); }),
                 {}, o);
  EXPECT_NE(m.find("supply"), std::string::npos) << m;
}

TEST(MeasuredRecord, UnitsOptionFillsHeadersWithoutBrackets) {
  RecordReadOptions o;
  o.units = {{"t", "ms"}, {"P1", "kPa"}, {"P2", "kPa g"}};
  const auto r = parse_measured_record(
      record("t,v,P1,P2", 120, [](int i, double) { return fmt::format("{},0,300,100", i); }),
      "rec.csv", {}, o);
  EXPECT_NEAR(r.dt_s(), 1e-3, 1e-12);
  EXPECT_DOUBLE_EQ(r.p1_Pa[0], 300e3);
  EXPECT_DOUBLE_EQ(r.p2_Pa[0], 100e3 + kStandardAmbientPa);
}
