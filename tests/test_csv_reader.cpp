// Time-series input: every bad case names file, line and column.
#include <gtest/gtest.h>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/csv_reader.hpp"

namespace pneumachaos {
namespace {

std::string error_of(const std::string& text, CsvSeriesOptions o = {}) {
  try {
    parse_csv_series(text, "rec.csv", o);
  } catch (const Error& e) {
    return e.what();
  }
  return "(no error)";
}

TEST(CsvReader, ReadsAColumnByNameWithTimeOrRate) {
  const auto s =
      parse_csv_series("t[s],x[m],v[m/s]\n0,1,0.5\n0.001,2,0.25\n0.002,3,0.125\n", "rec.csv", {});
  EXPECT_EQ(s.size(), 3u);
  EXPECT_NEAR(s.rate_Hz(), 1000.0, 1e-9);
  EXPECT_EQ(s.channels().front().name, "v");
  EXPECT_EQ(s.channels().front().unit, "m/s");
  EXPECT_EQ(s.channels().front().values[2], 0.125);
  CsvSeriesOptions o;
  o.column = "speed";
  o.rate_Hz = 500.0;
  const auto r = parse_csv_series("speed\r\n1\r\n2\r\n\r\n", "rec.csv", o);
  EXPECT_EQ(r.size(), 2u);
  EXPECT_EQ(r.rate_Hz(), 500.0);
}

TEST(CsvReader, BadInputNamesTheLineAndColumn) {
  EXPECT_EQ(error_of("t,v\n0,1\n0.001,abc\n"),
            "rec.csv:3: column 2 (v): expected a number, got \"abc\"");
  EXPECT_EQ(error_of("t,v\n0,1\n0.001,nan\n"),
            "rec.csv:3: column 2 (v): expected a finite number, got nan");
  EXPECT_EQ(error_of("t,v\n0,1\n0.001\n"), "rec.csv:3: expected 2 fields as in the header, got 1");
  EXPECT_EQ(error_of("t,v\n0,1\n0,2\n"),
            "rec.csv:3: column 1 (t): time must increase: 0 follows 0");
  EXPECT_NE(error_of("t,v\n0,1\n0.001,2\n0.003,3\n0.004,4\n").find("non-uniform sampling"),
            std::string::npos);
  EXPECT_NE(error_of("t,x\n0,1\n").find("no column \"v\""), std::string::npos);
  EXPECT_NE(error_of("v\n1\n2\n").find("give the sample rate"), std::string::npos);
  EXPECT_NE(error_of("t,v\n0,1\n").find("at least 2"), std::string::npos);
  EXPECT_NE(error_of("").find("empty"), std::string::npos);
}

}  // namespace
}  // namespace pneumachaos
