#include "pneumachaos/identify/measured_record_csv.hpp"

#include <fmt/format.h>

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

namespace pneumachaos::identify {
namespace {

std::string trim(std::string s) {
  const auto not_space = [](unsigned char c) { return !std::isspace(c); };
  s.erase(s.begin(), std::find_if(s.begin(), s.end(), not_space));
  s.erase(std::find_if(s.rbegin(), s.rend(), not_space).base(), s.end());
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return s;
}

std::string base_name(const std::string& header) {
  const auto bracket = header.find('[');
  return trim(bracket == std::string::npos ? header : header.substr(0, bracket));
}

std::string unit_of(const std::string& header) {
  const auto open = header.find('[');
  const auto close = header.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open) return "";
  return trim(header.substr(open + 1, close - open - 1));
}

enum class Quantity { kTime, kVelocity, kPressure, kPosition, kAcceleration };

const char* accepted_units(Quantity q) {
  switch (q) {
    case Quantity::kTime: return "s, ms";
    case Quantity::kVelocity: return "m/s, mm/s";
    case Quantity::kPressure: return "Pa, kPa, MPa, bar, psi, each optionally with \"gauge\"";
    case Quantity::kPosition: return "m, mm";
    case Quantity::kAcceleration: return "m/s^2, mm/s^2";
  }
  return "";
}

// scale to SI and, for pressures, whether the reading is gauge (ambient to be added).
struct Unit {
  double scale = 1.0;
  bool gauge = false;
};

Unit parse_unit(const std::string& text, Quantity q, const std::string& where,
                const std::string& column) {
  std::string u = text;
  Unit unit;
  if (q == Quantity::kPressure) {
    // "MPa gauge", "bar g", "kPa(g)", "psig", "Pa abs"
    std::string lower;
    for (char c : u) lower += static_cast<char>(std::tolower(static_cast<unsigned char>(c)));
    for (const char* marker : {" gauge", "(gauge)", " (g)", "(g)", " g", " abs", "(abs)", " absolute"}) {
      const std::string m = marker;
      if (lower.size() > m.size() && lower.ends_with(m)) {
        unit.gauge = m.find('g') != std::string::npos;
        u = trim(u.substr(0, u.size() - m.size()));
        break;
      }
    }
    if (u == "psig") {
      unit.gauge = true;
      u = "psi";
    }
  }
  u = trim(u);
  const auto is = [&](std::initializer_list<const char*> names) {
    return std::any_of(names.begin(), names.end(), [&](const char* n) { return u == n; });
  };
  bool known = true;
  switch (q) {
    case Quantity::kTime:
      if (u.empty() || is({"s"})) unit.scale = 1.0;
      else if (is({"ms"})) unit.scale = 1e-3;
      else known = false;
      break;
    case Quantity::kVelocity:
      if (u.empty() || is({"m/s"})) unit.scale = 1.0;
      else if (is({"mm/s"})) unit.scale = 1e-3;
      else known = false;
      break;
    case Quantity::kPressure:
      if (u.empty() || is({"Pa"})) unit.scale = 1.0;
      else if (is({"kPa"})) unit.scale = 1e3;
      else if (is({"MPa"})) unit.scale = 1e6;
      else if (is({"bar"})) unit.scale = 1e5;
      else if (is({"psi"})) unit.scale = 6894.757293168;
      else known = false;
      break;
    case Quantity::kPosition:
      if (u.empty() || is({"m"})) unit.scale = 1.0;
      else if (is({"mm"})) unit.scale = 1e-3;
      else known = false;
      break;
    case Quantity::kAcceleration:
      if (u.empty() || is({"m/s^2", "m/s2", "m/s/s"})) unit.scale = 1.0;
      else if (is({"mm/s^2", "mm/s2"})) unit.scale = 1e-3;
      else known = false;
      break;
  }
  if (!known)
    throw Error(where, fmt::format("column {}: unit \"{}\" is not understood; expected {}", column,
                                   text, accepted_units(q)));
  return unit;
}

// The lines of a record, numbered as in the file; blank lines and '#' comments skipped.
class LineSource {
 public:
  explicit LineSource(const std::string& text) : in_(text) {}
  bool next(std::string& line) {
    while (std::getline(in_, line)) {
      ++number_;
      if (!line.empty() && line.back() == '\r') line.pop_back();
      const std::string t = trim(line);
      if (!t.empty() && t.front() != '#') return true;
    }
    return false;
  }
  [[nodiscard]] std::size_t number() const { return number_; }

 private:
  std::istringstream in_;
  std::size_t number_ = 0;
};

struct ColumnSpec {
  ColumnSpec(const char* r, Quantity q) : role(r), quantity(q) {}
  const char* role;  // t, v, P1, ...
  Quantity quantity;
  int index = -1;
  Unit unit;
  std::vector<double> values;
};

int find_column(const std::vector<std::string>& names, const std::vector<std::string>& wanted) {
  for (const auto& w : wanted) {
    if (w.empty()) continue;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == w || base_name(names[i]) == w) return static_cast<int>(i);
  }
  return -1;
}

double parse_cell(const std::string& f, const std::string& where) {
  double v = 0.0;
  const char* end = f.data() + f.size();
  const auto [ptr, ec] = std::from_chars(f.data(), end, v);
  if (ec == std::errc::result_out_of_range && ptr == end)
    throw Error(where, fmt::format("{} is outside the range of a double", f));
  if (ec != std::errc() || ptr != end || f.empty())
    throw Error(where, fmt::format("expected a number, got \"{}\"", f));
  if (!std::isfinite(v)) throw Error(where, fmt::format("expected a finite number, got {}", f));
  return v;
}

}  // namespace

MeasuredRecord parse_measured_record(const std::string& text, const std::string& origin,
                                     const RecordColumns& names,
                                     const RecordReadOptions& options) {
  constexpr std::string_view kBom = "\xEF\xBB\xBF";
  LineSource lines(text.starts_with(kBom) ? text.substr(kBom.size()) : text);
  std::string line;
  if (!lines.next(line)) throw Error(origin, "the file is empty: expected a header line");
  const std::size_t header_line = lines.number();
  const std::string header_where = fmt::format("{}:{}", origin, header_line);
  if (line.find(',') == std::string::npos)
    throw Error(header_where, "expected a comma-separated header such as t[s],v[m/s],P1[Pa],P2[Pa]");
  std::vector<std::string> header;
  for (const auto& f : split_csv_fields(line)) header.push_back(trim(f));

  ColumnSpec t{"t", Quantity::kTime}, v{"v", Quantity::kVelocity}, p1{"P1", Quantity::kPressure},
      p2{"P2", Quantity::kPressure}, x{"x", Quantity::kPosition}, a{"a", Quantity::kAcceleration};
  t.index = find_column(header, {names.t, "t", "time"});
  v.index = find_column(header, {names.v});
  p1.index = find_column(header, {names.P1});
  p2.index = find_column(header, {names.P2});
  x.index = find_column(header, {names.x});
  a.index = find_column(header, {names.a});
  std::string listed;
  for (const auto& h : header) listed += (listed.empty() ? "" : ", ") + h;
  std::vector<std::string> missing;
  if (t.index < 0) missing.push_back(fmt::format("\"{}\" (time)", names.t));
  if (v.index < 0) missing.push_back(fmt::format("\"{}\" (velocity; --column-v)", names.v));
  if (p1.index < 0) missing.push_back(fmt::format("\"{}\" (pressure 1; --column-P1)", names.P1));
  if (p2.index < 0) missing.push_back(fmt::format("\"{}\" (pressure 2; --column-P2)", names.P2));
  if (!missing.empty()) {
    std::string m;
    for (const auto& s : missing) m += (m.empty() ? "" : ", ") + s;
    throw Error(header_where, fmt::format("missing column{} {}; the header has: {}",
                                          missing.size() > 1 ? "s" : "", m, listed));
  }
  std::vector<ColumnSpec*> cols{&t, &v, &p1, &p2};
  if (x.index >= 0) cols.push_back(&x);
  if (a.index >= 0) cols.push_back(&a);
  for (ColumnSpec* c : cols) {
    const std::string& h = header[static_cast<std::size_t>(c->index)];
    c->unit = parse_unit(unit_of(h), c->quantity,
                         fmt::format("{}:{}:{}", origin, header_line, c->index + 1), h);
    if (c->unit.gauge && c->quantity != Quantity::kPressure)
      throw Error(header_where, fmt::format("column {}: only pressures can be gauge", h));
  }

  std::vector<std::size_t> line_of;
  while (lines.next(line)) {
    const std::size_t n = lines.number();
    const auto fields = split_csv_fields(line);
    if (fields.size() != header.size())
      throw Error(fmt::format("{}:{}", origin, n),
                  fmt::format("expected {} fields as in the header, got {}", header.size(),
                              fields.size()));
    for (ColumnSpec* c : cols) {
      const auto i = static_cast<std::size_t>(c->index);
      const std::string where = fmt::format("{}:{}:{} ({})", origin, n, i + 1, header[i]);
      double value = parse_cell(trim(fields[i]), where) * c->unit.scale;
      if (c->quantity == Quantity::kPressure) {
        if (c->unit.gauge) value += options.ambient_Pa;
        if (value < 0.0)
          throw Error(where, fmt::format("absolute pressure {} Pa is below zero{}", value,
                                         c->unit.gauge ? "" : " (is the column gauge? mark its "
                                                             "unit, e.g. [MPa gauge])"));
        if (value > kMaxRecordPressurePa)
          throw Error(where, fmt::format("absolute pressure {} Pa is above {} MPa: wrong unit?",
                                         value, kMaxRecordPressurePa * 1e-6));
      }
      c->values.push_back(value);
    }
    line_of.push_back(n);
    const std::size_t k = t.values.size();
    if (k >= 2 && !(t.values[k - 1] > t.values[k - 2]))
      throw Error(fmt::format("{}:{}:{} ({})", origin, n, t.index + 1,
                              header[static_cast<std::size_t>(t.index)]),
                  fmt::format("time must increase: {} follows {}", fields[static_cast<std::size_t>(t.index)],
                              t.values[k - 2] / t.unit.scale));
  }
  constexpr std::size_t kMinSamples = 100;
  if (t.values.size() < kMinSamples)
    throw Error(origin, fmt::format("{} samples; at least {} are needed", t.values.size(),
                                    kMinSamples));
  // Uniform sampling: every step within 1 % of the median step (A/D timestamps jitter a
  // little and are printed rounded; a lost sample is a step of 2, a repeated one of 0).
  const std::size_t count = t.values.size();
  const double dt = (t.values.back() - t.values.front()) / double(count - 1);
  {
    std::vector<double> steps(count - 1);
    for (std::size_t i = 1; i < count; ++i) steps[i - 1] = t.values[i] - t.values[i - 1];
    std::nth_element(steps.begin(), steps.begin() + static_cast<std::ptrdiff_t>(steps.size() / 2),
                     steps.end());
    const double typical = steps[steps.size() / 2];
    for (std::size_t i = 1; i < count; ++i) {
      const double step = t.values[i] - t.values[i - 1];
      if (std::abs(step - typical) > 1e-2 * typical)
        throw Error(fmt::format("{}:{}", origin, line_of[i]),
                    fmt::format("time is not uniform: step {} s where the record's usual step is "
                                "{} s (a lost or repeated sample?)",
                                step, typical));
    }
  }
  // A velocity in the wrong unit (mm/s labelled m/s) travels far beyond the stroke.
  if (options.stroke_m) {
    const double limit = 1.5 * *options.stroke_m + 0.01;
    double s = 0.0, lo = 0.0, hi = 0.0;
    for (std::size_t i = 1; i < count; ++i) {
      s += 0.5 * (v.values[i] + v.values[i - 1]) * dt;
      lo = std::min(lo, s);
      hi = std::max(hi, s);
      if (hi - lo > limit)
        throw Error(fmt::format("{}:{}:{} ({})", origin, line_of[i], v.index + 1,
                                header[static_cast<std::size_t>(v.index)]),
                    fmt::format("the velocity integrates to a travel of {:.3g} m by here, more "
                                "than the stroke ({:.3g} m) allows: is the unit right (m/s vs "
                                "mm/s)?",
                                hi - lo, *options.stroke_m));
    }
  }
  MeasuredRecord r;
  r.source = origin;
  r.t_s = std::move(t.values);
  r.v_m_per_s = std::move(v.values);
  r.p1_Pa = std::move(p1.values);
  r.p2_Pa = std::move(p2.values);
  if (x.index >= 0) r.x_m = std::move(x.values);
  if (a.index >= 0) r.a_m_per_s2 = std::move(a.values);
  check_measured_record(r, kMinSamples);
  return r;
}

MeasuredRecord read_measured_record(const std::string& path, const RecordColumns& names,
                                    const RecordReadOptions& options) {
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
