#include "pneumachaos/io/csv_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <sstream>
#include <string_view>
#include <vector>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {
namespace {

std::string trim(std::string s) {
  const auto not_space = [](unsigned char c) { return !std::isspace(c); };
  s.erase(s.begin(), std::find_if(s.begin(), s.end(), not_space));
  s.erase(std::find_if(s.rbegin(), s.rend(), not_space).base(), s.end());
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return s;
}

std::vector<std::string> split(const std::string& line) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  while (std::getline(in, field, ',')) fields.push_back(trim(field));
  if (!line.empty() && line.back() == ',') fields.emplace_back();
  return fields;
}

std::string base_name(const std::string& header) {
  const auto bracket = header.find('[');
  return trim(bracket == std::string::npos ? header : header.substr(0, bracket));
}

std::string unit_of(const std::string& header) {
  const auto open = header.find('[');
  const auto close = header.find(']');
  if (open == std::string::npos || close == std::string::npos || close < open) return "";
  return header.substr(open + 1, close - open - 1);
}

}  // namespace

TimeSeries parse_csv_series(const std::string& text, const std::string& origin,
                            const CsvSeriesOptions& options) {
  // Spreadsheet exports often start with a UTF-8 byte-order mark; it is not part of a name.
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  std::istringstream in(text.starts_with(kBom) ? text.substr(kBom.size()) : text);
  std::string line;
  std::size_t line_no = 0;
  std::vector<std::string> header;
  while (header.empty() && std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (!trim(line).empty()) header = split(line);
  }
  if (header.empty()) throw Error(origin, "the file is empty: expected a header line");
  const auto find_column = [&](const std::vector<std::string>& names) -> int {
    for (std::size_t i = 0; i < header.size(); ++i) {
      for (const auto& n : names) {
        if (header[i] == n || base_name(header[i]) == n) return static_cast<int>(i);
      }
    }
    return -1;
  };
  const int value_col = find_column({options.column});
  if (value_col < 0) {
    std::string known;
    for (const auto& h : header) known += (known.empty() ? "" : ", ") + h;
    throw Error(fmt::format("{}:{}", origin, line_no),
                fmt::format("no column \"{}\" in the header; it has: {}", options.column, known));
  }
  const int time_col = find_column({"t", "time", "time_s", "t_s"});
  if (!options.rate_Hz && time_col < 0) {
    throw Error(fmt::format("{}:{}", origin, line_no),
                "no time column (t, time, t[s]) in the header: give the sample rate (--rate)");
  }
  if (options.rate_Hz && !(std::isfinite(*options.rate_Hz) && *options.rate_Hz > 0.0)) {
    throw Error("--rate", fmt::format("must be a positive number of Hz, got {}", *options.rate_Hz));
  }

  std::vector<double> values, times;
  const auto cell = [&](const std::vector<std::string>& fields, int col) {
    const std::string& f = fields[static_cast<std::size_t>(col)];
    double v = 0.0;
    const char* end = f.data() + f.size();
    const auto [ptr, ec] = std::from_chars(f.data(), end, v);
    const std::string where = fmt::format("{}:{}: column {} ({})", origin, line_no, col + 1,
                                          header[static_cast<std::size_t>(col)]);
    if (ec == std::errc::result_out_of_range && ptr == end) {
      throw Error(where, fmt::format("{} is outside the range of a double (about 1.8e308)", f));
    }
    if (ec != std::errc() || ptr != end || f.empty()) {
      throw Error(where, fmt::format("expected a number, got \"{}\"", f));
    }
    if (!std::isfinite(v)) throw Error(where, fmt::format("expected a finite number, got {}", f));
    return v;
  };
  while (std::getline(in, line)) {
    ++line_no;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    if (trim(line).empty()) continue;
    const auto fields = split(line);
    if (fields.size() != header.size()) {
      throw Error(
          fmt::format("{}:{}", origin, line_no),
          fmt::format("expected {} fields as in the header, got {}", header.size(), fields.size()));
    }
    values.push_back(cell(fields, value_col));
    if (time_col >= 0) {
      times.push_back(cell(fields, time_col));
      if (times.size() >= 2 && !(times.back() > times[times.size() - 2])) {
        throw Error(fmt::format("{}:{}: column {} ({})", origin, line_no, time_col + 1,
                                header[static_cast<std::size_t>(time_col)]),
                    fmt::format("time must increase: {} follows {}", times.back(),
                                times[times.size() - 2]));
      }
    }
  }
  if (values.size() < 2) {
    throw Error(origin, fmt::format("{} sample(s): at least 2 are needed", values.size()));
  }

  double rate = options.rate_Hz.value_or(0.0);
  double start = 0.0;
  if (!options.rate_Hz) {
    std::vector<double> steps(times.size() - 1);
    for (std::size_t i = 1; i < times.size(); ++i) steps[i - 1] = times[i] - times[i - 1];
    std::vector<double> sorted = steps;
    std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
    const double median = sorted[sorted.size() / 2];
    for (std::size_t i = 0; i < steps.size(); ++i) {
      if (std::abs(steps[i] - median) > options.time_jitter * median) {
        // Data line of sample i+1: count from the first data line, blank lines aside.
        throw Error(fmt::format("{}: sample {} (t = {})", origin, i + 2, times[i + 1]),
                    fmt::format("non-uniform sampling: step {} s differs from the median step "
                                "{} s by more than {} %",
                                steps[i], median, options.time_jitter * 100.0));
      }
    }
    // The mean step over the record is the best estimate of the sampling period.
    rate = static_cast<double>(times.size() - 1) / (times.back() - times.front());
    start = times.front();
  }
  TimeSeries series(rate, start);
  series.add_channel(base_name(header[static_cast<std::size_t>(value_col)]),
                     unit_of(header[static_cast<std::size_t>(value_col)]));
  for (double v : values) series.append(std::span<const double>(&v, 1));
  return series;
}

TimeSeries read_csv_series(const std::string& path, const CsvSeriesOptions& options) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot open the file");
  std::ostringstream text;
  text << in.rdbuf();
  return parse_csv_series(text.str(), path, options);
}

}  // namespace pneumachaos
