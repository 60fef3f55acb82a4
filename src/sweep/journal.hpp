#pragma once
// The append-only journal of finished runs (private to the sweep module).

#include <chrono>
#include <cstdio>
#include <map>
#include <string>
#include <utility>
#include <vector>

#include "pneumachaos/sweep/sweep.hpp"

namespace pneumachaos::detail {

/// The first line of a journal of the sweep with this fingerprint.
std::string journal_header(const std::string& fingerprint);

/// Reads journal files of one sweep, refusing a foreign or damaged header and a run recorded
/// twice (two writers), and naming file:line in every error.
class JournalReader {
 public:
  explicit JournalReader(std::string fingerprint) : fingerprint_(std::move(fingerprint)) {}
  /// Adds the complete lines of `path`; `cut` also truncates a torn last line in the file.
  void read(const std::string& path, bool cut);
  [[nodiscard]] std::vector<RunRecord> records() && { return std::move(records_); }

 private:
  std::string fingerprint_;
  std::vector<RunRecord> records_;
  std::map<std::pair<std::size_t, std::size_t>, std::string> origin_;  // (point, repeat) -> file:line
};

class Journal {
 public:
  /// Reads every journal*.csv in dir (other ranks' too) for this process's journal
  /// `own_name`. Each must carry the same fingerprint; a torn last line (a process killed
  /// mid-write) is ignored, and cut off in the own journal. Nothing is created until open():
  /// under MPI every rank must have read the directory before any rank creates its file.
  Journal(const std::string& dir, const std::string& own_name, const std::string& fingerprint,
          bool resume);

  /// Every record in the directory's journals (all ranks), read now.
  static std::vector<RunRecord> read_all(const std::string& dir, const std::string& fingerprint);
  ~Journal();
  Journal(const Journal&) = delete;
  Journal& operator=(const Journal&) = delete;

  /// Records found when the journal was opened.
  [[nodiscard]] const std::vector<RunRecord>& existing() const { return existing_; }
  /// Opens (creating if needed) the own journal for appending.
  void open();
  /// Appends one record: written through to the operating system before returning, forced
  /// to disk at least once a second (kSyncInterval) and by sync().
  void append(const RunRecord& record);
  /// Forces everything appended so far to disk.
  void sync();

 private:
  void write_line(const std::string& line);
  std::string path_;
  std::string fingerprint_;
  static constexpr std::chrono::seconds kSyncInterval{1};
  std::FILE* file_ = nullptr;
  std::chrono::steady_clock::time_point synced_{};
  std::vector<RunRecord> existing_;
};

}  // namespace pneumachaos::detail
