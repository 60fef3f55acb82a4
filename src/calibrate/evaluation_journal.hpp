#pragma once
// calibrate's journal (private to the module): one line per finished evaluation, appended and
// forced to disk before the next starts, so a calibration killed at any moment resumes by
// replaying what it holds (docs/guide/calibrate.md, "Resuming").

#include <cstdio>
#include <string>
#include <vector>

namespace pneumachaos::detail {

struct JournalEntry {
  std::vector<double> u;      ///< the point on the unit box
  double objective = 0.0;
  std::vector<double> terms;  ///< the objective's terms (claim margins, map errors)
};

class EvaluationJournal {
 public:
  /// Reads `path` if it exists: its header must carry `fingerprint`; a torn last line (a
  /// process killed mid-write) is cut off when `writer`. Error names file:line otherwise.
  EvaluationJournal(std::string path, std::string fingerprint, std::size_t dimension,
                    std::size_t terms, bool writer);
  ~EvaluationJournal();
  EvaluationJournal(const EvaluationJournal&) = delete;
  EvaluationJournal& operator=(const EvaluationJournal&) = delete;

  [[nodiscard]] const std::vector<JournalEntry>& entries() const { return entries_; }
  /// Appends an entry (only the writer touches the file) and forces it to disk.
  void append(const JournalEntry& e);

 private:
  void read_existing();
  std::string path_, header_;
  std::size_t dimension_, terms_;
  bool writer_;
  std::vector<JournalEntry> entries_;
  std::FILE* file_ = nullptr;
};

/// A double as text that reads back to the same bits ("nan" for NaN).
std::string exact_text(double x);

}  // namespace pneumachaos::detail
