#pragma once
// Output files that are either complete or absent: written to a temporary beside the target
// and renamed into place on commit(), so an interrupted run never leaves a half-written file
// that looks complete.

#include <fstream>
#include <memory>
#include <string>
#include <vector>

namespace pneumachaos {

/// One policy for every output path, checked before any work: why `path` cannot
/// be written as an output file, or "" when it can. It must not be a directory, and the
/// nearest of its ancestors that exists must be a writable directory: missing directories
/// are created when the file is written. No side effects.
std::string output_file_problem(const std::string& path);
/// The same for an output directory: an existing path must be a directory.
std::string output_directory_problem(const std::string& path);

class AtomicFile {
 public:
  /// Opens "<path>.part", creating missing directories; throws Error if it cannot be created
  /// (a directory at `path` included).
  explicit AtomicFile(std::string path);
  AtomicFile(const AtomicFile&) = delete;
  AtomicFile& operator=(const AtomicFile&) = delete;
  /// Removes the temporary if commit() was not reached.
  ~AtomicFile();

  std::ofstream& stream() { return out_; }
  /// Flushes, checks for write errors and renames into place; throws RunError on failure.
  void commit() {
    finish();
    publish();
  }
  /// The two halves of commit(), for a set of files published together: flush, check and
  /// close the temporary; then rename it into place.
  void finish();
  void publish();
  [[nodiscard]] const std::string& path() const { return path_; }

 private:
  std::string path_;
  std::string temp_;
  std::ofstream out_;
  bool committed_ = false;
};

/// The output files of one command, published together: nothing appears until every file
/// has been written completely, so a failure never leaves some outputs looking complete.
class OutputSet {
 public:
  /// Opens `path` for writing as AtomicFile does.
  std::ofstream& add(const std::string& path);
  /// Checks every file, then moves them all into place; if a move fails, the files already
  /// moved are removed again and RunError is thrown.
  void commit();

 private:
  std::vector<std::unique_ptr<AtomicFile>> files_;
};

}  // namespace pneumachaos
