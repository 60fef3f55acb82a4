#include "calibrate/measured_map.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <array>
#include <fstream>
#include <map>
#include <sstream>
#include <utility>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/csv_fields.hpp"
#include "pneumachaos/io/csv_text.hpp"

namespace pneumachaos {
namespace {

constexpr std::size_t kMaxPoints = 100000;
constexpr std::array<const char*, 4> kColumns = {"S1_mm2", "S2_mm2", "stick_slip", "chaos"};

std::array<int, 4> header_columns(const std::string& line, const std::string& where) {
  std::vector<std::string> names;
  for (std::string f : split_csv_fields(line)) names.push_back(trim_field(f));
  std::array<int, 4> at{};
  for (std::size_t i = 0; i < kColumns.size(); ++i) {
    at[i] = find_column(names, {kColumns[i]});
    if (at[i] < 0)
      throw Error(where, fmt::format("no column {} (expected the columns S1_mm2, S2_mm2, "
                                     "stick_slip, chaos){}",
                                     kColumns[i], separator_hint(names)));
  }
  return at;
}

std::vector<double> sorted_unique(std::vector<double> x) {
  std::sort(x.begin(), x.end());
  x.erase(std::unique(x.begin(), x.end()), x.end());
  return x;
}

}  // namespace

MeasuredMap parse_measured_map(const std::string& text, const std::string& origin) {
  CsvLines lines(text);
  std::string line;
  if (!lines.next(line)) throw Error(origin, "empty: expected a header and one row per point");
  const auto cols = header_columns(line, fmt::format("{}:{}", origin, lines.number()));
  const std::size_t fields = split_csv_fields(line).size();
  std::map<std::pair<double, double>, std::pair<double, double>> points;
  std::map<std::pair<double, double>, std::size_t> first_line;
  while (lines.next(line)) {
    const std::string where = fmt::format("{}:{}", origin, lines.number());
    const std::vector<std::string> f = split_csv_fields(line);
    if (f.size() != fields)
      throw Error(where, fmt::format("expected {} fields, got {}", fields, f.size()));
    std::array<double, 4> v{};
    for (std::size_t i = 0; i < v.size(); ++i) {
      const std::string cell_at = fmt::format("{} column {}", where, kColumns[i]);
      v[i] = parse_cell(f[static_cast<std::size_t>(cols[i])], cell_at);
      const bool ok = i < 2 ? v[i] > 0.0 && v[i] <= 1000.0 : v[i] >= 0.0 && v[i] <= 1.0;
      if (!ok)
        throw Error(cell_at, fmt::format("{} is out of range: expected {}", v[i],
                                         i < 2 ? "an area > 0 and <= 1000 mm^2" : "0 to 1"));
    }
    const auto key = std::make_pair(v[0], v[1]);
    if (!points.emplace(key, std::make_pair(v[2], v[3])).second)
      throw Error(where, fmt::format("the point S1 = {}, S2 = {} is given twice (first on line {})",
                                     v[0], v[1], first_line[key]));
    first_line[key] = lines.number();
    if (points.size() > kMaxPoints)
      throw Error(where, fmt::format("more than {} points", kMaxPoints));
  }
  if (points.empty()) throw Error(origin, "no data rows");
  MeasuredMap m;
  std::vector<double> s1, s2;
  for (const auto& [k, _] : points) {
    s1.push_back(k.first);
    s2.push_back(k.second);
  }
  m.s1 = sorted_unique(s1);
  m.s2 = sorted_unique(s2);
  if (m.s1.size() * m.s2.size() != points.size())
    throw Error(origin, fmt::format("the rows do not fill the grid of their {} S1 x {} S2 values "
                                    "({} of {} points given)",
                                    m.s1.size(), m.s2.size(), points.size(),
                                    m.s1.size() * m.s2.size()));
  for (const auto& [k, inc] : points) {  // std::map: S1 ascending, then S2 ascending
    m.stick_slip.push_back(inc.first);
    m.chaos.push_back(inc.second);
  }
  return m;
}

MeasuredMap read_measured_map(const std::string& path) {
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot open the measured map");
  std::stringstream text;
  text << in.rdbuf();
  return parse_measured_map(text.str(), path);
}

}  // namespace pneumachaos
