#include <gtest/gtest.h>

#include <sstream>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/time_series.hpp"
#include "pneumachaos/io/csv_writer.hpp"

namespace pneumachaos {
namespace {

TEST(TimeSeries, ChannelsAndTimes) {
  TimeSeries ts(1000.0, 0.5);
  ts.add_channel("v", "m/s");
  ts.add_channel("P1", "Pa");
  ts.append(std::vector<double>{0.1, 2e5});
  ts.append(std::vector<double>{0.2, 3e5});
  EXPECT_EQ(ts.size(), 2u);
  EXPECT_DOUBLE_EQ(ts.time_s(1), 0.501);
  EXPECT_EQ(ts.channel("P1").values[1], 3e5);
  EXPECT_THROW((void)ts.channel("P9"), Error);
  EXPECT_THROW(ts.append(std::vector<double>{1.0}), Error);
  EXPECT_THROW(TimeSeries(-1.0), Error);
}

TEST(CsvWriter, HeaderNamesUnitsAndNumbersRoundTrip) {
  TimeSeries ts(1000.0);
  ts.add_channel("v", "m/s");
  const double awkward = 0.1 + 0.2;  // needs 17 significant digits
  ts.append(std::vector<double>{awkward});
  std::ostringstream out;
  write_csv(out, ts);
  const std::string text = out.str();
  EXPECT_EQ(text.substr(0, text.find('\n')), "t[s],v[m/s]");
  EXPECT_EQ(std::stod(text.substr(text.find(',', text.find('\n')) + 1)), awkward);
}

}  // namespace
}  // namespace pneumachaos
