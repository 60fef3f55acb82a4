#include "pneumachaos/identify/measured_record_csv.hpp"

#include <fmt/format.h>
#include <fmt/ranges.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string_view>
#include <vector>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/csv_fields.hpp"
#include "pneumachaos/io/csv_text.hpp"

namespace pneumachaos::identify {
namespace {

struct ColumnSpec {
  ColumnSpec(const char* r, Quantity q) : role(r), quantity(q) {}
  const char* role;  // t, v, P1, ...
  Quantity quantity;
  int index = -1;
  ColumnUnit unit;
  std::vector<double> values;
};

// The columns of a record as the header names them.
struct ColumnSet {
  std::vector<std::string> header;
  ColumnSpec t{"t", Quantity::kTime}, v{"v", Quantity::kVelocity}, p1{"P1", Quantity::kPressure},
      p2{"P2", Quantity::kPressure}, x{"x", Quantity::kPosition}, a{"a", Quantity::kAcceleration};
  std::vector<ColumnSpec*> used() {
    std::vector<ColumnSpec*> cols{&t, &v, &p1, &p2};
    if (x.index >= 0) cols.push_back(&x);
    if (a.index >= 0) cols.push_back(&a);
    return cols;
  }
  [[nodiscard]] std::string cell(const std::string& origin, std::size_t line, const ColumnSpec& c) const {
    const auto i = static_cast<std::size_t>(c.index);
    return fmt::format("{}:{}:{} ({})", origin, line, i + 1, header[i]);
  }
};

// Finds every column by name and reads its unit; the missing ones are all named at once.
void locate_columns(ColumnSet& c, const RecordColumns& names, const std::string& origin,
                    std::size_t header_line, const RecordReadOptions& options) {
  const std::string where = fmt::format("{}:{}", origin, header_line);
  const auto& h = c.header;
  c.t.index = find_column(h, {names.t, "t", "time"});
  c.v.index = find_column(h, {names.v});
  c.p1.index = find_column(h, {names.P1});
  c.p2.index = find_column(h, {names.P2});
  c.x.index = find_column(h, {names.x});
  c.a.index = find_column(h, {names.a});
  std::vector<std::string> missing;
  if (c.t.index < 0) missing.push_back(fmt::format("\"{}\" (time)", names.t));
  if (c.v.index < 0) missing.push_back(fmt::format("\"{}\" (velocity; --column-v)", names.v));
  if (c.p1.index < 0) missing.push_back(fmt::format("\"{}\" (pressure 1; --column-P1)", names.P1));
  if (c.p2.index < 0) missing.push_back(fmt::format("\"{}\" (pressure 2; --column-P2)", names.P2));
  if (!missing.empty())
    throw Error(where, fmt::format("missing column{} {}; the header has: {}{}",
                                   missing.size() > 1 ? "s" : "", fmt::join(missing, ", "),
                                   fmt::join(h, ", "), separator_hint(h)));
  const std::vector<std::string> units = header_units(h, options.units, where);
  for (ColumnSpec* col : c.used()) {
    const auto i = static_cast<std::size_t>(col->index);
    col->unit = parse_unit(units[i], col->quantity, h[i],
                           fmt::format("{}:{}:{}", origin, header_line, i + 1));
  }
}

// One cell in SI units, absolute pressure, checked for what no rig can produce.
double read_cell(const std::string& field, const ColumnSpec& c, const RecordReadOptions& options,
                 const std::string& where, const std::string& column) {
  double value = parse_cell(trim_field(field), where) * c.unit.scale;
  if (c.unit.gauge) value += options.ambient_Pa;
  const std::string problem = implausible_value(value, c.unit, column, options.plausible);
  if (!problem.empty()) throw Error(where, problem);
  return value;
}

// Every data line into the columns; returns the file line of each sample.
std::vector<std::size_t> read_rows(CsvLines& lines, ColumnSet& c, const std::string& origin,
                                   const RecordReadOptions& options) {
  std::vector<std::size_t> line_of;
  std::string line;
  while (lines.next(line)) {
    const std::size_t n = lines.number();
    const auto fields = split_csv_fields(line);
    if (fields.size() != c.header.size())
      throw Error(fmt::format("{}:{}", origin, n),
                  fmt::format("expected {} fields as in the header, got {}", c.header.size(),
                              fields.size()));
    for (ColumnSpec* col : c.used())
      col->values.push_back(read_cell(fields[static_cast<std::size_t>(col->index)], *col, options,
                                      c.cell(origin, n, *col),
                                      c.header[static_cast<std::size_t>(col->index)]));
    line_of.push_back(n);
    const auto& t = c.t.values;
    const std::size_t k = t.size();
    if (k >= 2 && !(t[k - 1] > t[k - 2]))
      throw Error(c.cell(origin, n, c.t),
                  fmt::format("time must increase: {} follows {}",
                              fields[static_cast<std::size_t>(c.t.index)], t[k - 2] / c.t.unit.scale));
  }
  return line_of;
}

// Uniform sampling: every step within 1 % of the median step (A/D timestamps jitter a little
// and are printed rounded; a lost sample is a step of 2, a repeated one of 0).
void check_uniform_time(const std::vector<double>& t, const std::vector<std::size_t>& line_of,
                        const std::string& origin) {
  std::vector<double> steps(t.size() - 1);
  for (std::size_t i = 1; i < t.size(); ++i) steps[i - 1] = t[i] - t[i - 1];
  std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                   steps.end());
  const double typical = steps[steps.size() / 2];
  for (std::size_t i = 1; i < t.size(); ++i) {
    const double step = t[i] - t[i - 1];
    if (std::abs(step - typical) > 1e-2 * typical)
      throw Error(fmt::format("{}:{}", origin, line_of[i]),
                  fmt::format("time is not uniform: step {} s where the record's usual step is "
                              "{} s (a lost or repeated sample?)",
                              step, typical));
  }
}

// A velocity in the wrong unit (mm/s labelled m/s) travels far beyond the stroke.
void check_travel(const ColumnSet& c, const std::vector<std::size_t>& line_of,
                  const std::string& origin, double stroke_m) {
  const auto& v = c.v.values;
  const double dt = (c.t.values.back() - c.t.values.front()) / double(v.size() - 1);
  const double limit = 1.5 * stroke_m + 0.01;
  double s = 0.0, lo = 0.0, hi = 0.0;
  for (std::size_t i = 1; i < v.size(); ++i) {
    s += 0.5 * (v[i] + v[i - 1]) * dt;
    lo = std::min(lo, s);
    hi = std::max(hi, s);
    if (hi - lo > limit)
      throw Error(c.cell(origin, line_of[i], c.v),
                  fmt::format("the velocity integrates to a travel of {:.3g} m by here, more "
                              "than the stroke ({:.3g} m) allows: is the unit right (m/s vs "
                              "mm/s)? (or set cylinder.stroke_mm)",
                              hi - lo, stroke_m));
  }
}

}  // namespace

MeasuredRecord parse_measured_record(const std::string& text, const std::string& origin,
                                     const RecordColumns& names,
                                     const RecordReadOptions& options) {
  options.validate();
  refuse_binary(text, origin);
  CsvLines lines(text);
  std::string line;
  if (!lines.next(line)) throw Error(origin, "the file is empty: expected a header line");
  const std::size_t header_line = lines.number();
  if (line.find(',') == std::string::npos)
    throw Error(fmt::format("{}:{}", origin, header_line),
                "expected a comma-separated header such as t[s],v[m/s],P1[Pa],P2[Pa]" +
                    separator_hint({line}));
  ColumnSet c;
  for (const auto& f : split_csv_fields(line)) c.header.push_back(trim_field(f));
  locate_columns(c, names, origin, header_line, options);
  const std::vector<std::size_t> line_of = read_rows(lines, c, origin, options);
  constexpr std::size_t kMinSamples = 100;
  if (c.t.values.size() < kMinSamples)
    throw Error(origin, fmt::format("{} samples; at least {} are needed", c.t.values.size(),
                                    kMinSamples));
  check_uniform_time(c.t.values, line_of, origin);
  if (options.stroke_m) check_travel(c, line_of, origin, *options.stroke_m);
  MeasuredRecord r;
  r.source = origin;
  r.t_s = std::move(c.t.values);
  r.v_m_per_s = std::move(c.v.values);
  r.p1_Pa = std::move(c.p1.values);
  r.p2_Pa = std::move(c.p2.values);
  if (c.x.index >= 0) r.x_m = std::move(c.x.values);
  if (c.a.index >= 0) r.a_m_per_s2 = std::move(c.a.values);
  check_measured_record(r, kMinSamples);
  return r;
}

RecordReadOptions read_options_for(const Scenario& scenario) {
  RecordReadOptions read;
  read.ambient_Pa = scenario.ambient_pressure_Pa;
  read.plausible.supply_Pa = scenario.supply_pressure_Pa();
  if (!scenario.cylinder.volumes_frozen()) read.stroke_m = scenario.cylinder.stroke_m;
  return read;
}

MeasuredRecord read_measured_record(const std::string& path, const RecordColumns& names,
                                    const RecordReadOptions& options) {
  options.validate();
  std::ostringstream text;
  if (path == "-") {
    text << std::cin.rdbuf();
    return parse_measured_record(text.str(), "<stdin>", names, options);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot open the file");
  text << in.rdbuf();
  return parse_measured_record(text.str(), path, names, options);
}

}  // namespace pneumachaos::identify
