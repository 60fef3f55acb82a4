#pragma once
// The pieces every CSV record reader shares (the analysed series and the measured rig
// records): numbered lines without blanks and comments, trimmed fields, "name[unit]" headers,
// column lookup and strict number cells whose errors name file:line:column.

#include <string>
#include <string_view>
#include <vector>

namespace pneumachaos {

/// Surrounding blanks and one pair of double quotes removed.
std::string trim_field(std::string s);
/// "v [mm/s]" -> "v"; a header without brackets is its own name.
std::string header_name(const std::string& header);
/// "P1[MPa gauge]" -> "MPa gauge"; "" without brackets.
std::string header_unit(const std::string& header);

/// Index of the first name of `wanted` (in its order; empty names skipped) that a column
/// carries, either whole or as header_name(); -1 when none does.
int find_column(const std::vector<std::string>& names, const std::vector<std::string>& wanted);

/// When a header's fields look separated by ';' (a spreadsheet export in a locale with decimal
/// commas), what to do about it, starting with "; "; else "". Appended to a "no column" error.
std::string separator_hint(const std::vector<std::string>& names);

/// Throws Error(origin) when `text` is not text: a NUL byte among its first 4096 bytes (an
/// image, an archive, a spreadsheet's binary format), instead of echoing its bytes.
void refuse_binary(std::string_view text, const std::string& origin);

/// A finite double, or Error(where) saying what the cell holds instead.
double parse_cell(const std::string& field, const std::string& where);

/// The lines of a record, numbered as in the file; a UTF-8 byte-order mark at the start
/// (spreadsheet exports), blank lines, '#' comments and '\r' line ends skipped. It reads
/// `text` in place: the text must outlive it.
class CsvLines {
 public:
  explicit CsvLines(std::string_view text);
  bool next(std::string& line);
  [[nodiscard]] std::size_t number() const { return number_; }

 private:
  std::string_view text_;
  std::size_t pos_ = 0;  ///< start of the next line in text_
  std::size_t number_ = 0;
};

}  // namespace pneumachaos
