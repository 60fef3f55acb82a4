// The run panel's traces (src/report/run_traces.cpp): the quantised series the page decodes
// and the decimation that keeps a record's shape.
#include <gtest/gtest.h>

#include <cmath>
#include <string>
#include <vector>

#include "report/run_traces.hpp"

namespace pneumachaos {
namespace {

// The page's decoder (src/report/assets/report_charts.js), here to check the encoder.
std::vector<double> decode(const std::string& q, double lo, double hi) {
  const std::string a = "ABCDEFGHIJKLMNOPQRSTUVWXYZabcdefghijklmnopqrstuvwxyz0123456789+/";
  std::vector<double> out;
  for (std::size_t k = 0; k + 1 < q.size(); k += 2)
    out.push_back(lo +
                  (hi - lo) * static_cast<double>(a.find(q[k]) * 64 + a.find(q[k + 1])) / 4095.0);
  return out;
}

TEST(RunTraces, QuantisedSeriesDecodeWithinHalfALevel) {
  const std::vector<double> x = {-0.02, 0.0, 0.1, 0.29, 0.123456};
  double lo = 0.0, hi = 0.0;
  const std::string q = quantise_series(x, lo, hi);
  EXPECT_EQ(q.size(), 2 * x.size());
  EXPECT_EQ(lo, -0.02);
  EXPECT_EQ(hi, 0.29);
  const std::vector<double> back = decode(q, lo, hi);
  ASSERT_EQ(back.size(), x.size());
  for (std::size_t k = 0; k < x.size(); ++k) EXPECT_NEAR(back[k], x[k], 0.5 * 0.31 / 4095);
  EXPECT_EQ(back.front(), lo);
  EXPECT_EQ(back.back() > 0.1, true);
}

TEST(RunTraces, ConstantAndNonFiniteSeriesStayDecodable) {
  double lo = 1.0, hi = 1.0;
  EXPECT_EQ(quantise_series({2.0, 2.0}, lo, hi), "AAAA");
  EXPECT_EQ(lo, 2.0);
  EXPECT_EQ(hi, 2.0);
  EXPECT_EQ(quantise_series({NAN, 1.0, 3.0}, lo, hi), "AAAA//");
}

TEST(RunTraces, MinMaxDecimationKeepsEachPartsExtremesInOrder) {
  std::vector<double> x(1000);
  for (std::size_t k = 0; k < x.size(); ++k) x[k] = std::sin(0.37 * static_cast<double>(k));
  const std::vector<double> d = min_max_decimate(x, 10);
  ASSERT_EQ(d.size(), 20U);
  for (std::size_t b = 0; b < 10; ++b) {
    const auto first = x.begin() + static_cast<std::ptrdiff_t>(100 * b);
    const auto lo = std::min_element(first, first + 100), hi = std::max_element(first, first + 100);
    EXPECT_EQ(d[2 * b], lo < hi ? *lo : *hi);
    EXPECT_EQ(d[2 * b + 1], lo < hi ? *hi : *lo);
  }
  const std::vector<double> short_x = {1.0, 2.0, 3.0};
  EXPECT_EQ(min_max_decimate(short_x, 10), short_x);
}

}  // namespace
}  // namespace pneumachaos
