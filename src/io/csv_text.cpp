#include "pneumachaos/io/csv_text.hpp"

#include <fmt/format.h>

#include <algorithm>
#include <cctype>
#include <charconv>
#include <cmath>
#include <string_view>

#include "pneumachaos/core/error.hpp"

namespace pneumachaos {

std::string trim_field(std::string s) {
  const auto not_space = [](unsigned char c) { return !std::isspace(c); };
  s.erase(s.begin(), std::find_if(s.begin(), s.end(), not_space));
  s.erase(std::find_if(s.rbegin(), s.rend(), not_space).base(), s.end());
  if (s.size() >= 2 && s.front() == '"' && s.back() == '"') s = s.substr(1, s.size() - 2);
  return s;
}

std::string header_name(const std::string& header) {
  const auto bracket = header.find('[');
  return trim_field(bracket == std::string::npos ? header : header.substr(0, bracket));
}

std::string header_unit(const std::string& header) {
  const auto open = header.find('[');
  const auto close = header.rfind(']');
  if (open == std::string::npos || close == std::string::npos || close < open) return "";
  return trim_field(header.substr(open + 1, close - open - 1));
}

int find_column(const std::vector<std::string>& names, const std::vector<std::string>& wanted) {
  for (const auto& w : wanted) {
    if (w.empty()) continue;
    for (std::size_t i = 0; i < names.size(); ++i)
      if (names[i] == w || header_name(names[i]) == w) return static_cast<int>(i);
  }
  return -1;
}

std::string separator_hint(const std::vector<std::string>& names) {
  const bool semicolons = std::any_of(names.begin(), names.end(), [](const std::string& n) {
    return n.find(';') != std::string::npos;
  });
  if (!semicolons) return "";
  return "; the fields look separated by ';' (a spreadsheet export with decimal commas?): "
         "columns must be separated by commas or blanks, with decimal points; convert it, e.g. "
         "with `tr ',;' '.,' < in.csv > out.csv`";
}

void refuse_binary(std::string_view text, const std::string& origin) {
  if (text.substr(0, 4096).find('\0') == std::string_view::npos) return;
  throw Error(origin,
              "is not a text file (binary bytes: an image, an archive or a spreadsheet's "
              "own format?): expected a record as comma- or blank-separated text, e.g. "
              "a CSV export");
}

double parse_cell(const std::string& f, const std::string& where) {
  double v = 0.0;
  const char* end = f.data() + f.size();
  const auto [ptr, ec] = std::from_chars(f.data(), end, v);
  if (ec == std::errc::result_out_of_range && ptr == end)
    throw Error(where, fmt::format("{} is outside the range of a double (about 1.8e308)", f));
  if (ec != std::errc() || ptr != end || f.empty())
    throw Error(where, fmt::format("expected a number, got \"{}\"", f));
  if (!std::isfinite(v)) throw Error(where, fmt::format("expected a finite number, got {}", f));
  return v;
}

namespace {
constexpr std::string_view kBom = "\xEF\xBB\xBF";
}

CsvLines::CsvLines(std::string_view text)
    : text_(text.starts_with(kBom) ? text.substr(kBom.size()) : text) {}

// Lines as std::getline would cut them (a last line without '\n' counts, a final '\n' opens
// none), found by memchr rather than through a string stream, and judged blank or comment
// without copying: this runs once per sample of an analysed record.
bool CsvLines::next(std::string& line) {
  while (pos_ < text_.size()) {
    const std::size_t end = std::min(text_.find('\n', pos_), text_.size());
    line.assign(text_.substr(pos_, end - pos_));
    pos_ = end + 1;
    ++number_;
    if (!line.empty() && line.back() == '\r') line.pop_back();
    const auto first = std::find_if(line.begin(), line.end(), [](unsigned char c) {
      return !std::isspace(c);
    });
    if (first == line.end()) continue;
    if (*first != '"') {
      if (*first != '#') return true;
      continue;
    }
    // A quoted start: trim_field also strips the quotes, so let it decide.
    const std::string t = trim_field(line);
    if (!t.empty() && t.front() != '#') return true;
  }
  return false;
}

}  // namespace pneumachaos
