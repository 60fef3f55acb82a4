#include "evaluation_journal.hpp"

#include <fmt/format.h>
#include <unistd.h>

#include <cerrno>
#include <cmath>
#include <cstdlib>
#include <cstring>
#include <filesystem>
#include <fstream>
#include <sstream>

#include "pneumachaos/core/error.hpp"
#include "pneumachaos/io/csv_fields.hpp"

namespace pneumachaos::detail {
namespace {

double parse_exact(const std::string& s, const std::string& where) {
  if (s == "nan") return std::nan("");
  char* end = nullptr;
  errno = 0;
  const double x = std::strtod(s.c_str(), &end);
  if (s.empty() || end != s.c_str() + s.size() || errno == ERANGE)
    throw Error(where, fmt::format("damaged calibration journal: \"{}\" is not a number", s));
  return x;
}

}  // namespace

std::string exact_text(double x) { return std::isnan(x) ? "nan" : fmt::format("{}", x); }

EvaluationJournal::EvaluationJournal(std::string path, std::string fingerprint,
                                     std::size_t dimension, std::size_t terms, bool writer)
    : path_(std::move(path)),
      header_(fmt::format("# pneumachaos calibration journal 1, fingerprint {}, {} free, {} terms",
                          fingerprint, dimension, terms)),
      dimension_(dimension),
      terms_(terms),
      writer_(writer) {
  read_existing();
  if (!writer_) return;
  std::error_code ec;
  const bool fresh = !std::filesystem::exists(path_, ec) || std::filesystem::file_size(path_, ec) == 0;
  file_ = std::fopen(path_.c_str(), "ab");
  if (file_ == nullptr)
    throw RunError(path_, std::string("cannot open the calibration journal: ") + std::strerror(errno));
  if (fresh) {
    const std::string h = header_ + "\n";
    if (std::fputs(h.c_str(), file_) < 0 || std::fflush(file_) != 0 || ::fsync(fileno(file_)) != 0)
      throw RunError(path_, std::string("cannot write the calibration journal: ") + std::strerror(errno));
  }
}

EvaluationJournal::~EvaluationJournal() {
  if (file_ != nullptr) std::fclose(file_);
}

void EvaluationJournal::read_existing() {
  std::ifstream in(path_, std::ios::binary);
  if (!in) return;
  std::stringstream ss;
  ss << in.rdbuf();
  const std::string text = ss.str();
  std::size_t pos = 0, line_no = 0, complete = 0;
  while (pos < text.size()) {
    const std::size_t nl = text.find('\n', pos);
    if (nl == std::string::npos) break;  // a torn last line: the evaluation is run again
    const std::string line = text.substr(pos, nl - pos);
    const std::string where = fmt::format("{}:{}", path_, ++line_no);
    if (line_no == 1) {
      if (line != header_)
        throw Error(where, "this directory holds another calibration's journal (its spec, seed or "
                           "measured map differ); use a new --out directory");
    } else {
      const std::vector<std::string> f = split_csv_fields(line);
      if (f.size() != 2 + dimension_ + terms_ || f[0] != std::to_string(entries_.size()))
        throw Error(where, "damaged calibration journal line");
      JournalEntry e;
      for (std::size_t i = 0; i < dimension_; ++i) e.u.push_back(parse_exact(f[1 + i], where));
      e.objective = parse_exact(f[1 + dimension_], where);
      for (std::size_t i = 0; i < terms_; ++i) e.terms.push_back(parse_exact(f[2 + dimension_ + i], where));
      entries_.push_back(std::move(e));
    }
    pos = nl + 1;
    complete = pos;
  }
  if (writer_ && complete < text.size()) std::filesystem::resize_file(path_, complete);
}

void EvaluationJournal::append(const JournalEntry& e) {
  if (writer_) {
    std::string line = std::to_string(entries_.size());
    for (double x : e.u) line += "," + exact_text(x);
    line += "," + exact_text(e.objective);
    for (double x : e.terms) line += "," + exact_text(x);
    line += "\n";
    if (std::fputs(line.c_str(), file_) < 0 || std::fflush(file_) != 0 || ::fsync(fileno(file_)) != 0)
      throw RunError(path_, std::string("cannot write the calibration journal: ") + std::strerror(errno));
  }
  entries_.push_back(e);
}

}  // namespace pneumachaos::detail
