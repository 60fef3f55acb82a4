#pragma once
// The append-only journal of finished runs (private to the sweep module).

#include <cstdio>
#include <string>
#include <vector>

#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos::detail {

class Journal {
 public:
  /// Opens (creating if needed) this process's journal `own_name` in dir for appending, after
  /// reading every journal*.csv there (other ranks' too). Each must carry the same
  /// fingerprint; a torn last line (a process killed mid-write) is ignored, and cut off in
  /// the own journal.
  Journal(const std::string& dir, const std::string& own_name, const std::string& fingerprint,
          bool resume);

  /// Every record in the directory's journals (all ranks), read now.
  static std::vector<RunRecord> read_all(const std::string& dir, const std::string& fingerprint);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  /// Records found when the journal was opened.
  [[nodiscard]] const std::vector<RunRecord>& existing() const { return existing_; }
  /// Appends one record and forces it to disk before returning.
  void append(const RunRecord& record);

 private:
  std::string path_;
  std::FILE* file_ = nullptr;
  std::vector<RunRecord> existing_;
};

}  // namespace pneumachaos::detail
