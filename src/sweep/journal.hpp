#pragma once
// The append-only journal of finished runs (private to the sweep module).

#include <cstdio>
#include <string>
#include <vector>

#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos::detail {

class Journal {
 public:
  /// Opens (creating if needed) path for appending. An existing journal must carry the same
  /// fingerprint; a torn last line (the process killed mid-write) is cut off.
  Journal(const std::string& path, const std::string& fingerprint, bool resume);
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
