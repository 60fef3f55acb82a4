#include "pneumachaos/io/csv_reader.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <filesystem>
#include <fstream>
#include <iostream>
#include <sstream>
#include <string_view>
#include <vector>

#include "pneumachaos/io/csv_fields.hpp"
#include "pneumachaos/io/csv_text.hpp"
#include "pneumachaos/core/error.hpp"
#include "pneumachaos/core/validation.hpp"
#include "pneumachaos/io/column_units.hpp"

namespace pneumachaos {
namespace {

// Fields of one line: comma-separated (our own CSV, spreadsheets) or, in a file without
// commas, separated by runs of blanks (TISEAN and most lab exports).
std::vector<std::string> split(const std::string& line, bool commas) {
  std::vector<std::string> fields;
  std::string field;
  std::istringstream in(line);
  if (!commas) {
    while (in >> field) fields.push_back(trim_field(field));
    return fields;
  }
  for (const std::string& f : split_csv_fields(line)) fields.push_back(trim_field(f));
  return fields;
}

// The same fields as split(), as views into `line` (no allocation per field): a string stream
// and a string per field cost 11 % of a 1e4-sample analysis (docs/notes/performance.md). Fields that start or end with a quote are left as they are for the
// caller to trim exactly as trim_field does.
void split_views(std::string_view line, bool commas, std::vector<std::string_view>& fields) {
  fields.clear();
  const auto blank = [](char c) { return std::isspace(static_cast<unsigned char>(c)) != 0; };
  const auto trimmed = [&](std::string_view f) {
    while (!f.empty() && blank(f.front())) f.remove_prefix(1);
    while (!f.empty() && blank(f.back())) f.remove_suffix(1);
    return f;
  };
  if (!commas) {
    std::size_t i = 0;
    while (true) {
      while (i < line.size() && blank(line[i])) ++i;
      if (i == line.size()) return;
      const std::size_t start = i;
      while (i < line.size() && !blank(line[i])) ++i;
      fields.push_back(line.substr(start, i - start));
    }
  }
  if (line.empty()) return;  // as split_csv_fields: no field at all
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(trimmed(line.substr(start, comma - start)));
    if (comma == std::string_view::npos) return;
    start = comma + 1;
  }
}

bool is_number(const std::string& f) {
  double v = 0.0;
  const char* end = f.data() + f.size();
  const auto [ptr, ec] = std::from_chars(f.data(), end, v);
  return !f.empty() && ptr == end && (ec == std::errc() || ec == std::errc::result_out_of_range);
}

// The column layout, from the first line: a header of names, or (all fields numbers) none,
// in which case columns are numbered from 1 and the first line is already data.
struct Layout {
  bool commas = true;
  bool has_header = true;
  std::vector<std::string> names;
  std::size_t header_line = 0;
  int value = -1, time = -1;
  ColumnUnit time_unit, value_unit;
};

// Without a header the column is given by its number (1 = first); "v", the default, means
// the first column, as in TISEAN.
int numbered_column(const std::string& column, std::size_t count, const std::string& where) {
  if (column == "v") return 0;
  int n = 0;
  const auto [ptr, ec] = std::from_chars(column.data(), column.data() + column.size(), n);
  if (ec != std::errc() || ptr != column.data() + column.size() || n < 1 ||
      static_cast<std::size_t>(n) > count) {
    throw Error(where, fmt::format("the file has no header: give --column as a number from 1 to "
                                   "{}, got \"{}\"",
                                   count, column));
  }
  return n - 1;
}

// The units of the time and analysed columns, from their brackets or --units: the clock is
// converted to seconds; the analysed values keep their unit, which only labels them, but a
// known one is checked for values no rig produces.
void read_units(Layout& l, const CsvSeriesOptions& options, const std::string& where) {
  const std::vector<std::string> units = header_units(l.names, options.units, where);
  const auto unit_of = [&](int col, std::optional<Quantity> q) {
    const auto i = static_cast<std::size_t>(col);
    return parse_unit(units[i], q, l.names[i], fmt::format("{}:{}", where, col + 1));
  };
  if (l.time >= 0) l.time_unit = unit_of(l.time, Quantity::kTime);
  l.value_unit = unit_of(l.value, std::nullopt);
}

Layout read_layout(CsvLines& lines, std::string& first, const std::string& origin,
                   const CsvSeriesOptions& options) {
  if (!lines.next(first)) throw Error(origin, "the file is empty: expected a header line");
  Layout l;
  l.commas = first.find(',') != std::string::npos;
  l.names = split(first, l.commas);
  l.header_line = lines.number();
  l.has_header = !std::all_of(l.names.begin(), l.names.end(), is_number);
  const std::string where = fmt::format("{}:{}", origin, l.header_line);
  if (!l.has_header) {
    for (std::size_t i = 0; i < l.names.size(); ++i) l.names[i] = fmt::format("column {}", i + 1);
    l.value = numbered_column(options.column, l.names.size(), where);
  } else {
    l.value = find_column(l.names, {options.column});
    l.time = find_column(l.names, {"t", "time", "time_s", "t_s"});
  }
  if (l.value < 0) {
    std::string known;
    for (const auto& h : l.names) known += (known.empty() ? "" : ", ") + h;
    const bool number = std::all_of(options.column.begin(), options.column.end(),
                                    [](unsigned char c) { return std::isdigit(c) != 0; });
    throw Error(where, fmt::format("no column \"{}\" in the header; it has: {}{}{}", options.column,
                                   known, separator_hint(l.names),
                                   number ? "; a number selects a column only in a file without a "
                                            "header: give the column's name"
                                          : ""));
  }
  if (l.has_header)
    read_units(l, options, where);
  else if (!options.units.empty())
    throw Error(where,
                "--units names columns of a header, and the file has none: give the "
                "rate (--rate) and read the values in their own unit");
  if (!options.rate_Hz && l.time < 0) {
    throw Error(where, l.has_header ? "no time column (t, time, t[s]) in the header: give the "
                                      "sample rate (--rate)"
                                    : "the file has no header and so no time column: give the "
                                      "sample rate (--rate)");
  }
  return l;
}

struct Columns {
  std::vector<double> values, times;
};

// One cell of a data line: parsed in place; anything from_chars does not take whole as a
// finite number (or a quoted cell) goes through parse_cell, which says what is wrong.
double read_cell(std::string_view field, std::size_t line_no, int col, const Layout& l,
                 const std::string& origin) {
  double v = 0.0;
  const char* end = field.data() + field.size();
  const auto [ptr, ec] = std::from_chars(field.data(), end, v);
  if (!field.empty() && ptr == end && ec == std::errc() && std::isfinite(v)) return v;
  const auto i = static_cast<std::size_t>(col);
  return parse_cell(trim_field(std::string(field)),
                    fmt::format("{}:{}: column {} ({})", origin, line_no, col + 1, l.names[i]));
}

// A value of a known unit, in SI (absolute for a gauge pressure), must be physical.
void check_plausible(double value, std::size_t line_no, const Layout& l,
                     const std::string& origin) {
  const ColumnUnit& u = l.value_unit;
  const double si = value * u.scale + (u.gauge ? kStandardAmbientPa : 0.0);
  const std::string& name = l.names[static_cast<std::size_t>(l.value)];
  const std::string problem = implausible_value(si, u, name, PlausibleRange{});
  if (!problem.empty())
    throw Error(fmt::format("{}:{}: column {} ({})", origin, line_no, l.value + 1, name), problem);
}

// One data line into the columns; time must increase.
void read_row(const std::string& line, std::size_t line_no, const Layout& l,
              const std::string& origin, Columns& c) {
  thread_local std::vector<std::string_view> fields;
  split_views(line, l.commas, fields);
  if (fields.size() != l.names.size()) {
    throw Error(fmt::format("{}:{}", origin, line_no),
                fmt::format("expected {} fields as in {}, got {}", l.names.size(),
                            l.has_header ? "the header" : "the first line", fields.size()));
  }
  const auto cell = [&](int col) {
    return read_cell(fields[static_cast<std::size_t>(col)], line_no, col, l, origin);
  };
  c.values.push_back(cell(l.value));
  if (l.value_unit.quantity != Quantity::kOther)
    check_plausible(c.values.back(), line_no, l, origin);
  if (l.time < 0) return;
  c.times.push_back(cell(l.time) * l.time_unit.scale);
  const std::size_t n = c.times.size();
  if (n >= 2 && !(c.times[n - 1] > c.times[n - 2])) {
    throw Error(fmt::format("{}:{}: column {} ({})", origin, line_no, l.time + 1,
                            l.names[static_cast<std::size_t>(l.time)]),
                fmt::format("time must increase: {} follows {}", c.times[n - 1], c.times[n - 2]));
  }
}

// The sample rate from the time column: every step within the jitter of the median step,
// and the mean step over the record as the estimate of the sampling period.
double rate_from_times(const std::vector<double>& times, const std::string& origin,
                       double jitter) {
  std::vector<double> steps(times.size() - 1);
  for (std::size_t i = 1; i < times.size(); ++i) steps[i - 1] = times[i] - times[i - 1];
  std::vector<double> sorted = steps;
  std::nth_element(sorted.begin(), sorted.begin() + sorted.size() / 2, sorted.end());
  const double median = sorted[sorted.size() / 2];
  for (std::size_t i = 0; i < steps.size(); ++i) {
    if (std::abs(steps[i] - median) > jitter * median) {
      // Data line of sample i+1: count from the first data line, blank lines aside.
      throw Error(fmt::format("{}: sample {} (t = {})", origin, i + 2, times[i + 1]),
                  fmt::format("non-uniform sampling: step {} s differs from the median step "
                              "{} s by more than {} %",
                              steps[i], median, jitter * 100.0));
    }
  }
  return static_cast<double>(times.size() - 1) / (times.back() - times.front());
}

bool same_rate(double a, double b, double jitter) { return std::abs(a - b) <= jitter * b; }

// What to do when --rate and the clock disagree: when they differ by a power of 1000 the
// clock's unit is the likely mistake (milliseconds under t[s]), and the unit it counts in is
// named; otherwise one of the two is wrong.
std::string clock_hint(const Layout& l, double file_rate_Hz, double given_rate_Hz) {
  const std::string counts =
      unit_with_scale(Quantity::kTime, l.time_unit.scale * file_rate_Hz / given_rate_Hz);
  const std::string name = header_name(l.names[static_cast<std::size_t>(l.time)]);
  if (counts.empty()) return "drop the rate option to use the time column, or correct one of them";
  return fmt::format(
      "the clock looks like it counts {0}, not {1}: head the column {2}[{0}] (or "
      "give --units {2}={0} to a header without brackets)",
      counts, l.time_unit.text.empty() ? "s" : l.time_unit.text, name);
}

// A file without a header whose analysed column is the default first one, and that first
// column rises at a constant step like a time column, is refused: analysing the clock calls
// its ramp "periodic". Naming the column (--column N) settles it either way.
void refuse_time_like_first_column(const std::vector<double>& first, const Layout& l,
                                   const std::string& origin, const CsvSeriesOptions& options) {
  if (options.column != "v" || l.names.size() < 2 || first.size() < 3) return;
  const double step = (first.back() - first.front()) / static_cast<double>(first.size() - 1);
  if (!(step > 0.0)) return;
  for (std::size_t i = 1; i < first.size(); ++i) {
    if (std::abs(first[i] - first[i - 1] - step) > options.time_jitter * step) return;
  }
  throw Error(fmt::format("{}:{}", origin, l.header_line),
              fmt::format("the file has no header and its first column rises at a constant step "
                          "of {:g}, like a time column: name the column to analyse, e.g. "
                          "--column 2 (or --column 1 to analyse the first column anyway)",
                          step));
}

// The file's bytes in one string of its size, read at once: a string stream grows by
// doubling and is copied out, and the fresh pages of every copy cost as much as parsing
// (docs/notes/performance.md, "Reading a record at once"). Anything but a regular file (a pipe; a
// directory, whose "size" can be anything) is read to its end in chunks.
std::string whole_file(const std::string& path, std::ifstream& in) {
  std::error_code ec;
  const std::uintmax_t size =
      std::filesystem::is_regular_file(path, ec) ? std::filesystem::file_size(path, ec) : 0;
  std::string text;
  if (!ec && size > 0) {
    text.resize(static_cast<std::size_t>(size));
    in.read(text.data(), static_cast<std::streamsize>(size));
    text.resize(static_cast<std::size_t>(in.gcount()));
  }
  in.clear();
  char chunk[1 << 16];
  while (in.read(chunk, sizeof chunk) || in.gcount() > 0) {
    text.append(chunk, static_cast<std::size_t>(in.gcount()));
  }
  return text;
}

}  // namespace

std::vector<std::string> split_csv_fields(const std::string& line) {
  // Every comma ends a field; a line without any character has no field at all.
  std::vector<std::string> fields;
  if (line.empty()) return fields;
  std::size_t start = 0;
  while (true) {
    const std::size_t comma = line.find(',', start);
    fields.push_back(line.substr(start, comma == std::string::npos ? comma : comma - start));
    if (comma == std::string::npos) return fields;
    start = comma + 1;
  }
}

TimeSeries parse_csv_series(const std::string& text, const std::string& origin,
                            const CsvSeriesOptions& options) {
  options.validate();
  refuse_binary(text, origin);
  // Spreadsheet exports often start with a UTF-8 byte-order mark; it is not part of a name.
  CsvLines lines(text);
  std::string line;
  const Layout layout = read_layout(lines, line, origin, options);
  Columns c;
  // At most one sample per line: no regrowth (and fresh pages) while the columns fill.
  const auto lines_at_most =
      static_cast<std::size_t>(std::count(text.begin(), text.end(), '\n')) + 1;
  c.values.reserve(lines_at_most);
  if (layout.time >= 0) c.times.reserve(lines_at_most);
  if (!layout.has_header) read_row(line, layout.header_line, layout, origin, c);
  while (lines.next(line)) read_row(line, lines.number(), layout, origin, c);
  if (c.values.size() < 2) {
    throw Error(origin, fmt::format("{} sample(s): at least 2 are needed", c.values.size()));
  }
  if (!layout.has_header) refuse_time_like_first_column(c.values, layout, origin, options);
  const bool timed = layout.time >= 0;
  const double rate_Hz = timed ? rate_from_times(c.times, origin, options.time_jitter) : *options.rate_Hz;
  if (timed && options.rate_Hz && !same_rate(rate_Hz, *options.rate_Hz, options.time_jitter)) {
    const auto t = static_cast<std::size_t>(layout.time);
    throw Error(CsvSeriesOptions::kRateField,
                fmt::format("{} Hz disagrees with the time column \"{}\" of {}, sampled at {:.6g} "
                            "Hz: {}",
                            *options.rate_Hz, layout.names[t], origin, rate_Hz,
                            clock_hint(layout, rate_Hz, *options.rate_Hz)));
  }
  TimeSeries series(rate_Hz, timed ? c.times.front() : 0.0);
  const std::string& header = layout.names[static_cast<std::size_t>(layout.value)];
  series.add_channel(layout.has_header ? header_name(header) : header, layout.value_unit.text,
                     std::move(c.values));
  return series;
}

void CsvSeriesOptions::validate() const {
  if (column.empty()) throw Error("csv.column", "expected a column's name or number");
  if (rate_Hz) validation::require_finite_gt(kRateField, *rate_Hz, 0, "Hz");
  validation::require_ge_lt(validation::field("csv.time_jitter"), time_jitter, 0, 1);
}

TimeSeries read_csv_series(const std::string& path, const CsvSeriesOptions& options) {
  if (path == "-") {
    std::ostringstream text;
    text << std::cin.rdbuf();
    return parse_csv_series(text.str(), "<stdin>", options);
  }
  std::ifstream in(path, std::ios::binary);
  if (!in) throw Error(path, "cannot open the file");
  return parse_csv_series(whole_file(path, in), path, options);
}

}  // namespace pneumachaos
